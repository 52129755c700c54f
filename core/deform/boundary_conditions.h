// Boundary conditions of the corotational Somigliana deformer: face and vertex rotations and traction scales
// (paper section 4.4, Eqs. 12-15), as settled in docs/method.md.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "deform/deform_params.h"
#include "geometry/cage.h"

namespace somicage {

// y = scale * rotation * x + translation.
struct Similarity {
  Eigen::MatrixXd rotation;  // d by d, det = +1
  double scale = 1.0;
  Eigen::VectorXd translation;  // d
};

// Least-squares similarity from `from` to `to` (both #V by d, equal weights), reflection-safe (Umeyama 1991).
Similarity fitSimilarity(const Eigen::MatrixXd& from, const Eigen::MatrixXd& to);

// y = A x + b.
struct AffineMap {
  Eigen::MatrixXd linear;       // A, d by d
  Eigen::VectorXd translation;  // b, d
};

// Least-squares affine map from `from` to `to` (both #V by d, equal weights; from's points span d dimensions).
AffineMap fitAffine(const Eigen::MatrixXd& from, const Eigen::MatrixXd& to);

// The rotation factor of the polar decomposition of a d by d matrix (det +1 even if det M < 0).
Eigen::MatrixXd closestRotation(const Eigen::MatrixXd& M);

// The weight of face j at its k-th vertex (#F by d) in averages over a vertex's faces: Area, the face's area (3D)
// or length (2D) in that pose; Angle, its corner angle at the vertex (3D) or 1 (2D, where a straight run of edges
// then gives the same normal however it is split).
Eigen::MatrixXd cornerWeights(const Cage& cage, const Eigen::MatrixXd& vertices, NormalWeights weights);

// Unit vertex normals (#V by d): normalised sum of incident face normals with cornerWeights in that pose.
Eigen::MatrixXd vertexNormals(const Cage& cage, const Eigen::MatrixXd& vertices,
                              NormalWeights weights = NormalWeights::Area);

// Per-face spread of the vertex normals (#F): 3D, the solid angle of the face's three vertex normals
// (van Oosterom-Strackee; signed: 0 when they are equal, > 0 on convex patches; unsigned: its absolute value
// where the normals' triangle is under a hemisphere, as the authors' code measures it); 2D, the signed angle from
// the normal at the edge's first vertex to the one at its second (> 0 where they diverge), signed either way.
Eigen::VectorXd normalSpread(const Cage& cage, const Eigen::MatrixXd& unitVertexNormals, bool signedAngle = true);

// Each face's planar polygon (#F): faces that share an edge (2D: a vertex) and whose rest unit normals agree to
// 1e-12 (1 - n.n') lie in one plane and get one id, the smallest face index of the polygon (bulging: polygon).
std::vector<int> planarPolygons(const Cage& cage);

// The signed volume (3D) or area (2D) face j sweeps from its place in `from` to its place in `to` (#V by d
// each), > 0 when it moves along its outward normal. 3D: the closed prism of the face in `to`, the face in `from`
// reversed, and three side quads, each split along the diagonal from its first corner (as the authors' code).
double sweptMeasure(const Cage& cage, const Eigen::MatrixXd& from, const Eigen::MatrixXd& to, int j);

struct BoundaryConditions {
  std::vector<Eigen::MatrixXd> faceRotations;    // R_j (#F of d by d)
  std::vector<Eigen::MatrixXd> vertexRotations;  // R_i (#V of d by d)
  Eigen::VectorXd tangentialStretch;             // lambda_j (#F)
  Eigen::VectorXd normalStretch;                 // eta_j (#F)
  Eigen::VectorXd tractionScales;                // s_j of Eq. 14, after Eq. 15 when enabled (#F)
  Similarity global;                             // the Umeyama fit of the whole cage
  // The affine variant (VariantKind::Affine): the best-fit affine map A = R S (every rotation above is R) and the
  // stress sigma(S) = 2 S + lambda tr(S) I (mu = 1, lambda = 2 nu / (1 - 2 nu)). Its face tractions are
  // R sigma n_j + tractionScales(j) R n_j: the scales hold only bulging's share, (2 + lambda)(eta_j - lambda_j).
  AffineMap affine;
  Eigen::MatrixXd stress;
  // The stable variant (VariantKind::Stable): a second traction globalScales(j) R n_j with R the global rotation,
  // besides tractionScales(j) R_j n_j. Empty otherwise.
  Eigen::VectorXd globalScales;
};

// Rotations, stretches and traction scales for the posed cage (#V by d) and the parameters.
BoundaryConditions computeBoundaryConditions(const Cage& restCage, const Eigen::MatrixXd& posedVertices,
                                             const DeformParams& params);

}  // namespace somicage
