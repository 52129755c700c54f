// somicage check: is the cage valid as given (cage_validation.h), what would repairCage fix (cage_repair.h), and how
// well do the Somigliana coordinates of the cage the other commands use reproduce the identity (partition of
// unity, Eq. 9) at the points of a mesh?
#include <algorithm>
#include <iostream>
#include <sstream>
#include <type_traits>
#include <variant>

#include "base/errors.h"
#include "cage/cage_check.h"
#include "cli/arg_parser.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/json_writer.h"
#include "cli/progress_reporter.h"
#include "cli/tightness_report.h"
#include "coordinates/somigliana_coordinates.h"
#include "deform/deformer.h"
#include "generation/cage_enclosure.h"
#include "io/obj_io.h"
#include "tetrahedralization/cage_tetrahedralization.h"

namespace somicage {

namespace {

const char* const kCommand = "somicage check";

ArgParser checkOptions() {
  return ArgParser(kCommand, withScriptOptions({
                                 {"--cage", "C.obj", "the cage to check (3D mesh, or 2D polygon with z = 0)", true},
                                 {"--mesh", "M.obj", "points for the partition-of-unity check (any readable format)"},
                                 weldOptionSpec(),
                                 {"--json", "", "print one JSON object instead of the readable report"},
                                 threadsOptionSpec(),
                             }));
}

// The partition-of-unity residual max_ij |sum_i T_i(x) - I|_ij over the points inside the cage.
struct UnityCheck {
  bool computed = false;
  int points = 0, inside = 0, outside = 0, singular = 0;
  double max = 0.0, median = 0.0, precomputeSeconds = 0.0;
};

UnityCheck checkPartitionOfUnity(const Cage& cage, const Eigen::MatrixXd& points, int threads, Eigen::VectorXd& winding,
                                 const CommandLog& log) {
  UnityCheck check;
  check.points = static_cast<int>(points.rows());
  IntegrationOptions options;
  options.threads = threads;
  const CliClock::time_point start = CliClock::now();
  SomiglianaCoordinates coords;
  {
    ProgressReporter progress = log.progress("computing somigliana coordinates");
    coords = computeSomiglianaCoordinates(cage, points, options, progress.callback());
  }
  check.precomputeSeconds = secondsSince(start);
  const Eigen::VectorXd residual = partitionOfUnityResidual(coords);
  winding = coords.winding;
  std::vector<double> inside;
  for (int p = 0; p < check.points; ++p) {
    if (!(coords.winding(p) >= 0.5)) {
      ++check.outside;  // Eq. 9 holds inside only
    } else if (!std::isfinite(residual(p))) {
      ++check.singular;  // on the cage
    } else {
      inside.push_back(residual(p));
    }
  }
  check.inside = static_cast<int>(inside.size());
  check.computed = true;
  if (!inside.empty()) {
    check.max = *std::max_element(inside.begin(), inside.end());
    const size_t middle = inside.size() / 2;
    std::nth_element(inside.begin(), inside.begin() + middle, inside.end());
    check.median = inside[middle];
    if (inside.size() % 2 == 0) {  // the mean of the two middle values
      check.median = 0.5 * (check.median + *std::max_element(inside.begin(), inside.begin() + middle));
    }
  }
  return check;
}

// Each method's identity reproduction at rest: max |x~ - x| / cage diameter over the inside points (all points for
// a method that reproduces outside the cage too: mean value coordinates, which are defined everywhere). Somigliana and
// Green reproduce the identity up to their integration error; mean value coordinates exactly.
std::vector<std::pair<std::string, double>> checkReproduction(const Cage& cage, const Eigen::MatrixXd& points,
                                                              const Eigen::VectorXd& winding, int threads,
                                                              const CommandLog& log) {
  std::vector<std::pair<std::string, double>> errors;
  const double diameter = cageDiameter(cage.vertices);
  PrecomputeOptions options = precomputeOptions(threads);
  options.volumeMesher = tetrahedralizeCageWithOptions;  // Phong's default volume mesh
  for (Method method : allMethods()) {
    ProgressReporter progress = log.progress("reproduction with " + methodName(method));
    std::unique_ptr<CageDeformer> deformer;
    try {
      deformer = makeDeformer(method, cage, points, options, progress.callback());
    } catch (const InputError& e) {  // no volume mesh for this cage: the other methods' checks stand
      progress.finish();
      log.note("no " + methodName(method) + " reproduction: " + e.what());
      continue;
    }
    progress.finish();
    const Eigen::VectorXd moved = (deformer->deform(cage.vertices, {}) - points).rowwise().norm();
    double worst = 0;
    for (Eigen::Index p = 0; p < points.rows(); ++p)
      if (method->reproducesOutside || winding(p) >= 0.5) worst = std::max(worst, moved(p) / diameter);
    errors.emplace_back(methodName(method), worst);
  }
  return errors;
}

// How tightly the cage fits the mesh (3D, a mesh with faces).
struct Fit {
  bool computed = false;
  CageTightness tightness;
};

void writeJson(const std::string& cagePath, const std::string& meshPath, const CageCheck& check,
               const UnityCheck& unity, const std::vector<std::pair<std::string, double>>& reproduction,
               const Fit& fit) {
  JsonObjectWriter json(std::cout);
  json.field("cage", cagePath);
  if (meshPath.empty()) {
    json.null("mesh");
  } else {
    json.field("mesh", meshPath);
  }
  for (const auto& [key, value] : cageCheckFields(check)) {  // the keys Python's somicage.check() returns too
    std::visit(
        [&json, &name = key](const auto& v) {
          if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::nullptr_t>) {
            json.null(name);
          } else {
            json.field(name, v);
          }
        },
        value);
  }
  json.field("mesh_vertices", unity.points);
  json.field("pou_computed", unity.computed);
  json.field("inside_points", unity.inside);
  json.field("outside_points", unity.outside);
  json.field("singular_points", unity.singular);
  if (unity.inside > 0) {
    json.field("pou_max", unity.max);
    json.field("pou_median", unity.median);
  } else {
    json.null("pou_max");
    json.null("pou_median");
  }
  if (unity.computed) {
    json.field("precompute_s", unity.precomputeSeconds);
    json.field("reproduction_error", reproduction);
  } else {
    json.null("precompute_s");
    json.null("reproduction_error");
  }
  if (fit.computed) {
    writeTightness(json, fit.tightness);
  } else {
    json.null("hausdorff_diagonals");  // no mesh with faces, or a 2D cage
    json.null("volume_ratio");
    json.null("mesh_closed");
  }
  json.close();
}

void writeReport(const std::string& cagePath, const std::string& meshPath, const CageCheck& check,
                 const UnityCheck& unity, const std::vector<std::pair<std::string, double>>& reproduction,
                 const Fit& fit) {
  const CageReport& report = check.report;
  const std::vector<std::string>& problems = check.problems;
  const auto yesNo = [](bool value) { return value ? "yes" : "NO"; };
  std::ostringstream out;
  out << "cage   " << cagePath << ": " << report.dim << "D, " << report.numVertices << " vertices, " << report.numFaces
      << (report.dim == 3 ? " triangles" : " edges") << "\n";
  if (report.dim == 3) {
    out << "       closed " << yesNo(report.closed()) << ", edge-manifold " << yesNo(report.manifold())
        << ", consistently oriented " << yesNo(report.consistentlyOriented()) << ", outward " << yesNo(report.outward())
        << " (signed volume " << formatNumber(report.signedVolume) << ")\n";
  } else {
    out << "       closed " << yesNo(report.closed()) << ", simple " << yesNo(report.simple()) << ", counter-clockwise "
        << yesNo(report.outward()) << " (signed area " << formatNumber(report.signedVolume) << ")\n";
  }
  if (!meshPath.empty()) {
    out << "mesh   " << meshPath << ": " << unity.points << " vertices";
    if (unity.computed) {
      out << ", " << unity.inside << " inside the cage, " << unity.outside << " outside";
      if (unity.singular) out << ", " << unity.singular << " on the cage (singular)";
      out << "\n";
      if (unity.inside > 0) {
        out << "       partition of unity |sum_i T_i - I| over the inside points: max " << formatNumber(unity.max, 3)
            << ", median " << formatNumber(unity.median, 3) << " (coordinates in "
            << formatSeconds(unity.precomputeSeconds) << ")\n";
        out << "       identity at rest, max |x~ - x| / diameter:";
        for (const auto& [method, error] : reproduction) out << " " << method << " " << formatNumber(error, 3);
        out << "\n";
      }
    } else {
      out << "; partition of unity not computed: fix the cage first\n";
    }
    if (fit.computed) out << "fit    " << describeTightness(fit.tightness) << "\n";
  }
  if (!problems.empty()) {
    out << "problems (indices are 0-based):\n";
    for (const std::string& problem : problems) out << "  - " << problem << "\n";
  }
  if (!check.repair.fixes.empty()) {
    out << "repairs that deform, bench and the editor apply (the file is not changed):\n";
    for (const std::string& fix : check.repair.fixes) out << "  - " << fix << "\n";
  }
  if (!check.warnings.empty()) {
    out << "warnings:\n";
    for (const std::string& warning : check.warnings) out << "  - " << warning << "\n";
  }
  if (problems.empty()) {
    out << "result: the cage is valid\n";
  } else {
    out << "result: the cage has " << problems.size() << (problems.size() == 1 ? " problem" : " problems")
        << (check.usable() ? "; repaired as above, it is usable" : "") << "\n";
  }
  std::cout << out.str();
}

}  // namespace

std::string checkUsage() {
  std::ostringstream out;
  out << "usage: " << kCommand << " --cage C.obj [--mesh M.obj] [--json]\n\n"
      << "Checks that the cage is closed, edge-manifold, consistently oriented and outward (3D), or a simple\n"
      << "counter-clockwise polygon (2D), with no degenerate faces or duplicate vertices. With --mesh, computes the\n"
      << "Somigliana coordinates of the mesh vertices and the partition-of-unity residual max |sum_i T_i - I| over\n"
      << "those inside the cage (winding number >= 0.5). Lists what deform would repair (face orientation) and\n"
      << "warns about 3D self-intersections. Exit status: 0 the cage is valid as given, 1 it has problems; with\n"
      << "--strict, 3 when it is valid but intersects itself, or leaves points of the mesh outside (or on it).\n\n"
      << "options:\n"
      << checkOptions().optionHelp();
  return out.str();
}

int runCheckCommand(const std::vector<std::string>& rawArgs, CommandLog& log) {
  ArgParser args = checkOptions();
  args.parse(rawArgs);
  log.configure(args);
  if (args.helpRequested()) {
    std::cout << checkUsage();
    return kExitOk;
  }
  const int threads = threadsOption(args);
  const std::string cagePath = args.text("--cage"), meshPath = args.text("--mesh");

  const ReadOptions read = readOptions(args);
  const Cage cage = loadCage(cagePath, read);
  PolygonMesh mesh;
  if (!meshPath.empty()) mesh = loadAnyMesh(meshPath, read);
  const CageCheck check = checkCage(cage);  // the numbers below are of the cage deform uses: the repaired one
  const CageReport& report = check.report;

  UnityCheck unity;
  unity.points = mesh.numVertices();
  std::vector<std::pair<std::string, double>> reproduction;
  // Integrating needs valid indices and faces with a normal; other defects still give numbers worth seeing.
  if (!meshPath.empty() && report.indicesValid() && report.numFaces > 0 && report.degenerateFaces.empty()) {
    const Eigen::MatrixXd points = meshPointsFor(cage, mesh.vertices, meshPath, cagePath, log.sink());
    Eigen::VectorXd winding;
    unity = checkPartitionOfUnity(check.repair.cage, points, threads, winding, log);
    reproduction = checkReproduction(check.repair.cage, points, winding, threads, log);
  }
  Fit fit;
  if (unity.computed && cage.dim() == 3 && !mesh.faces.empty()) {
    fit.tightness = measureTightness(check.repair.cage, mesh.vertices, triangulatePolygons(mesh.vertices, mesh.faces));
    fit.computed = true;
  }
  if (args.has("--json")) {
    writeJson(cagePath, meshPath, check, unity, reproduction, fit);
  } else {
    writeReport(cagePath, meshPath, check, unity, reproduction, fit);
  }
  // The report lists them; --strict counts them as the other commands' warnings: the repairs they would make, the
  // self-intersections, and the points outside the cage (or on it).
  log.listed(static_cast<int>(check.repair.fixes.size() + check.warnings.size()) +
             (unity.outside + unity.singular > 0 ? 1 : 0));
  return report.valid() ? kExitOk : kExitFailure;
}

}  // namespace somicage
