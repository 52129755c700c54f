// The boundary element reference deformer (bem_system.h): the linear-elastic solution of the pose.
//
// Precompute: the boundary system of the rest cage and, per point x, the integrals T_i(x), K_j(x)
// (bem_layer_integrals.h). A frame: the displacement u = posed - rest at the cage vertices, the tractions t_j
// from one triangular solve (the LU of the boundary matrix is kept per nu), and the interior displacement
//   x~ = x + sum_i T_i(x) u_i + sum_j K_j(x) t_j + omega                        (Somigliana identity, Eq. 2)
// as one product C W (frame_evaluation.h) with C = [vertex terms | face terms (S, M) | x | 1 | x | 1]: the first
// block is the interior formula, the last d + 1 columns the similarity row of exterior points (exterior_points.h).
//
// DeformParams::corotational removes the cage's best-fit rotation R (Umeyama, as the global Somigliana variant
// fits it) before the solve and applies it after: u'_i = R^T (v~_i - m~) + m - v_i about the rest and posed
// centroids m, m~, and x~ = m~ + R (x + u'(x) - m). Rigid motions are then exact; without it a large rotation of
// the cage shears and inflates the mesh, as linear elasticity does. Off by default. DeformParams::nu is the Poisson
// ratio (validateBemPoissonRatio); blend, gamma and tractionCorrection are ignored.
#pragma once

#include <memory>

#include "deformer.h"

namespace somicage {

std::unique_ptr<CageDeformer> makeBemDeformer(const Cage& restCage, const Eigen::MatrixXd& points,
                                              const PrecomputeOptions& options, const ProgressCallback& progress);

}  // namespace somicage
