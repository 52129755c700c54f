// The Kelvin layer integrals a boundary element solution needs at a point: the Somigliana coordinates' nu-independent
// vertex terms (somigliana_coordinates.h, same layout) and, per face, the full moment M_j = int psi_j r r^T / r^d
// instead of its product q_j = M_j n_j with the rest normal, because an elastic traction t_j may point anywhere:
//   K_j t_j = k1(nu) S_j t_j + k2(nu) M_j t_j                                  (docs/method.md, mu = 1)
// Points may also sit on the cage, at a point strictly inside one of its faces, where the integrals are taken in the
// limit from the inside of the cage (integrateTriangleInteriorLimit / integrateEdgeInteriorLimit): that limit holds
// the jump term of the double layer, so sum_i T_i = I there as it does inside (paper Eq. 9).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "base/progress.h"
#include "coordinates/somigliana_coordinates.h"
#include "deform/coordinate_layout.h"
#include "geometry/cage.h"

namespace somicage {

// Per-face term count: S, then M (3D: xx, yy, zz, xy, xz, yz; 2D: xx, yy, xy).
constexpr int bemFaceTermCount(int dim) { return 1 + dim * (dim + 1) / 2; }

// The integrals' columns (coordinate_layout.h): vertexTermCount(dim) per vertex, bemFaceTermCount(dim) per face, no
// tail (the BEM method's C adds its own, bem_method.cpp).
CoordinateLayout bemLayerLayout(int dim, int numVertices, int numFaces);

struct BemLayerIntegrals {
  int dim = 3;
  CoordinateLayout layout;  // bemLayerLayout
  RowMatrixXd values;       // #P by layout.mainColumns()
  Eigen::VectorXd winding;  // generalised winding number per point: 1 inside and in a face's interior limit

  // T_i(x_p) at nu (d by d), and K_j(x_p) = k1 S_j I + k2 M_j at nu (d by d).
  Eigen::MatrixXd vertexCoordinate(int p, int i, double nu) const;
  Eigen::MatrixXd faceKelvinlet(int p, int j, double nu) const;
};

// K_j at nu from its bemFaceTermCount(dim) stored terms.
Eigen::MatrixXd assembleFaceKelvinlet(const double* terms, int dim, double nu);

// Integrates every point (#P by d). onFace is empty, or #P face indices: onFace[p] >= 0 says that point p lies
// strictly inside that face and takes its integrals over it in the limit from inside. Closed forms only. threads = 0:
// the OpenMP default; the result does not depend on it. Throws Cancelled when progress returns false.
BemLayerIntegrals integrateBemLayers(const Cage& cage, const Eigen::MatrixXd& points, const std::vector<int>& onFace,
                                     int threads = 0, const ProgressCallback& progress = noProgress);

}  // namespace somicage
