#include "jobs/export_jobs.h"

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "animation/animation_export.h"
#include "animation/normal_transform.h"
#include "base/errors.h"
#include "base/progress.h"
#include "deform/jacobian.h"
#include "deform/memory_estimate.h"
#include "deform/method.h"
#include "io/mesh_document.h"
#include "io/mesh_formats.h"
#include "io/obj_io.h"
#include "model/app_state.h"
#include "model/pose_keys.h"

namespace somicage::editor {

void pollExport(AppState& state) {
  std::optional<ExportOutcome> outcome = state.jobs.exporter.poll();
  if (!outcome) return;
  if (outcome->cancelled) {
    state.status.message = "export cancelled; nothing was written to " + outcome->target;
  } else if (!outcome->error.empty()) {
    state.status.errors.push_back(outcome->error);
    state.status.message = "export failed; nothing was written to " + outcome->target;
  } else {
    for (const std::string& note : outcome->notes) state.status.errors.push_back("export: " + note);
    state.status.message = outcome->doneMessage;
  }
}

bool gradientsFit(const CageDeformer& deformer, std::string* note) {
  const std::size_t bytes = static_cast<std::size_t>(deformer.dim()) * deformer.frameCoordinates().bytes();
  const std::optional<std::size_t> available = availableMemoryBytes();
  if (!available || static_cast<double>(bytes) <= 0.85 * static_cast<double>(*available)) return true;
  *note = "the normals were recomputed from the deformed faces: carrying them by the gradient would need " +
          formatBytes(bytes) + " (" + formatBytes(*available) + " free)";
  return false;
}

// The first view's mesh: the current method at the panel's parameters, or the compare view's first pane.
ExportWorker::Job makeMeshExportJob(AppState& state, const std::string& path) {
  ensureCpuPoints(state, 0);
  const Eigen::MatrixXd& points = displayedPoints(state, 0);
  const Method method = state.views().front().method;
  const std::shared_ptr<const Scene> scene = state.model.scene;
  ExportWorker::Job job;
  if (scene->document) {  // a file: everything of it but the positions is kept (core/io/mesh_formats.h)
    Eigen::MatrixXd positions = scene->document->geometry.vertices;  // a 2D scene keeps z
    positions.leftCols(points.cols()) = points;
    std::shared_ptr<const CageDeformer> deformer;
    if (hasDeformer(state, method) && scene->document->normalCount > 0) deformer = state.model.deformers.at(method);
    job = [scene, deformer, positions, path, pose = state.document.pose,
           params = state.viewParams(0)](const ProgressCallback& progress) {
      std::vector<std::string> notes;
      Eigen::MatrixXd normals;  // empty: recomputed by the writer
      std::string note;
      if (deformer && gradientsFit(*deformer, &note)) {
        // the gradients kept with the coordinates (a J view's, an earlier export's), else integrated and kept
        const auto gradients = deformer->gradients(scene->meshVertices, stageProgress(progress, 0.0, 0.9));
        const TransformedNormals carried = transformNormals(*scene->document, positions, *gradients, pose, params);
        normals = carried.normals;
        if (carried.recomputed > 0)
          notes.push_back(std::to_string(carried.recomputed) +
                          " normals were recomputed: their vertices lie outside the cage, where J is undefined");
      } else if (!note.empty()) {
        notes.push_back(note);
      }
      if (!progress(0.9)) throw Cancelled();
      for (std::string& n : writeMeshDocument(path, *scene->document, positions, normals)) notes.push_back(n);
      return notes;
    };
  } else {  // a demo: its triangles
    job = [scene, points = Eigen::MatrixXd(points), path](const ProgressCallback&) {
      PolygonMesh topology;
      const Eigen::MatrixXi& f = scene->meshTriangles;
      topology.faces.reserve(static_cast<std::size_t>(f.rows()));
      for (Eigen::Index i = 0; i < f.rows(); ++i) topology.faces.push_back({f(i, 0), f(i, 1), f(i, 2)});
      saveObj(path, points, topology);
      return std::vector<std::string>();
    };
  }
  return job;
}

bool exportDeformedMesh(AppState& state, const std::string& path) {
  if (!state.model.scene) return false;
  if (state.jobs.exporter.busy()) {
    state.status.errors.push_back("Export: another export is running; wait for it or cancel it");
    return false;
  }
  state.jobs.exporter.start(
      path, "exported the deformed mesh (" + std::string(state.views().front().method->displayName) + ") to " + path,
      makeMeshExportJob(state, path));
  state.status.message = "exporting the deformed mesh to " + path;
  return true;
}

ExportWorker::Job makeAnimationExportJob(AppState& state, AnimationExportJob::Kind kind, const std::string& out) {
  if (kind == AnimationExportJob::Kind::Glb && !writesGlb(out)) {
    state.status.errors.push_back("Export animation: " + out +
                                  " does not end in .glb; give a file name like animation.glb");
    return {};
  }
  if (kind == AnimationExportJob::Kind::ObjSequence && writesGlb(out)) {
    state.status.errors.push_back("Export animation: " + out + " ends in .glb; give a new folder for the OBJ sequence");
    return {};
  }
  if (!hasDeformer(state, state.document.method)) {
    state.status.errors.push_back(
        "Export animation: the coordinates are still being computed; export when they are ready");
    return {};
  }
  if (state.jobs.exporter.busy()) {
    state.status.errors.push_back("Export animation: another export is running; wait for it or cancel it");
    return {};
  }
  const std::shared_ptr<const Scene> scene = state.model.scene;
  const std::shared_ptr<const CageDeformer> deformer = state.model.deformers.at(state.document.method);
  const AnimationState& a = state.animation;
  const int first = a.timeline.firstFrame, last = a.timeline.lastFrame;
  const bool carryNormals = kind == AnimationExportJob::Kind::ObjSequence && scene->document->normalCount > 0;
  return [scene, deformer, timeline = a.timeline, poses = a.poses, params = state.document.params, out, first, last,
          carryNormals](const ProgressCallback& progress) {
    const MeshDocument& document = *scene->document;
    const std::vector<Eigen::MatrixXd> frames =
        deformTimelineFrames(*deformer, scene->restCage, timeline, poses, params, document.geometry.vertices,
                             scene->dim(), first, last, stageProgress(progress, 0.0, carryNormals ? 0.3 : 0.8));
    std::vector<Eigen::MatrixXd> normals;  // empty: recomputed per frame
    std::vector<std::string> notes;
    std::string note;
    if (carryNormals && gradientsFit(*deformer, &note)) {
      const auto gradients = deformer->gradients(scene->meshVertices, stageProgress(progress, 0.3, 0.7));
      normals = deformTimelineNormals(*gradients, scene->restCage, timeline, poses, params, document, frames, first,
                                      stageProgress(progress, 0.7, 0.8));
    } else if (!note.empty()) {
      notes.push_back(note);
    }
    for (std::string& n :
         writeAnimation(out, document, frames, first, timeline.fps, stageProgress(progress, 0.8, 1.0), normals))
      notes.push_back(n);
    return notes;
  };
}

}  // namespace somicage::editor
