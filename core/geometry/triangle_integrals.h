// Exact integrals over one flat triangle of the kernels that 3D Somigliana coordinates need
// (paper Eqs. 3, 4, 8; derivation in shared docs/closed-form.md, section 4).
//
// Conventions: triangle p0, p1, p2 counter-clockwise about its outward unit normal n; query point x;
// r = y - x for y on the triangle, R = |r|; phi_k is the hat function of corner k.
// All integrals are nu-independent; somigliana_kernels.h combines them into T_i and K_j for a given nu.
#pragma once

#include <Eigen/Core>

#include "base/dual_number.h"
#include "base/simd_pack.h"
#include "geometry/triangle_integrals_kernel.h"

namespace somicage {

// The results for one (query point, triangle) pair, in world coordinates.
struct TriangleIntegrals {
  double S = 0;           // int 1/R
  Eigen::Matrix3d M;      // int r r^T / R^3 (symmetric)
  double D[3];            // int phi_k (n.r) / R^3
  Eigen::Vector3d V[3];   // int phi_k r / R^3
  Eigen::Matrix3d B[3];   // int phi_k (n.r) r r^T / R^5 (symmetric)
  double solidAngle = 0;  // W = int h / R^3 with h = n.(x - p0): signed solid angle, -2pi just inside the face
};

// Per-face data computed once per cage face (local frame, edge directions, hat gradients).
// Edge e runs from corner e to corner e+1 (mod 3); all 2D quantities are in the local (u, v) coordinates.
struct TriangleFrame {
  Eigen::Vector3d origin, u, v, n;    // p0 and the orthonormal frame [u v n], u along p1 - p0
  double q[3][2];                     // local 2D corners
  double ell[3], tau[3][2], m[3][2];  // edge lengths, unit directions, outward in-plane normals
  double grad[3][2];                  // in-plane gradients of the hat functions: -m_{k+1} ell_{k+1} / (2A)
  double twiceArea = 0;               // 2A = |(p1 - p0) x (p2 - p0)|
  bool degenerate = false;            // zero-area faces contribute nothing

  // Derived per-face constants, so that the per-point work has few divisions.
  double ellOverTwiceArea[3];  // ell_e / (2A): the barycentric coordinate of the projection is t_{k+1} times this
  double mm[3][3];             // m_e m_e^T as (xx, xy, yy)
  double tm[3][3];             // sym(tau_e m_e^T) as (xx, xy, yy)
  double tt[3][3];             // tau_e tau_e^T as (xx, xy, yy)
  double mDotGrad[3][3];       // [k][e] = m_e . grad_k

  PortableTriangleFrame kernel;  // all of the above as plain arrays: what integrateTriangle (and CUDA) evaluates
};

// Builds the frame of the triangle p0 p1 p2 (counter-clockwise about the outward normal). A face whose area is
// zero to rounding (2A <= 16 eps max|edge|^2, or not finite) is marked degenerate and gets zero axes.
TriangleFrame makeTriangleFrame(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2);

// Closed form (docs/closed-form.md section 4), double precision, valid for any x not on the triangle: the Eigen
// face of integrateTrianglePortable (triangle_integrals_kernel.h), the one implementation, shared with CUDA.
// No heap allocation; about 1 atan2, 3 sqrt and 3 log1p per call. A degenerate frame gives all zeros.
// Accuracy: near-round-off where the integrals are well conditioned, about eps * diam / delta at a distance delta
// from an edge or vertex (the conditioning of the integrals themselves), and for a face D diameters away an
// error that is small in absolute terms but grows like eps (D / h_min)^3 relative to the face's own integrals.
void integrateTriangle(const TriangleFrame& frame, const Eigen::Vector3d& x, TriangleIntegrals& out);

// The same in dual numbers seeded with the unit vectors: every output carries its exact gradient with respect to x
// (coordinate_gradients.h). A function of its own, not the template, so that it is dispatched (cpu_dispatch.h).
void integrateTriangle(const TriangleFrame& frame, const dual::Dual<3> x[3],
                       PortableTriangleIntegralsOf<dual::Dual<3>>& out);
#if SOMICAGE_SIMD_PACKS
// The same for simd::kLanes points at once (dual numbers of packs; Green's and BEM's gradients).
void integrateTriangle(const TriangleFrame& frame, const dual::Dual<3, simd::Pack> x[3],
                       PortableTriangleIntegralsOf<dual::Dual<3, simd::Pack>>& out);
#endif

// The limit of integrateTriangle as x tends to the point `onFace` of the face (strictly inside it; it is projected
// onto the face's plane) from the inside of the cage, h -> 0-: the closed form with h = -0 (exact, no quadrature).
// The integrals are finite there (D, B weakly singular, V in-plane a Cauchy principal value) and carry the jump of
// the double layer: solidAngle = -2pi, D_k = 2pi phi_k(onFace), B_k = (2pi/3) phi_k(onFace) I, S and M continuous.
void integrateTriangleInteriorLimit(const TriangleFrame& frame, const Eigen::Vector3d& onFace, TriangleIntegrals& out);

}  // namespace somicage
