#include "animation/animation_export.h"

#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "animation/normal_transform.h"
#include "base/errors.h"
#include "io/gltf_writer.h"

namespace somicage {

namespace {

namespace fs = std::filesystem;

void step(const ProgressCallback& progress, double fraction) {
  if (!progress(fraction)) throw Cancelled();
}

// Removes the temporary folder unless it was renamed onto the target.
struct TemporaryFolder {
  fs::path path;
  bool kept = false;
  ~TemporaryFolder() {
    std::error_code ignored;
    if (!kept && !path.empty()) fs::remove_all(path, ignored);
  }
};

// A new, empty folder next to target, made as mkdir makes folders (0777 less the umask): mkdtemp's 0700 would stay on
// the sequence once it is renamed into place.
fs::path makeTemporaryFolder(const std::string& out, const fs::path& target, const fs::path& parent) {
  const std::string stem = (parent / target.filename()).string() + ".tmp-" + std::to_string(::getpid()) + "-";
  std::error_code error;
  for (int attempt = 0; attempt < 1000; ++attempt) {
    const fs::path candidate = stem + std::to_string(attempt);
    if (fs::create_directory(candidate, error)) return candidate;
    if (error) break;  // not "it exists already": permissions, a full disk
  }
  throw InputError(out, -1, "cannot create a folder next to it" + (error ? ": " + error.message() : std::string()),
                   "check the permissions of " + parent.string());
}

std::vector<std::string> writeObjSequence(const std::string& out, const MeshDocument& document,
                                          const std::vector<Eigen::MatrixXd>& frames, int first,
                                          const ProgressCallback& progress,
                                          const std::vector<Eigen::MatrixXd>& normals) {
  std::error_code error;
  fs::path target = fs::path(out);
  if (target.filename().empty()) target = target.parent_path();  // "DIR/"
  if (fs::exists(target, error) && (!fs::is_directory(target, error) || !fs::is_empty(target, error))) {
    throw InputError(out, -1, "exists and is not an empty folder",
                     "give a new folder for the OBJ sequence (or a path ending in .glb)");
  }
  const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(parent, error)) {
    throw InputError(out, -1, "the folder " + parent.string() + " does not exist", "create it first");
  }
  TemporaryFolder temporary;
  temporary.path = makeTemporaryFolder(out, target, parent);
  const std::string stem = document.sourcePath.empty() ? "mesh" : fs::path(document.sourcePath).stem().string();
  for (size_t k = 0; k < frames.size(); ++k) {
    char number[16];
    std::snprintf(number, sizeof number, "_%04d.obj", first + static_cast<int>(k));
    writeObjDocument((temporary.path / (stem + number)).string(), document, frames[k],
                     normals.empty() ? Eigen::MatrixXd() : normals[k]);
    step(progress, static_cast<double>(k + 1) / static_cast<double>(frames.size()));
  }
  if (fs::exists(target, error)) fs::remove(target, error);  // empty, checked above
  fs::rename(temporary.path, target, error);
  if (error)
    throw InputError(out, -1, "cannot rename the finished sequence into place: " + error.message(),
                     "check the permissions");
  temporary.kept = true;
  return {};
}

}  // namespace

bool writesGlb(std::string out) {
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out.size() > 4 && out.compare(out.size() - 4, 4, ".glb") == 0;
}

AnimationOutput animationOutput(const std::string& out) {
  if (writesGlb(out)) return AnimationOutput::Glb;
  const fs::path path(out);
  if (!out.empty() && (out.back() == '/' || !path.has_extension())) return AnimationOutput::ObjSequence;
  throw InputError(out, -1, "is neither a .glb file nor a folder",
                   "write anim.glb for one GLB, or a folder such as frames/ (ending in '/') for an OBJ sequence");
}

std::vector<Eigen::MatrixXd> deformTimelineFrames(const CageDeformer& deformer, const Cage& cage,
                                                  const Timeline& timeline, const PoseLibrary& poses,
                                                  const DeformParams& base, const Eigen::MatrixXd& meshVertices,
                                                  int dim, int first, int last, const ProgressCallback& progress) {
  if (last < first)
    throw InputError("--frames", -1, "the last frame comes before the first", "write --frames A:B with A <= B");
  std::vector<Eigen::MatrixXd> frames;
  for (int frame = first; frame <= last; ++frame) {
    const FrameState state = evaluateTimeline(timeline, poses, frame, base, cage.numVertices(), cage.dim());
    validateDeformParams(state.params);
    const Eigen::MatrixXd deformed = deformer.deform(state.cage, state.params);
    if (!deformed.allFinite()) {
      throw InputError("frame " + std::to_string(frame), -1, "some points could not be deformed",
                       "nothing was written; please report this with the session");
    }
    Eigen::MatrixXd positions = meshVertices;
    positions.leftCols(dim) = deformed;
    frames.push_back(std::move(positions));
    step(progress, static_cast<double>(frame - first + 1) / static_cast<double>(last - first + 1));
  }
  return frames;
}

std::vector<Eigen::MatrixXd> deformTimelineNormals(const DeformationGradients& gradients, const Cage& cage,
                                                   const Timeline& timeline, const PoseLibrary& poses,
                                                   const DeformParams& base, const MeshDocument& document,
                                                   const std::vector<Eigen::MatrixXd>& frames, int first,
                                                   const ProgressCallback& progress) {
  std::vector<Eigen::MatrixXd> normals;
  for (size_t k = 0; k < frames.size(); ++k) {
    const FrameState state =
        evaluateTimeline(timeline, poses, first + static_cast<int>(k), base, cage.numVertices(), cage.dim());
    normals.push_back(transformNormals(document, frames[k], gradients, state.cage, state.params).normals);
    step(progress, static_cast<double>(k + 1) / static_cast<double>(frames.size()));
  }
  return normals;
}

std::vector<std::string> writeAnimation(const std::string& out, const MeshDocument& document,
                                        const std::vector<Eigen::MatrixXd>& frames, int first, double fps,
                                        const ProgressCallback& progress, const std::vector<Eigen::MatrixXd>& normals) {
  if (animationOutput(out) == AnimationOutput::Glb) {
    step(progress, 0.0);  // the last chance to stop: once the file is in place, it stays
    std::vector<std::string> notes = writeGlbAnimation(out, document, frames, fps, first);
    progress(1.0);
    return notes;
  }
  return writeObjSequence(out, document, frames, first, progress, normals);
}

}  // namespace somicage
