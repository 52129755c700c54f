// Points that a cage's coordinates cannot deform -- outside the cage, on it, or inside where the integrals are
// unreliable -- and the smooth rule they follow instead (docs/engine.md, "Points outside the cage"):
//
//   x~(x) = S(x) + w(d) [phi(x_in) - S(x_in)],      w(d) = 1 - smootherstep(d / band)
//
// S(x) = s R x + t is the posed cage's best-fit similarity (boundary_conditions.h), c the closest point of the
// rest cage to x, d = |x - c|, n the outward pseudo-normal at c (the face normal; on an edge the normalised sum of
// its faces' normals; at a vertex the angle-weighted normal of Baerentzen & Aanaes 2005; in 2D the edge normal, or
// the sum of the two edge normals at a vertex), x_in = c - h n a proxy point just inside the cage, and phi the
// method's own deformation. Points on the cage and interior points with unreliable integrals take d = 0 (w = 1).
// The result is a pure similarity beyond the band, C2 in d, and continuous across the cage up to O(h).
//
// The deformers store the rule in their coordinate matrix (frame_evaluation.h: two extra rows per exterior point),
// so every frame, on the CPU or the GPU, costs two more rows per exterior point and nothing else.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <functional>
#include <vector>

#include "deform/frame_evaluation.h"
#include "geometry/cage.h"
#include "geometry/cage_proximity.h"

namespace somicage {

// h: deep enough that the proxy's closed-form integrals keep full accuracy (|sum T_i - I| <= 6e-13 measured there,
// 1e-11 tested), shallow enough that the jump across the cage, O(h |grad phi - sR|), stays below 4e-5 diameters.
constexpr double kProxyDepth = 1e-5;  // in cage diameters
// The band over which the interior deformation fades into the similarity: wide enough that the fall-off has
// bounded derivatives (|w'| <= 1.875 / band), narrow enough that points far from the cage move rigidly.
constexpr double kExteriorBand = 0.25;  // in cage diameters
// A point inside the cage whose exact integrals miss the partition of unity (Eq. 9; for Green coordinates
// sum_i phi_i = 1) by more than this, or are not finite, lies on the cage or within round-off of it.
constexpr double kUnreliableResidual = 1e-8;

// How a point is deformed. Inside: its own coordinates. Outside (winding number < 1/2) and OnCage (winding
// >= 1/2 but unreliable integrals: on the cage or within round-off of it): the rule above.
enum class PointRegion : unsigned char { Inside, Outside, OnCage };

PointRegion classifyPoint(double winding, bool reliableIntegrals);

// w(d) = 1 - smootherstep(d / band): 1 at d = 0, 0 from d = band on, C2 (6t^5 - 15t^4 + 10t^3).
double exteriorWeight(double distance, double band);

// The exterior points of a precompute: a blend per point whose region is not Inside (ascending point order), the
// closest point of each and its proxy x_in = c - h n (#E by d). threads = 0: the OpenMP default; the result does
// not depend on it.
struct ExteriorPlan {
  std::vector<ExteriorBlend> blends;
  std::vector<CageProximity::Closest> closest;
  Eigen::MatrixXd proxies;
};
ExteriorPlan planExteriorPoints(const Cage& restCage, const Eigen::MatrixXd& points,
                                const std::vector<PointRegion>& regions, int threads = 0);

// Integrates the proxies of `plan` with integrate(proxies, which) -- which[k] is the exterior index of row k of
// proxies; it stores their rows of C and returns whether each one's integrals are reliable -- and moves the
// proxies that fail to coarser features (CageProximity::coarsen) to integrate them again. A proxy that fails at
// a corner too keeps what integrate stored for it last (the deformers store the anchor row: S alone).
using ProxyIntegrator = std::function<std::vector<bool>(const Eigen::MatrixXd& proxies, const std::vector<int>& which)>;
void integrateProxies(const Cage& restCage, ExteriorPlan& plan, const ProxyIntegrator& integrate);

// The row [0 ... 0 | x | 1] of C (the last d + 1 of `columns` hold point p of points, then 1): with the frame's
// tail weights it evaluates to the similarity S(x).
template <typename Scalar>
void writeSimilarityRow(const Eigen::MatrixXd& points, int p, Scalar* row, int columns) {
  const int d = static_cast<int>(points.cols());
  std::fill(row, row + columns, Scalar(0));
  for (int a = 0; a < d; ++a) row[columns - d - 1 + a] = static_cast<Scalar>(points(p, a));
  row[columns - 1] = 1;
}
// The same row as sparse entries (coordinate_layout.h, rowEntries >= d + 1): x and 1 at the last d + 1 of `columns`,
// the other entries 0 at the last column.
template <typename Scalar, typename Index>
void writeSimilarityEntries(const Eigen::MatrixXd& points, int p, Scalar* values, Index* entryColumns, int entries,
                            int columns) {
  const int d = static_cast<int>(points.cols());
  std::fill(values, values + entries, Scalar(0));
  std::fill(entryColumns, entryColumns + entries, static_cast<Index>(columns - 1));
  for (int a = 0; a < d; ++a) {
    values[a] = static_cast<Scalar>(points(p, a));
    entryColumns[a] = static_cast<Index>(columns - d - 1 + a);
  }
  values[d] = 1;
}

}  // namespace somicage
