// Exact integrals over one flat triangle of the kernels that 3D Somigliana coordinates need
// (paper Eqs. 3, 4, 8; derivation in shared docs/closed-form.md, section 4).
//
// Conventions: triangle p0, p1, p2 counter-clockwise about its outward unit normal n; query point x;
// r = y - x for y on the triangle, R = |r|; phi_k is the hat function of corner k.
// All integrals are nu-independent; somigliana_kernels.h combines them into T_i and K_j for a given nu.
#pragma once

#include <Eigen/Core>

namespace somicage {

// The results for one (query point, triangle) pair, in world coordinates.
struct TriangleIntegrals {
  double S = 0;             // int 1/R
  Eigen::Matrix3d M;        // int r r^T / R^3 (symmetric)
  double D[3];              // int phi_k (n.r) / R^3
  Eigen::Vector3d V[3];     // int phi_k r / R^3
  Eigen::Matrix3d B[3];     // int phi_k (n.r) r r^T / R^5 (symmetric)
  double solidAngle = 0;    // W = int h / R^3 with h = n.(x - p0): signed solid angle, -2pi just inside the face
};

// Per-face data computed once per cage face (local frame, edge directions, hat gradients).
struct TriangleFrame {
  Eigen::Vector3d origin, u, v, n;  // p0 and the orthonormal frame [u v n], u along p1 - p0
  double q[3][2];                   // local 2D corners
  double ell[3], tau[3][2], m[3][2];  // edge lengths, unit directions, outward in-plane normals
  double grad[3][2];                // in-plane gradients of the hat functions
  double twiceArea = 0;
  bool degenerate = false;          // zero-area faces contribute nothing
};

TriangleFrame makeTriangleFrame(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2);

// Closed form (docs/closed-form.md section 4), double precision, valid for any x not on the triangle.
void integrateTriangle(const TriangleFrame& frame, const Eigen::Vector3d& x, TriangleIntegrals& out);

}  // namespace somicage
