// The editor's file exports as ExportWorker jobs (export_worker.h): File > Export deformed mesh here, the GLB / OBJ
// sequence of File > Export animation in animation_export_job.cpp. Both carry the mesh's own normals by the
// deformation's gradient (core/animation/normal_transform.h) when it has `vn` and the gradients fit in memory, and
// write through core's writers (mesh_formats.h, animation_export.h), the same calls as `somicage deform` / `animate`.
#pragma once

#include <string>

#include "deform/deformer.h"
#include "jobs/animation_export_job.h"
#include "jobs/export_worker.h"

namespace somicage::editor {

struct AppState;

// The job of File > Export deformed mesh: the shown method's deformed mesh (the scene's file, lossless; a demo's
// triangles) with its normals carried by J. exportDeformedMesh (app_state.h) starts it.
ExportWorker::Job makeMeshExportJob(AppState& state, const std::string& path);

// The job of File > Export animation as a GLB (kind Glb, out ending in .glb) or an OBJ sequence (a new folder): the
// timeline's frames deformed with the current method, as `somicage animate` does. Empty, with the reason in
// state.errors, when the request cannot run (a wrong extension, the deformer not computed yet).
ExportWorker::Job makeAnimationExportJob(AppState& state, AnimationExportJob::Kind kind, const std::string& out);

// Takes a finished export into the status line (done, cancelled) or state.errors (failure, the format's notes).
void pollExport(AppState& state);

// Whether the gradients of deformer's points fit in the free memory (they take about 3x the coordinates); when
// not, the normals are recomputed and *note says why.
bool gradientsFit(const CageDeformer& deformer, std::string* note);

}  // namespace somicage::editor
