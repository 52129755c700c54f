// Small helpers shared by the commands.
#pragma once

#include <Eigen/Core>
#include <chrono>
#include <string>

#include "cli/arg_parser.h"
#include "cli/command_log.h"
#include "deform/deformer.h"
#include "engine/engine.h"
#include "io/mesh_formats.h"
#include "io/obj_io.h"

namespace somicage {

using CliClock = std::chrono::steady_clock;

double secondsSince(CliClock::time_point start);

// "0.0123 s", "1.23 s", "12.3 s".
std::string formatSeconds(double seconds);

// %g with the given significant digits.
std::string formatNumber(double value, int digits = 6);

// --method (default somigliana); an unknown name throws InputError naming --method.
Method methodOption(const ArgParser& args);

// before, then the options of every command that deforms (--method, and one per row of parameter_schema.h with
// its aliases: read them with methodOption and deformParamsOptions), then after.
std::vector<OptionSpec> withDeformParams(std::vector<OptionSpec> before, const std::vector<OptionSpec>& after);

// "methods (--method):" and a line per method of the registry: "  NAME  DISPLAY NAME: DESCRIPTION", for the help
// texts of the commands that deform.
std::string methodsHelp();

// The parameter options (parameter_schema.h, aliases first) as DeformParams, validated for the method
// (MethodDescriptor::validateParams; InputError names the option).
DeformParams deformParamsOptions(const ArgParser& args, Method method);

// Notes (log.note) the options given to a method that ignores them (MethodDescriptor::parameters, ::options).
// volumeMeshUsed: the command builds a volume mesh for any method (analyze --seams), so its options are read.
void noteIgnoredParameters(const CommandLog& log, const ArgParser& args, Method method, bool volumeMeshUsed = false);

// Sets the OpenMP thread count for everything that follows; 0 keeps the OpenMP default.
void setThreadCount(int threads);

// The --threads N option of the commands that compute (default 0: all cores).
OptionSpec threadsOptionSpec();
// --threads (0 to 4096), set for everything that follows (setThreadCount).
int threadsOption(const ArgParser& args);
// --weld: every command reads its meshes and cages through loadAnyMesh (mesh_formats.h), OBJ or any other format;
// STL and FBX have no shared vertices, which --weld joins back.
OptionSpec weldOptionSpec();
ReadOptions readOptions(const ArgParser& args);
// The options of a precompute on that many threads (0: all cores), its integration's included.
PrecomputeOptions precomputeOptions(int threads);

// Every method's own precompute options (MethodDescriptor::options) as --KEY VALUE, with "; NAME only": part of
// withDeformParams, for the commands that precompute without it (animate, bench).
std::vector<OptionSpec> methodOptionSpecs();
// The method options given (--KEY VALUE) in options.methodOptions, the CGAL tetrahedralization as the volume
// mesher, and, for a method that needs a volume mesh, the mesh made now (engine.h: prepareVolumeMesh), its
// notices sent to `notices`.
void applyMethodOptions(const ArgParser& args, Method method, const Cage& cage, PrecomputeOptions& options,
                        const NoticeSink& notices);

// The memory check of the commands' precomputes (engine.h: precompute): the refusal's hint offers no float
// storage (no command has that option), and when the precompute takes 1 GB or more, or 10% of the free memory or
// more, "COMMAND: estimated memory: X of coordinates, Y in all (Z free)" is a status line (log.status) before it
// starts. withGradients: the deformation gradient (jacobian.h) will be built as well (estimateGradientBytes).
MemoryCheck commandMemoryCheck(const CommandLog& log, bool withGradients = false);

// Whether the deformation gradients (normals carried by J, normal_transform.h) fit in the free memory next to the
// coordinates; when they do not, notes that the normals will be recomputed. The precompute's own check
// (commandMemoryCheck) still refuses a run whose coordinates do not fit.
bool gradientsFitForNormals(const CommandLog& log, Method method, const Cage& cage, std::size_t points,
                            const PrecomputeOptions& options, const std::string& meshPath);

}  // namespace somicage
