// somicage deform: the batch form of what the editor does on every frame, through the same engine facade
// (engine.h: loadUsableCage, meshPointsFor, precompute, deformPoints), then saveObj.
#include <cmath>
#include <iostream>
#include <sstream>

#include "cli/arg_parser.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/progress_reporter.h"
#include "deformer.h"
#include "errors.h"
#include "obj_io.h"

namespace somicage {

namespace {

const char* const kCommand = "somicage deform";

// "somigliana only": the methods that read --variant, --blend, --nu, --gamma and --no-traction-fix.
std::string paramMethods() {
  std::string names;
  for (Method m : allMethods())
    if (m->takesDeformParams) names += (names.empty() ? "" : ", ") + std::string(m->name);
  return names + " only";
}

ArgParser deformOptions() {
  return ArgParser(
      kCommand,
      {
          {"--cage", "REST.obj", "the rest cage: a closed triangle/quad mesh, or a 2D polygon (z = 0)", true},
          {"--posed", "POSED.obj", "the posed cage: the rest cage's vertices, moved, in the same order", true},
          {"--mesh", "IN.obj", "the mesh or point set to deform (2D cage: its x, y; z is kept)", true},
          {"--out", "OUT.obj", "where to write the result: IN's vertices moved, IN's faces", true},
          {"--method", "NAME", methodNameList() + " (default " + methodName(Method()) + ")"},
          {"--variant", "NAME", "global (default, blend 0) or local (blend 1); " + paramMethods()},
          {"--blend", "T", "blend between the global (0) and local (1) variant; overrides --variant"},
          {"--nu", "V", "Poisson ratio in (-1, 0.5), or inf / -inf (default 0); " + paramMethods()},
          {"--gamma", "G", "bulging scale >= 0 (default 0); " + paramMethods()},
          {"--no-traction-fix", "", "skip the traction correction of Eq. 15; " + paramMethods()},
          {"--threads", "N", "OpenMP threads (default: all cores)"},
      });
}

// validateDeformParams names the parameter ("nu"); on the command line it is the option ("--nu").
void validateOptions(const DeformParams& params) {
  try {
    validateDeformParams(params);
  } catch (const InputError& e) {
    const std::string source = e.source().rfind("--", 0) == 0 ? e.source() : "--" + e.source();
    throw InputError(source, -1, e.problem(), e.hint());
  }
}

Method methodOption(const ArgParser& args) { return parseMethod(args.text("--method", methodName(Method()))); }

}  // namespace

std::string deformUsage() {
  std::ostringstream out;
  out << "usage: " << kCommand << " --cage REST.obj --posed POSED.obj --mesh IN.obj --out OUT.obj [OPTIONS]\n\n"
      << "Deforms the vertices of IN with the cage moved from REST to POSED and writes OUT with IN's vertex order\n"
      << "and faces (coordinates with 17 significant digits). The cage is 2D when every z is 0.\n\n"
      << "options:\n"
      << deformOptions().optionHelp();
  return out.str();
}

int runDeformCommand(const std::vector<std::string>& rawArgs) {
  ArgParser args = deformOptions();
  args.parse(rawArgs);
  if (args.helpRequested()) {
    std::cout << deformUsage();
    return kExitOk;
  }

  // Options first, so that a typo fails before any file is read.
  const Method method = methodOption(args);
  DeformParams params;
  params.blend = args.choice("--variant", {"global", "local"}, "global") == "local" ? 1.0 : 0.0;
  params.blend = args.number("--blend", params.blend);
  params.nu = args.numberOrInfinity("--nu", params.nu);
  params.gamma = args.number("--gamma", params.gamma);
  params.tractionCorrection = !args.has("--no-traction-fix");
  validateOptions(params);
  const int threads = args.integer("--threads", 0, 0, 4096);
  setThreadCount(threads);
  const std::string cagePath = args.text("--cage"), posedPath = args.text("--posed");
  const std::string meshPath = args.text("--mesh"), outPath = args.text("--out");

  // Inputs.
  const Cage cage = loadUsableCage(cagePath, printNotice);
  const Eigen::MatrixXd posed = loadPosedVertices(posedPath, cage);
  const PolygonMesh mesh = loadMesh(meshPath);
  const Eigen::MatrixXd points = meshPointsFor(cage, mesh.vertices, meshPath, cagePath, printNotice);
  if (!method->takesDeformParams && (args.has("--variant") || args.has("--blend") || args.has("--nu") ||
                                     args.has("--gamma") || args.has("--no-traction-fix"))) {
    std::cerr << kCommand << ": note: --variant, --blend, --nu, --gamma and --no-traction-fix apply to "
              << paramMethods() << "; " << methodName(method) << " ignores them\n";
  }

  // Precompute once, deform once.
  PrecomputeOptions options;
  options.threads = threads;
  options.integration.threads = threads;
  requirePrecomputeMemory(kCommand, method, cage, static_cast<std::size_t>(points.rows()), options, meshPath);
  const CliClock::time_point precomputeStart = CliClock::now();
  std::unique_ptr<CageDeformer> deformer;
  {
    ProgressReporter progress("precomputing " + methodName(method) + " coordinates");
    deformer = precompute(method, cage, points, options, meshPath, progress.callback());
  }
  const double precomputeSeconds = secondsSince(precomputeStart);
  const int exterior = deformer->diagnostics().exteriorCount();
  if (exterior > 0) {
    std::cerr << kCommand << ": warning: " << exterior << " of " << points.rows() << " points of " << meshPath
              << " lie outside the cage (or on it); they follow the cage's best-fit similarity, blended smoothly "
              << "into the deformation inside (docs/engine.md, \"Points outside the cage\")\n";
  }
  const CliClock::time_point deformStart = CliClock::now();
  const Eigen::MatrixXd deformed = deformPoints(*deformer, cage, posed, params, posedPath, meshPath);
  const double deformSeconds = secondsSince(deformStart);

  Eigen::MatrixXd result = mesh.vertices;  // a 2D cage moves x, y and keeps z
  result.leftCols(cage.dim()) = deformed;
  saveObj(outPath, result, mesh);

  std::ostringstream summary;
  summary << kCommand << ": " << cage.dim() << "D " << methodName(method);
  if (method->takesDeformParams) {
    summary << " (blend " << formatNumber(params.blend) << ", nu " << formatNumber(params.nu) << ", gamma "
            << formatNumber(params.gamma) << (params.tractionCorrection ? "" : ", no traction fix") << ")";
  }
  summary << ": cage " << cage.numVertices() << " vertices / " << cage.numFaces()
          << (cage.dim() == 3 ? " faces" : " edges") << ", " << points.rows() << " points; precompute "
          << formatSeconds(precomputeSeconds) << ", deform " << formatSeconds(deformSeconds) << "; wrote " << outPath
          << "\n";
  std::cerr << summary.str();
  return kExitOk;
}

}  // namespace somicage
