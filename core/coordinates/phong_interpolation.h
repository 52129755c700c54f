// Phong deformation (James 2020, "Phong Deformation: a better C0 interpolant for embedded deformation"; the
// disabled DeformerType::PHONG path of the authors' CageModeler) over a volume mesh (volume_mesh.h):
//   F_t = D_s D_m^-1                                    per simplex (the piecewise-linear map's gradient)
//   F_v = sum_t w_vt F_t / sum_t w_vt                   per vertex, over its incident simplices
//   phi(X) = 1/2 sum_i l_i x_i + 1/2 sum_i l_i (x_i + F_i (X - X_i))   in a simplex with barycentrics l_i
// The weights are the authors': r_t = c_t - X_v (c_t the simplex's rest centroid), r^_t = r_t / |r_t|, solve
// (I + sum_t r^_t r^_t^T) a = -sum_t r^_t, w_vt = (1 + a . r^_t) / |r_t|. phi is continuous across faces (both
// sides interpolate the same vertices' x_i and F_i), quadratic in each simplex, and its J jumps across faces.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/volume_mesh.h"

namespace somicage {

// Per vertex v, its incident simplices simplex[start[v] .. start[v + 1]) with their weights, normalised to sum 1.
struct PhongVertexWeights {
  std::vector<int> start, simplex;
  std::vector<double> weight;
};
PhongVertexWeights phongVertexWeights(const VolumeMesh& rest);

// F_t for every simplex from the deformed positions (#N by d) of its vertices: sum_k x_k g_k^T.
std::vector<Eigen::MatrixXd> simplexGradients(const VolumeMesh& rest, const std::vector<Eigen::MatrixXd>& gradients,
                                              const Eigen::MatrixXd& positions);
// F_v for every vertex (#N matrices d by d).
std::vector<Eigen::MatrixXd> vertexGradients(const PhongVertexWeights& weights,
                                             const std::vector<Eigen::MatrixXd>& simplexF);

}  // namespace somicage
