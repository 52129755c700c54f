// glTF 2.0 binary (.glb) output through tinygltf: a mesh, and optionally its animation as one morph target per
// frame, which Blender imports as shape keys driven by the action and other viewers play as they are.
//
// The mesh is triangulated (each polygon cut as triangulatePolygons cuts it at rest, so every frame has the same
// triangles), one primitive per `usemtl` material in order of first use (mesh_material.h: the .mtl's or the source
// file's colour and opacity as a glTF PBR base colour, not metallic, fully rough; its base-colour texture as an image
// embedded in the GLB's buffer, PNG or JPEG, when the faces have UVs; a texture file that is missing is named in the
// notes and left out), positions as 32-bit floats (glTF has no doubles). When every face has UVs, each distinct
// (vertex, `vt`) pair of the faces is one glTF vertex, in order of first appearance, with TEXCOORD_0 (v flipped: glTF's
// origin is at the top); otherwise glTF vertex i is mesh vertex i. `l` polylines are not written (named in the notes).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "io/mesh_document.h"

namespace somicage {

// frames: one #V by 2 or 3 position matrix per frame (frame k plays at time k / fps). The first frame is the
// mesh's own positions; frames 1.. are morph targets, weight 1 at their time and 0 elsewhere (LINEAR sampler),
// named "frame_N" by the timeline frame N = firstFrame + k they hold (Blender's shape key names).
// Written atomically; returns one sentence per kind of data the file does not carry.
std::vector<std::string> writeGlbAnimation(const std::string& path, const MeshDocument& document,
                                           const std::vector<Eigen::MatrixXd>& frames, double fps, int firstFrame = 0);

}  // namespace somicage
