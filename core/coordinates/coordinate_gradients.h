// The exact gradients, with respect to the query point x, of the coordinates each method integrates: forward-mode
// dual numbers (dual_number.h) carried through the same closed forms, or (3D Somigliana) the closed-form derivatives
// of those integrals, so that the deformation gradient (jacobian.h) is exact to rounding rather than a finite
// difference of positions.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>

#include "base/progress.h"
#include "geometry/cage.h"

namespace somicage {

// Receives a point's gradient rows: rows[a] (a < d) holds d(row)/dx_a, `columns` numbers in the layout of the
// method's coordinates. Called from OpenMP worker threads, once per point; the buffers are reused after it returns.
using GradientRowSink = std::function<void(int point, const double* const* rows)>;

// A group of points' gradient rows where the integrator left them: d(row of point first + l)[k] / dx_a at
// rows[a][l * laneStride + k * entryStride], l < count. The closed form's packs leave a group's rows interleaved
// (laneStride 1, entryStride 3 lanes): read with the lanes innermost, they are read once, in order, and not copied.
struct GradientRowGroup {
  int first = 0, count = 0;
  const double* rows[3] = {nullptr, nullptr, nullptr};
  std::ptrdiff_t laneStride = 0, entryStride = 0;
};
// Called from OpenMP worker threads, once per group; the buffers are reused after it returns.
using GradientGroupSink = std::function<void(const GradientRowGroup& group)>;

// Somigliana: rows in the layout of SomiglianaCoordinates::values (somiglianaLayout's main columns), always from the
// closed form (also for a deformer whose coordinates came from the Gauss baseline). A 3D cage runs the closed-form
// derivatives of the triangle integrals (triangle_gradients_kernel.h, docs/closed-form-gradients.md) in packs of
// simd::kLanes points, as the precompute, one group per pack; scalarKernel = true (and 2D cages, and builds without
// packs) runs the dual-number kernel one point at a time (groups of one), the independent reference. The two agree
// to 1e-12 of each entry (at least 1; coordinate_gradients_test.cpp).
void integrateSomiglianaGradientGroups(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                                       const ProgressCallback& progress, const GradientGroupSink& sink,
                                       bool scalarKernel = false);

// The same rows one point at a time, each row contiguous (a copy of the group's).
void integrateSomiglianaGradients(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                                  const ProgressCallback& progress, const GradientRowSink& sink,
                                  bool scalarKernel = false);

// Green: rows [phi (#V) | psi (#F)] (green_coordinates.h). phi_i and psi_j are the double layer of the hats and
// the single layer of the faces, the integrals D_k and S that the Somigliana kernels compute as well.
// Green and BEM (3D) integrate kLanes points at once as well, the per-face kernel on duals of packs with the
// accumulation outside it; scalarKernel as above.
void integrateGreenGradients(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                             const ProgressCallback& progress, const GradientRowSink& sink, bool scalarKernel = false);

// BEM: rows in the layout of BemLayerIntegrals::values (bemLayerLayout, bem_layer_integrals.h) for points off the
// cage.
void integrateBemLayerGradients(const Cage& cage, const Eigen::MatrixXd& points, int threads,
                                const ProgressCallback& progress, const GradientRowSink& sink,
                                bool scalarKernel = false);

}  // namespace somicage
