// somicage animate: the timeline of a saved editor session, deformed frame by frame and written as a GLB
// (morph-target animation) or an OBJ sequence, through the same core calls as `somicage deform`.
#include <iostream>
#include <sstream>

#include "animation/animation_export.h"
#include "base/errors.h"
#include "base/file_util.h"
#include "cli/arg_parser.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/progress_reporter.h"
#include "engine/session.h"
#include "generation/cage_generation.h"
#include "io/mesh_formats.h"
#include "io/obj_io.h"

namespace somicage {

namespace {

const char* const kCommand = "somicage animate";

ArgParser animateOptions() {
  std::vector<OptionSpec> options = withScriptOptions({
      {"--session", "S.json", "an editor session with poses and keys (File > Save session)", true},
      {"--out", "OUT", "anim.glb (one GLB, morph-target animation) or DIR/ (OBJ sequence)", true},
      {"--fps", "F", "frames per second of the GLB (default: the session's timeline)"},
      {"--frames", "A:B", "the frames to write, inclusive (default: the timeline's range)"},
      {"--recompute-normals", "",
       "OBJ sequence: recompute the normals from the deformed faces instead of carrying them by J"},
      threadsOptionSpec(),
  });
  const std::vector<OptionSpec> methodOptions = methodOptionSpecs();  // over the session's "methodOptions"
  options.insert(options.end(), methodOptions.begin(), methodOptions.end());
  return ArgParser(kCommand, options);
}

void parseFrameRange(const std::string& text, int& first, int& last) {
  const size_t colon = text.find(':');
  try {
    size_t used = 0;
    if (colon == std::string::npos) throw std::invalid_argument("no colon");
    first = std::stoi(text.substr(0, colon), &used);
    if (used != colon) throw std::invalid_argument("junk");
    last = std::stoi(text.substr(colon + 1), &used);
    if (used != text.size() - colon - 1) throw std::invalid_argument("junk");
  } catch (const std::exception&) {
    throw InputError("--frames", -1, "'" + text + "' is not a frame range", "write --frames A:B, e.g. --frames 0:48");
  }
  if (last < first) throw InputError("--frames", -1, "the range " + text + " is empty", "write A:B with A <= B");
}

}  // namespace

std::string animateUsage() {
  std::ostringstream out;
  out << "usage: " << kCommand << " --session S.json --out anim.glb|DIR/ [--fps 24] [--frames A:B]\n\n"
      << "Plays the session's timeline (its keys, poses and interpolation) and writes every\n"
      << "whole frame of A..B: a .glb OUT gets the mesh at frame A and one morph target per later frame N, named\n"
      << "frame_N, animated at F frames per second (Blender imports them as shape keys); a folder OUT (ending in '/',\n"
      << "or without an extension) becomes a new folder of NAME_0001.obj ... files (numbered by frame), each keeping\n"
      << "everything of the OBJ mesh but its positions. Any other OUT (a.obj) is refused before any work. Nothing\n"
      << "is left half-written on failure. The session's method deforms with its parameters and its own options\n"
      << "(\"methodOptions\": phong's tets file, next to the session or as given, and tet-level); --tets and\n"
      << "--tet-level replace them.\n\n"
      << "options:\n"
      << animateOptions().optionHelp();
  return out.str();
}

int runAnimateCommand(const std::vector<std::string>& rawArgs, CommandLog& log) {
  ArgParser args = animateOptions();
  args.parse(rawArgs);
  log.configure(args);
  if (args.helpRequested()) {
    std::cout << animateUsage();
    return kExitOk;
  }
  const std::string sessionPath = args.text("--session"), outPath = args.text("--out");
  const AnimationOutput output = animationOutput(outPath);  // a.obj is refused before any work
  const int threads = threadsOption(args);

  const Session session = loadSession(sessionPath);  // core/engine/session.h: the editor's own reader
  if (session.meshPath.empty()) {
    throw InputError(sessionPath, -1, "the session animates a built-in demo, which has no mesh file",
                     "open a mesh and a cage in the editor, key it, and save the session again");
  }
  if (session.timeline.keys.empty()) {
    throw InputError(sessionPath, -1, "the session's timeline has no keys",
                     "add keys in the editor's Timeline panel (Key pose) and save the session");
  }
  int first = session.timeline.firstFrame, last = session.timeline.lastFrame;
  if (args.has("--frames")) parseFrameRange(args.text("--frames"), first, last);
  const double fps = args.number("--fps", session.timeline.fps);
  if (!(fps > 0 && fps <= 1000)) throw InputError("--fps", -1, "must be in (0, 1000]", "write e.g. --fps 24");

  const std::string& meshPath = session.meshPath;
  const MeshDocument document = loadMeshDocument(meshPath);
  // The rest cage the editor shows: the session's inline cage, else its cage file, else (a version 1-2 session of a
  // mesh opened alone) the cage the editor generates for the mesh, with `somicage cage`'s defaults.
  const NoticeSink notices = log.sink();
  std::string cageSource = session.cagePath;
  Cage cage;
  if (session.restCage.numVertices() > 0) {
    cageSource = sessionPath + " (restCage)";
    cage = session.restCage;
    for (const Notice& notice : session.cageNotices) notices(notice);
  } else if (!session.cagePath.empty()) {
    cage = loadUsableCage(cageSource, notices);
  } else {
    cageSource = meshPath;
    const PolygonMesh& mesh = document.geometry;
    cage = prepareCage(generateCage(mesh.vertices, triangulatePolygons(mesh.vertices, mesh.faces), {}, meshPath).cage,
                       meshPath, notices);
  }
  const Eigen::MatrixXd points = meshPointsFor(cage, document.geometry.vertices, meshPath, cageSource, notices);
  PrecomputeOptions options = precomputeOptions(threads);
  options.methodOptions = session.methodOptions;  // the session's, then the command line's (--tets) over them
  applyMethodOptions(args, session.method, cage, options, notices);
  // An OBJ sequence carries the mesh's normals by the deformation's gradient (normal_transform.h); GLB has none.
  const bool normalsByGradient =
      document.normalCount > 0 && !args.has("--recompute-normals") && output == AnimationOutput::ObjSequence &&
      gradientsFitForNormals(log, session.method, cage, static_cast<std::size_t>(points.rows()), options, meshPath);
  std::unique_ptr<CageDeformer> deformer;
  {
    ProgressReporter progress = log.progress("precomputing " + methodName(session.method) + " coordinates");
    deformer = precompute(session.method, cage, points, options, meshPath, progress.callback(),
                          commandMemoryCheck(log, normalsByGradient));
  }
  if (const std::optional<Notice> outside = exteriorPointsNotice(*deformer, meshPath)) log.notice(*outside);
  std::vector<Eigen::MatrixXd> frames;
  {
    ProgressReporter progress = log.progress("deforming frames " + std::to_string(first) + ".." + std::to_string(last));
    frames = deformTimelineFrames(*deformer, cage, session.timeline, session.poses, session.params,
                                  document.geometry.vertices, cage.dim(), first, last, progress.callback());
  }
  std::vector<Eigen::MatrixXd> normals;  // empty: recomputed per frame
  if (normalsByGradient) {
    std::shared_ptr<const DeformationGradients> gradients;
    {
      ProgressReporter progress = log.progress("integrating the gradients for the normals");
      gradients = deformer->gradients(points, progress.callback());
    }
    ProgressReporter progress = log.progress("carrying the normals");
    normals = deformTimelineNormals(*gradients, cage, session.timeline, session.poses, session.params, document, frames,
                                    first, progress.callback());
  }
  {
    ProgressReporter progress = log.progress("writing " + outPath);
    for (const std::string& note : writeAnimation(outPath, document, frames, first, fps, progress.callback(), normals))
      log.note(outPath + ": " + note);
  }
  log.status(std::to_string(frames.size()) + " frames (" + std::to_string(first) + ".." + std::to_string(last) +
             ") of " + meshPath + " at " + formatNumber(fps) + " fps; wrote " + outPath);
  return kExitOk;
}

}  // namespace somicage
