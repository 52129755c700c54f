#include "cli/command_support.h"

#include <omp.h>

#include <cstdio>
#include <iostream>

#include "bem_system.h"
#include "cage_repair.h"
#include "cage_validation.h"
#include "errors.h"
#include "memory_estimate.h"
#include "mesh_placement.h"

namespace somicage {

constexpr std::size_t kBigPrecomputeBytes = 1000000000;  // 1 GB

double secondsSince(CliClock::time_point start) {
  return std::chrono::duration<double>(CliClock::now() - start).count();
}

std::string formatSeconds(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, seconds < 0.1 ? "%.4f s" : seconds < 10 ? "%.3f s" : "%.1f s", seconds);
  return text;
}

std::string formatNumber(double value, int digits) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

void setThreadCount(int threads) {
  if (threads > 0) omp_set_num_threads(threads);
}

Cage loadUsableCage(const std::string& path, const ReadOptions& read) {
  CageRepair repair = repairCage(cageFromMesh(loadAnyMesh(path, read), path));
  for (const std::string& fix : repair.fixes) std::cerr << "somicage: note: " << path << ": " << fix << "\n";
  const CageReport report = validateCage(repair.cage);
  for (const std::string& warning : describeCageWarnings(report))
    std::cerr << "somicage: warning: " << path << ": " << warning << "\n";
  requireValidCage(report, path);
  return std::move(repair.cage);
}

Method methodOption(const ArgParser& args) {
  try {
    return parseMethod(args.text("--method", "somigliana"));
  } catch (const InputError& e) {
    throw InputError("--method", -1, e.problem(), e.hint());
  }
}

std::vector<OptionSpec> withDeformParams(std::vector<OptionSpec> before, const std::vector<OptionSpec>& after) {
  before.insert(before.end(),
                {
                    {"--method", "NAME", "somigliana (default), green, mvc or bem (the linear-elastic reference)"},
                    {"--variant", "NAME", "global (default, blend 0) or local (blend 1); somigliana only"},
                    {"--blend", "T", "blend between the global (0) and local (1) variant; overrides --variant"},
                    {"--nu", "V", "Poisson ratio in (-1, 0.5), or inf / -inf (default 0); somigliana and bem"},
                    {"--gamma", "G", "bulging scale >= 0 (default 0); somigliana only"},
                    {"--no-traction-fix", "", "skip the traction correction of Eq. 15; somigliana only"},
                    {"--corotational", "", "remove the cage's best-fit rotation before the linear solve; bem only"},
                });
  before.insert(before.end(), after.begin(), after.end());
  return before;
}

DeformParams deformParamsOptions(const ArgParser& args, Method method) {
  DeformParams params;
  params.blend = args.choice("--variant", {"global", "local"}, "global") == "local" ? 1.0 : 0.0;
  params.blend = args.number("--blend", params.blend);
  params.nu = args.numberOrInfinity("--nu", params.nu);
  params.gamma = args.number("--gamma", params.gamma);
  params.tractionCorrection = !args.has("--no-traction-fix");
  params.corotational = args.has("--corotational");
  try {
    if (method == Method::Bem) validateBemPoissonRatio(params.nu);  // says why nu = 0.5 is refused
    validateDeformParams(params);
  } catch (const InputError& e) {  // validateDeformParams names the parameter ("nu"); here it is the option
    const std::string source = e.source().rfind("--", 0) == 0 ? e.source() : "--" + e.source();
    throw InputError(source, -1, e.problem(), e.hint());
  }
  return params;
}

void noteIgnoredParameters(const std::string& command, const ArgParser& args, Method method) {
  if (method != Method::Somigliana && (args.has("--variant") || args.has("--blend") || args.has("--gamma") ||
                                       args.has("--no-traction-fix") || (method != Method::Bem && args.has("--nu")))) {
    std::cerr << command << ": note: --variant, --blend, --nu, --gamma and --no-traction-fix apply to somigliana "
              << "only (--nu also to bem); " << methodName(method) << " ignores them\n";
  }
  if (method != Method::Bem && args.has("--corotational"))
    std::cerr << command << ": note: --corotational applies to bem only; " << methodName(method) << " ignores it\n";
}

void requirePrecomputeMemory(const std::string& command, Method method, const Cage& cage, std::size_t points,
                             const PrecomputeOptions& options, const std::string& meshPath, bool withGradients) {
  MemoryEstimate estimate = estimatePrecomputeMemory(method, cage.dim(), cage.numVertices(), cage.numFaces(), points,
                                                     options.floatStorage, options.threads);
  if (withGradients)
    estimate.gradients =
        estimateGradientBytes(method, cage.dim(), cage.numVertices(), cage.numFaces(), points, options.floatStorage);
  const std::optional<std::size_t> available = availableMemoryBytes();
  requireMemory(estimate, available, meshPath, memoryHint(false));  // neither command offers another storage
  // Small runs keep their one summary line; a big one says what it is about to take before it takes a while.
  const bool big = estimate.total() >= kBigPrecomputeBytes || (available && estimate.total() * 10 >= *available);
  if (big)
    std::cerr << command << ": estimated memory: " << formatBytes(estimate.coordinates) << " of coordinates, "
              << formatBytes(estimate.total()) << " in all ("
              << (available ? formatBytes(*available) + " free" : std::string("free memory unknown")) << ")\n";
}

bool requirePrecomputeMemoryForNormals(const std::string& command, Method method, const Cage& cage, std::size_t points,
                                       const PrecomputeOptions& options, const std::string& meshPath) {
  try {
    requirePrecomputeMemory(command, method, cage, points, options, meshPath, true);
    return true;
  } catch (const InputError&) {
    requirePrecomputeMemory(command, method, cage, points, options, meshPath, false);
    std::cerr << command << ": note: " << meshPath << ": the normals are recomputed from the deformed faces: "
              << "carrying them by the deformation's gradient would not fit in the free memory\n";
    return false;
  }
}

void warnAboutMeshPlacement(const Cage& cage, const Eigen::MatrixXd& points, const std::string& meshPath,
                            const std::string& cagePath) {
  if (const auto warning = describeMeshPlacement(measureMeshPlacement(cage, points), meshPath, cagePath))
    std::cerr << "somicage: warning: " << *warning << "\n";
}

Eigen::MatrixXd meshPoints(const PolygonMesh& mesh, int dim) { return mesh.vertices.leftCols(dim); }

}  // namespace somicage
