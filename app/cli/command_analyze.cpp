// somicage analyze: the numbers behind a pose (issue 12): volume change, det J, conformal distortion, fold-overs
// and face area ratios of a deformed mesh, from the exact deformation gradient (core/deform/jacobian.h); with a nu
// sweep, and the per-vertex J as CSV.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <sstream>

#include "analysis/deformation_analysis.h"
#include "base/errors.h"
#include "cli/arg_parser.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/json_writer.h"
#include "cli/progress_reporter.h"
#include "deform/deformer.h"
#include "io/obj_io.h"

namespace somicage {

namespace {

const char* const kCommand = "somicage analyze";

ArgParser analyzeOptions() {
  return ArgParser(
      kCommand,
      withDeformParams(
          {
              {"--cage", "REST.obj", "the rest cage: a closed triangle/quad mesh, or a 2D polygon (z = 0)", true},
              {"--posed", "POSED.obj", "the posed cage: the rest cage's vertices, moved, in the same order", true},
              {"--mesh", "MESH.obj", "the mesh whose deformation is measured (2D cage: its x, y)", true},
          },
          withScriptOptions({
              {"--nu-sweep", "FROM:TO:N", "volume change and fold-overs at N values of nu from FROM to TO"},
              {"--fields", "OUT.csv", "write det J, distortion and J per mesh vertex"},
              {"--seams", "",
               "measure the jumps of J where mesh edges cross tetrahedra's faces (seam_jump; phong: always), over the "
               "tetrahedral mesh phong would use (--tets, --tet-level)"},
              {"--json", "", "print one JSON object"},
              weldOptionSpec(),
              threadsOptionSpec(),
          })));
}

// FROM:TO:N.
std::vector<double> sweepOption(const ArgParser& args) {
  const std::string text = args.text("--nu-sweep");
  double from = 0, to = 0;
  int count = 0;
  char rest = 0;
  if (std::sscanf(text.c_str(), "%lf:%lf:%d%c", &from, &to, &count, &rest) != 3)
    throw InputError("--nu-sweep", -1, "'" + text + "' is not FROM:TO:N",
                     "give two Poisson ratios and a count, e.g. -0.9:0.49:30");
  return nuSweepValues(from, to, count);
}

std::string csvNumber(double value) {
  if (std::isnan(value)) return "nan";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

// vertex,det_j,conformal_distortion,j00,... (row-major J), one row per mesh vertex in input order.
std::string fieldsCsv(const DeformationAnalysis& a, int dim) {
  std::string out = "vertex,det_j,conformal_distortion";
  for (int r = 0; r < dim; ++r)
    for (int c = 0; c < dim; ++c) out += ",j" + std::to_string(r) + std::to_string(c);
  out += '\n';
  for (Eigen::Index p = 0; p < a.jacobians.rows(); ++p) {
    out += std::to_string(p) + ',' + csvNumber(a.points.detJ(p)) + ',' + csvNumber(a.points.distortion(p));
    for (int k = 0; k < dim * dim; ++k) out += ',' + csvNumber(a.jacobians(p, k));
    out += '\n';
  }
  return out;
}

}  // namespace

std::string analyzeUsage() {
  std::ostringstream out;
  out << "usage: " << kCommand << " --cage REST.obj --posed POSED.obj --mesh MESH.obj [OPTIONS]\n\n"
      << "Measures the deformation of MESH by the cage moved from REST to POSED with the exact deformation gradient\n"
      << "J = df/dx at every vertex (docs/engine.md, \"Quantities\"): the enclosed volume before and after (a closed\n"
      << "mesh; the area in 2D), det J (local volume ratio), the conformal distortion sigma_max/sigma_min of J,\n"
      << "fold-overs (det J <= 0) and the face area ratios. Vertices outside the cage follow the exterior rule and\n"
      << "have no J (outside_points; nan in the CSV). With --seams (always for phong): where mesh edges cross faces\n"
      << "between tetrahedra of the cage, the jump of J across them, |J+ - J-|_F / mean(|J+|_F, |J-|_F) (seam_jump;\n"
      << "0 up to round-off for the smooth methods, whose J is one function).\n\n"
      << "options:\n"
      << analyzeOptions().optionHelp() << "\n"
      << methodsHelp();
  return out.str();
}

int runAnalyzeCommand(const std::vector<std::string>& rawArgs, CommandLog& log) {
  ArgParser args = analyzeOptions();
  args.parse(rawArgs);
  log.configure(args);
  if (args.helpRequested()) {
    std::cout << analyzeUsage();
    return kExitOk;
  }
  const Method method = methodOption(args);
  const DeformParams params = deformParamsOptions(args, method);
  const std::vector<double> nus = args.has("--nu-sweep") ? sweepOption(args) : std::vector<double>();
  const bool json = args.has("--json");
  const int threads = threadsOption(args);
  const std::string meshPath = args.text("--mesh");

  const ReadOptions read = readOptions(args);
  const Cage cage = loadUsableCage(args.text("--cage"), log.sink(), read);
  const Eigen::MatrixXd posed = loadPosedVertices(args.text("--posed"), cage, read);
  const PolygonMesh mesh = loadAnyMesh(meshPath, read);
  const Eigen::MatrixXd points = meshPointsFor(cage, mesh.vertices, meshPath, args.text("--cage"), log.sink());
  noteIgnoredParameters(log, args, method, args.has("--seams"));  // the seams' tetrahedra read --tets, --tet-level

  PrecomputeOptions options = precomputeOptions(threads);
  applyMethodOptions(args, method, cage, options, log.sink());
  std::unique_ptr<CageDeformer> deformer;
  std::shared_ptr<const DeformationGradients> gradients;
  {
    ProgressReporter progress = log.progress("precomputing " + methodName(method) + " coordinates");
    deformer = precompute(method, cage, points, options, meshPath, progress.callback(), commandMemoryCheck(log, true));
  }
  if (const std::optional<Notice> outside = exteriorPointsNotice(*deformer, meshPath)) log.notice(*outside);
  {
    ProgressReporter progress = log.progress("integrating their gradients");
    gradients = deformer->gradients(points, progress.callback());
  }
  std::unique_ptr<SeamJumpEvaluator> seams;
  if (args.has("--seams") || measuresSeamsByDefault(method)) {
    ProgressReporter progress = log.progress("measuring the seams across tetrahedra");
    seams = prepareSeamJumps(*deformer, cage, points, mesh.faces, options, meshPath, progress.callback());
  }
  if (!nus.empty() && !readsParameter(method, kParamNu))
    log.note(methodName(method) + " does not depend on nu; the sweep is flat");
  PoseAnalysis analysis;
  {
    ProgressReporter progress = log.progress("sweeping nu");  // the only part that reports: a sweep takes a while
    analysis = analyzePose(*deformer, *gradients, cage, points, mesh.faces, posed, params, nus, args.text("--posed"),
                           meshPath, progress.callback(), seams.get());
  }
  const DeformationAnalysis& a = analysis.fields;
  if (args.has("--fields")) saveTextFile(args.text("--fields"), fieldsCsv(a, cage.dim()));
  if (!a.volume.closed)
    log.note(meshPath + " is not a closed mesh: it encloses no volume; the volume change with its holes capped by " +
             "cones is reported instead (volume_change_capped)");

  if (json) {
    JsonObjectWriter out(std::cout);
    out.field("method", methodName(method));
    if (readsParameter(method, kParamBlend)) {
      out.field("variant", variantName(params));
      out.field("blend", params.blend);
    }
    if (readsParameter(method, kParamGamma)) out.field("gamma", params.gamma);
    for (const ChoiceParameter& choice : choiceParameters())
      if (readsParameter(method, choice.parameter))
        out.field(choice.name, choice.values[static_cast<std::size_t>(choice.get(params))].name);
    out.field("dimension", cage.dim());
    out.field("vertices", static_cast<int>(points.rows()));
    // An open mesh encloses no volume: null, and the estimate with its holes capped (deformation_quantities.h).
    const double none = std::numeric_limits<double>::quiet_NaN();
    const bool closed = a.volume.closed;
    out.field("closed", closed);
    out.field("volume_rest", closed ? a.volume.rest : none);
    out.field("volume_deformed", closed ? a.volume.deformed : none);
    out.field("volume_change", closed ? a.volume.change() : none);
    if (!closed) out.field("volume_change_capped", a.volume.change());
    out.field("jacobian_det", analysis.jacobianDet);
    out.field("conformal_distortion", analysis.conformalDistortion);
    out.field("foldover_vertices", a.points.foldovers);
    out.field("area_ratio", analysis.areaRatio);
    if (seams) out.field("seam_jump", analysis.seamJump);
    out.field("outside_points", a.points.undefined);
    if (!nus.empty()) {
      std::vector<JsonObjectWriter::NumberObject> entries;
      for (const NuSweepEntry& e : analysis.nuSweep)
        entries.push_back({{"nu", e.nu},
                           {closed ? "volume_change" : "volume_change_capped", e.volumeChange},
                           {"foldover_vertices", static_cast<double>(e.foldovers)}});
      out.field("nu_sweep", entries);
    }
    return kExitOk;
  }
  const char* measure = cage.dim() == 3 ? "volume" : "area";
  std::cout << kCommand << ": " << cage.dim() << "D " << methodName(method) << ", " << points.rows() << " vertices ("
            << a.points.undefined << " outside the cage)\n";
  if (a.volume.closed)
    std::cout << "  " << measure << ": " << formatNumber(a.volume.rest, 10) << " -> "
              << formatNumber(a.volume.deformed, 10) << " (" << formatNumber(100 * a.volume.change(), 4) << " %)\n";
  else
    std::cout << "  " << measure << ": the mesh is open; with its holes capped " << formatNumber(a.volume.rest, 10)
              << " -> " << formatNumber(a.volume.deformed, 10) << " (" << formatNumber(100 * a.volume.change(), 4)
              << " %)\n";
  std::cout << "  det J: min " << formatNumber(quantile(a.points.detJ, 0)) << ", median "
            << formatNumber(quantile(a.points.detJ, 0.5)) << ", max " << formatNumber(quantile(a.points.detJ, 1))
            << "; fold-over vertices (det J <= 0): " << a.points.foldovers << "\n"
            << "  conformal distortion: median " << formatNumber(quantile(a.points.distortion, 0.5)) << ", p95 "
            << formatNumber(quantile(a.points.distortion, 0.95)) << "\n";
  if (seams && seams->crossings().edges.empty())
    std::cout << "  seam jump: no mesh edge crosses a face between " << (cage.dim() == 3 ? "tetrahedra" : "triangles")
              << "\n";
  else if (seams)
    std::cout << "  seam jump |J+ - J-| / |J| across " << (cage.dim() == 3 ? "tetrahedra" : "triangles") << " ("
              << seams->crossings().edges.size() << " crossing edges): median "
              << formatNumber(analysis.seamJump[0].second) << ", p95 " << formatNumber(analysis.seamJump[1].second)
              << ", max " << formatNumber(analysis.seamJump[2].second) << "\n";
  for (const NuSweepEntry& e : analysis.nuSweep)
    std::cout << "  nu " << formatNumber(e.nu) << ": " << measure << " change " << formatNumber(100 * e.volumeChange, 4)
              << " %, fold-overs " << e.foldovers << "\n";
  return kExitOk;
}

}  // namespace somicage
