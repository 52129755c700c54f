// The "Fig. 8" demo (the paper's Fig. 8, C-infinity smoothness): the 3D demo's bar twisted in its cage, shown by the
// Phong deformer (James 2020) over a coarse and a finer tetrahedral mesh of the cage beside Somigliana's local
// variant at nu = 0. Phong is only C0 across tetrahedra: its shading creases where the mesh crosses their faces,
// whatever the mesh's detail; Somigliana's is smooth. No files: the scene is makeDemoScene(3). No GL.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "engine/view_spec.h"
#include "geometry/cage.h"
#include "model/app_state.h"

namespace somicage::editor {

// The tetrahedral mesh level of the finer Phong view (cage_tetrahedralization.h); the coarse one is the cage's star.
constexpr const char* kFig8FineTetLevel = "2";
// How far the ends of the bar turn about its axis (radians, opposite ways); the stations between turn in proportion.
constexpr double kFig8TwistRadians = 1.0;
// How far the middle of the cage rises above its ends (a parabolic arch along x, in scene units; the bar's radius is
// 0.5), so that the smooth view visibly bends too (a twisted cylinder looks like a cylinder).
constexpr double kFig8ArchHeight = 0.6;

// The views: Phong on the cage's star (one Steiner vertex), Phong on CGAL's level-2 mesh, Somigliana local nu = 0.
std::vector<ViewSpec> fig8Views();
// The demo cage twisted about the bar's axis (x), each vertex turned by kFig8TwistRadians * t (t = x / the cage's
// half length), then arched: y + kFig8ArchHeight (1 - t^2).
Eigen::MatrixXd fig8Pose(const Cage& restCage);

// Opens the demo: the scene, its pose (the opened state, the history's first step), and the compare view of
// fig8Views() unless keepViews (the command line gave its own --view / --compare).
void requestFig8Demo(AppState& state, bool keepViews = false);

}  // namespace somicage::editor
