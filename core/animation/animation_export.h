// Animation export: the timeline's frames deformed and written as one GLB (a morph target per frame,
// gltf_writer.h) or as a folder of OBJ files NAME_0001.obj ... (one per frame, numbered by frame, each lossless
// as writeObjDocument writes it). Nothing is half-written: the GLB goes through an atomic write, the OBJ sequence
// is written into a temporary folder next to the target and renamed onto it at the end.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "animation/pose_timeline.h"
#include "base/progress.h"
#include "deform/deformer.h"
#include "deform/jacobian.h"
#include "io/mesh_document.h"

namespace somicage {

// The mesh's positions at frames first..last (inclusive): the timeline evaluated at each whole frame, then
// deformed. A 2D cage moves x, y and keeps the mesh's z. progress gets the fraction of frames done; returning
// false throws Cancelled. Throws InputError when a frame cannot be deformed (a point not finite).
std::vector<Eigen::MatrixXd> deformTimelineFrames(const CageDeformer& deformer, const Cage& cage,
                                                  const Timeline& timeline, const PoseLibrary& poses,
                                                  const DeformParams& base, const Eigen::MatrixXd& meshVertices,
                                                  int dim, int first, int last,
                                                  const ProgressCallback& progress = noProgress);

// The document's `vn` normals at each of frames (frame k is timeline frame first + k, 3 columns), carried by the
// deformation's gradient (normal_transform.h; gradients made for the mesh's vertices). progress as above.
std::vector<Eigen::MatrixXd> deformTimelineNormals(const DeformationGradients& gradients, const Cage& cage,
                                                   const Timeline& timeline, const PoseLibrary& poses,
                                                   const DeformParams& base, const MeshDocument& document,
                                                   const std::vector<Eigen::MatrixXd>& frames, int first,
                                                   const ProgressCallback& progress = noProgress);

// Whether out names one GLB (a path ending in .glb, any case) rather than an OBJ sequence.
bool writesGlb(std::string out);

// What writeAnimation makes of out: one GLB for a path ending in .glb (any case), an OBJ sequence for a folder path
// (ending in '/', or whose last name has no extension). Anything else (a.obj: neither a GLB nor clearly a folder)
// throws InputError naming out, so that a command refuses it before any work.
enum class AnimationOutput { Glb, ObjSequence };
AnimationOutput animationOutput(const std::string& out);

// Writes frames (frame k is timeline frame first + k) to out (animationOutput): one GLB at fps whose morph targets
// are named by timeline frame (gltf_writer.h), or a new folder for the OBJ sequence (it must not exist, or be empty;
// created with the user's umask). Returns the notes of what the format could not carry. normals: per frame, the OBJ
// sequence's `vn` (empty: recomputed per frame; GLB carries none). progress as above (for the writing).
std::vector<std::string> writeAnimation(const std::string& out, const MeshDocument& document,
                                        const std::vector<Eigen::MatrixXd>& frames, int first, double fps,
                                        const ProgressCallback& progress = noProgress,
                                        const std::vector<Eigen::MatrixXd>& normals = {});

}  // namespace somicage
