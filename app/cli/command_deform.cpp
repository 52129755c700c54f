// somicage deform: the batch form of what the editor does on every frame, through the same engine facade
// (engine.h: loadUsableCage, meshPointsFor, precompute, deformPoints), then writeMeshDocument: everything of the
// mesh but its positions is written back as it came, with normals carried by the gradient J or recomputed.
#include <iostream>
#include <sstream>

#include "animation/normal_transform.h"
#include "base/errors.h"
#include "cli/arg_parser.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/progress_reporter.h"
#include "deform/deformer.h"
#include "engine/engine.h"
#include "io/mesh_formats.h"

namespace somicage {

namespace {

const char* const kCommand = "somicage deform";

ArgParser deformOptions() {
  return ArgParser(
      kCommand,
      withDeformParams(
          {
              {"--cage", "REST", "the rest cage: a closed triangle/quad mesh, or a 2D polygon (z = 0)", true},
              {"--posed", "POSED", "the posed cage: the rest cage's vertices, moved, in the same order", true},
              {"--mesh", "IN", "the mesh or point set to deform (2D cage: its x, y; z is kept)", true},
              {"--out", "OUT", "where to write the result (.obj keeps all of IN; .ply, .glb: see the notes)", true},
              weldOptionSpec(),
              {"--recompute-normals", "",
               "recompute IN's normals from the deformed faces instead of carrying them by the gradient J"},
          },
          withScriptOptions({
              threadsOptionSpec(),
              {"--device", "NAME",
               "where the frame is evaluated: cpu (default), opengl, cuda (which integrates the "
               "3D Somigliana coordinates on the device too)"},
          })));
}

// The device of --device (default cpu), refused now, before any file is read, when it says it cannot run here.
const FrameDevice& deviceOption(const ArgParser& args, const FrameDevices& devices) {
  const std::string name = args.has("--device") ? args.text("--device") : "cpu";
  const FrameDevice& device = frameDeviceOption(devices, name);
  const std::string why = device.unavailable ? device.unavailable() : std::string();
  if (!why.empty()) throw InputError("--device " + name, -1, "not usable here: " + why, "use --device cpu");
  return device;
}

std::unique_ptr<FrameEvaluator> makeEvaluator(const FrameDevice& device, const CageDeformer& deformer) {
  try {
    return device.make(deformer);
  } catch (const FrameDeviceUnavailable& e) {
    throw InputError("--device " + device.name, -1, std::string("not usable here: ") + e.what(), "use --device cpu");
  }
}

}  // namespace

std::string deformUsage() {
  std::ostringstream out;
  out << "usage: " << kCommand << " --cage REST --posed POSED --mesh IN --out OUT [OPTIONS]\n\n"
      << "Deforms the vertices of IN with the cage moved from REST to POSED and writes OUT with IN's vertex order\n"
      << "(coordinates with 17 significant digits). An OBJ OUT of an OBJ IN keeps every line of IN but the\n"
      << "positions (UVs, groups, materials, smoothing groups, faces as written); its normals are carried by the\n"
      << "deformation's gradient J (n' = J^-T n, normalised), or recomputed with --recompute-normals.\n"
      << "The cage is 2D when every z is 0. Reads " << readableExtensions() << "; writes " << writableExtensions()
      << ".\n\n"
      << "options:\n"
      << deformOptions().optionHelp() << "\n"
      << methodsHelp();
  return out.str();
}

int runDeformCommand(const std::vector<std::string>& rawArgs, const FrameDevices& devices, CommandLog& log) {
  ArgParser args = deformOptions();
  args.parse(rawArgs);
  log.configure(args);
  if (args.helpRequested()) {
    std::cout << deformUsage();
    return kExitOk;
  }

  // Options first, so that a typo fails before any file is read.
  const Method method = methodOption(args);
  const DeformParams params = deformParamsOptions(args, method);
  const int threads = threadsOption(args);
  const std::string cagePath = args.text("--cage"), posedPath = args.text("--posed");
  const std::string meshPath = args.text("--mesh"), outPath = args.text("--out");
  const FrameDevice& device = deviceOption(args, devices);

  // Inputs.
  const ReadOptions read = readOptions(args);
  const Cage cage = loadUsableCage(cagePath, log.sink(), read);
  const Eigen::MatrixXd posed = posedVerticesFromMesh(loadAnyMesh(posedPath, read), cage, posedPath);
  const MeshDocument document = loadMeshDocument(meshPath, read);
  const PolygonMesh& mesh = document.geometry;
  const Eigen::MatrixXd points = meshPointsFor(cage, mesh.vertices, meshPath, cagePath, log.sink());
  noteIgnoredParameters(log, args, method);

  // Precompute once, deform once.
  PrecomputeOptions options = precomputeOptions(threads);
  options.rowIntegrator = device.rowIntegrator;
  applyMethodOptions(args, method, cage, options, log.sink());
  // The mesh's own normals are carried by the deformation's gradient (normal_transform.h) unless asked otherwise.
  const bool normalsByGradient =
      document.normalCount > 0 && !args.has("--recompute-normals") &&
      gradientsFitForNormals(log, method, cage, static_cast<std::size_t>(points.rows()), options, meshPath);
  const CliClock::time_point precomputeStart = CliClock::now();
  std::unique_ptr<CageDeformer> deformer;
  {
    ProgressReporter progress = log.progress("precomputing " + methodName(method) + " coordinates");
    deformer = precompute(method, cage, points, options, meshPath, progress.callback(),
                          commandMemoryCheck(log, normalsByGradient));
  }
  const double precomputeSeconds = secondsSince(precomputeStart);
  if (const std::optional<Notice> outside = exteriorPointsNotice(*deformer, meshPath)) log.notice(*outside);
  const CliClock::time_point deformStart = CliClock::now();
  const Eigen::MatrixXd deformed =
      deformPoints(*deformer, *makeEvaluator(device, *deformer), cage, posed, params, posedPath, meshPath);
  const double deformSeconds = secondsSince(deformStart);

  Eigen::MatrixXd result = mesh.vertices;  // a 2D cage moves x, y and keeps z
  result.leftCols(cage.dim()) = deformed;
  Eigen::MatrixXd normals;  // empty: recomputed by the writer
  if (normalsByGradient) {
    ProgressReporter progress = log.progress("integrating the gradients for the normals");
    const auto gradients = deformer->gradients(points, progress.callback());
    const TransformedNormals transformed = transformNormals(document, result, *gradients, posed, params);
    normals = transformed.normals;
    if (transformed.recomputed > 0)
      log.note(std::to_string(transformed.recomputed) + " of " + std::to_string(document.normalCount) +
               " normals were recomputed from the deformed faces: their vertices lie outside the cage (or on it), "
               "where the deformation has no gradient");
  }
  for (const std::string& note : writeMeshDocument(outPath, document, result, normals)) log.note(outPath + ": " + note);

  std::ostringstream summary;
  summary << cage.dim() << "D " << methodName(method);
  std::string used;  // the parameters the method reads
  const auto add = [&](DeformParameter p, const std::string& text) {
    if (readsParameter(method, p) && !text.empty()) used += (used.empty() ? "" : ", ") + text;
  };
  add(kParamBlend, params.kind == VariantKind::Blend ? "blend " + formatNumber(params.blend)
                                                    : "variant " + variantName(params));
  add(kParamNu, "nu " + formatNumber(params.nu));
  add(kParamGamma, "gamma " + formatNumber(params.gamma));
  add(kParamTractionFix, params.tractionCorrection ? "" : "no traction fix");
  add(kParamCorotational, params.corotational ? "corotational" : "");
  for (const ChoiceParameter& choice : choiceParameters())  // only where not the default
    if (const int value = choice.get(params))
      add(choice.parameter, std::string(choice.name) + " " + choice.values[static_cast<std::size_t>(value)].name);
  if (!used.empty()) summary << " (" << used << ")";
  summary << ": cage " << cage.numVertices() << " vertices / " << cage.numFaces()
          << (cage.dim() == 3 ? " faces" : " edges") << ", " << points.rows() << " points; precompute "
          << formatSeconds(precomputeSeconds) << ", deform " << formatSeconds(deformSeconds) << "; wrote " << outPath;
  log.status(summary.str());
  return kExitOk;
}

}  // namespace somicage
