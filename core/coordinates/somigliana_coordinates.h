// Somigliana coordinates T_i(x), K_j(x) (paper Eq. 8) of a set of points inside a cage, stored as
// nu-independent integrals so that a change of the Poisson ratio never integrates again (paper section 5).
//
// With a = 1/(2^{d-1} pi) and mu = 1 (docs/method.md):
//   T_i = alpha(nu) (D_i I + A_i) + beta(nu) B_i,        alpha = a(1-2nu)/(2(1-nu)),  beta = d a/(2(1-nu))
//   K_j n_j = k1(nu) S_j n_j + k2(nu) q_j,                k1 = a(3-4nu)/(4(1-nu)),     k2 = a/(4(1-nu))
// where, with r = y - x, phi_i the hat of vertex i and psi_j the indicator of face j,
//   D_i = int phi_i (n.r)/r^d,  A_i = int phi_i (n r^T - r n^T)/r^d,  B_i = int phi_i (n.r) r r^T/r^{d+2},
//   S_j = int psi_j 1/r (3D) or int psi_j ln(1/r) (2D),  q_j = (int psi_j r r^T/r^d) n_j.
// nu = +-infinity is the limit alpha = k1 = a, beta = k2 = 0.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "base/progress.h"
#include "coordinates/somigliana_row_portable.h"
#include "deform/coordinate_layout.h"
#include "geometry/cage.h"
#include "geometry/edge_integrals.h"
#include "geometry/integration_options.h"
#include "geometry/triangle_integrals.h"

namespace somicage {

// Per-vertex and per-face term counts in a row of C (coordinate_layout.h).
//   3D vertex (10): D, omega (3) with A w = omega x w, B (xx, yy, zz, xy, xz, yz);  face (4): S, q (3).
//   2D vertex (5):  D, A01 (A = [[0, A01], [-A01, 0]]), B (xx, yy, xy);             face (3): S, q (2).
constexpr int vertexTermCount(int dim) { return 1 + dim * dim; }
constexpr int faceTermCount(int dim) { return 1 + dim; }
// Per point, for the affine variant's tractions M_j sigma n_j with one symmetric sigma (somigliana_method.cpp): the
// sums P_a,(bc) = sum_j (M_j)_ab (n_j)_c + (M_j)_ac (n_j)_b (b != c; once for b = c) over the faces, for every
// output a and pair bc in B's order (3D: xx, yy, zz, xy, xz, yz; 2D: xx, yy, xy), output-major. 18 (3D) or 6 (2D).
constexpr int affineTermCount(int dim) { return dim * dim * (dim + 1) / 2; }

// Numbers per point after the vertex and face blocks of C: [per-vertex sums | affine terms | x | 1].
constexpr int tailColumnCount(int dim) { return vertexTermCount(dim) + affineTermCount(dim) + dim + 1; }

struct NuCoefficients {
  double alpha, beta, k1, k2;
};
NuCoefficients nuCoefficients(int dim, double nu);

// T_i at nu (d by d) from its vertexTermCount(dim) stored terms.
Eigen::MatrixXd assembleVertexCoordinate(const double* terms, int dim, double nu);

// max |sum_i T_i - I| at nu = 0, from the sums over i of the vertex terms (vertexTermCount(dim) numbers).
double unityResidualOfSums(const double* termSums, int dim);

// The Somigliana layout of C: these terms per vertex and per face, then the tail: the per-point sums over the
// vertices of the vertex terms, the affine terms (the integrator's tailIntegrals), [x | 1] (somigliana_method.cpp).
CoordinateLayout somiglianaLayout(int dim, int numVertices, int numFaces);

// The terms of vertex i gathered from a row laid out as C (vertexTermCount(dim) numbers into terms).
void gatherVertexTerms(const CoordinateLayout& layout, const double* row, int i, double* terms);

struct SomiglianaCoordinates {
  int dim = 3;
  CoordinateLayout layout;  // somiglianaLayout
  // #P by layout.mainColumns(), in the layout of C (the affine terms are the deformer's only).
  RowMatrixXd values;
  // Unit outward normals n_j of the rest cage (#F by d), which K_j is applied to.
  Eigen::MatrixXd restNormals;
  // Generalised winding number of each point with respect to the cage: 1 inside, 0 outside (#P).
  Eigen::VectorXd winding;

  int numPoints() const { return static_cast<int>(values.rows()); }

  // Eq. 8a at nu: T_i(x_p), d by d.
  Eigen::MatrixXd vertexCoordinate(int p, int i, double nu) const;
  // Eq. 8b applied to the rest normal: K_j(x_p) n_j, a d-vector.
  Eigen::VectorXd faceCoordinateTimesNormal(int p, int j, double nu) const;
  // sum_i T_i(x_p) at nu; the identity for points strictly inside (Eq. 9).
  Eigen::MatrixXd vertexCoordinateSum(int p, double nu) const;
};

// Adds one triangle's (3D) or edge's (2D) integrals to the vertex terms of a point's row laid out as `layout`
// (vertexTermCount(dim) terms per vertex, as above): the corners' hat-function integrals, with the antisymmetric
// part as omega = V x n. Face terms are the caller's (Somigliana's and BEM's differ).
void addVertexTerms(const TriangleIntegrals& integrals, const Eigen::Vector3d& n, const int corners[3],
                    const CoordinateLayout& layout, double* row);
void addVertexTerms(const EdgeIntegrals& integrals, const int ends[2], const CoordinateLayout& layout, double* row);

// The frames of a 3D cage's faces (makeTriangleFrame), one per face.
std::vector<TriangleFrame> cageFrames(const Cage& cage);

// The faces of a 3D cage as the row kernels take them (cuda/somigliana_row_portable.h), from its frames (one per face).
std::vector<PortableFace> portableFaces(const Cage& cage, const std::vector<TriangleFrame>& frames);

// Integrates the coordinates of every point (#P by d) against the cage. Points on the cage are singular.
// Throws somicage::Cancelled when progress returns false. The result does not depend on the thread count.
SomiglianaCoordinates computeSomiglianaCoordinates(const Cage& cage, const Eigen::MatrixXd& points,
                                                   const IntegrationOptions& options = {},
                                                   const ProgressCallback& progress = noProgress);

// The integration behind computeSomiglianaCoordinates on the CPU (a RowIntegrator), streaming rows to a sink
// instead of storing them (so a deformer can build its own storage without a second copy of the coordinates).
void integrateSomiglianaCoordinates(const Cage& cage, const Eigen::MatrixXd& points, const IntegrationOptions& options,
                                    const ProgressCallback& progress, const CoordinateRowSink& sink);

// A group of points' rows where the CPU's pack kernel left them (somigliana_row_kernels.h): entry k of point first + l
// (l < count) at rows[k * lanes + l], its winding number at winding[l]; lanes from count on repeat the last point.
struct CoordinateRowGroup {
  int first = 0, count = 0, lanes = 0;
  const double* rows = nullptr;
  const double* winding = nullptr;
};
// Called from worker threads, once per group; the buffers are reused after it returns.
using CoordinateGroupSink = std::function<void(const CoordinateRowGroup& group)>;

// Hands a group's rows to a row sink one point at a time (each row contiguous: a copy of the group's), for writers
// that take rows one by one.
void forEachRowOfGroup(const CoordinateRowGroup& group, int columns, const CoordinateRowSink& sink);

// integrateSomiglianaCoordinates for a writer that takes a group of points at once, as the kernel left them: a 3D
// cage's closed form in SIMD packs. Elsewhere (2D, the Gauss rule, scalarKernel, a build without packs) it calls
// nothing and returns false.
bool integrateSomiglianaCoordinateGroups(const Cage& cage, const Eigen::MatrixXd& points,
                                         const IntegrationOptions& options, const ProgressCallback& progress,
                                         const CoordinateGroupSink& sink);

// Partition-of-unity residual of each point: the largest entry of |sum_i T_i(x) - I| at nu = 0 (#P).
Eigen::VectorXd partitionOfUnityResidual(const SomiglianaCoordinates& coords);

}  // namespace somicage
