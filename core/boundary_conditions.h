// Boundary conditions of the corotational Somigliana deformer: face and vertex rotations and traction scales
// (paper section 4.4, Eqs. 12-15), as settled in docs/method.md.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "cage.h"
#include "deformer.h"

namespace somicage {

// y = scale * rotation * x + translation.
struct Similarity {
  Eigen::MatrixXd rotation;  // d by d, det = +1
  double scale = 1.0;
  Eigen::VectorXd translation;  // d
};

// Least-squares similarity from `from` to `to` (both #V by d, equal weights), reflection-safe (Umeyama 1991).
Similarity fitSimilarity(const Eigen::MatrixXd& from, const Eigen::MatrixXd& to);

// The rotation factor of the polar decomposition of a d by d matrix (det +1 even if det M < 0).
Eigen::MatrixXd closestRotation(const Eigen::MatrixXd& M);

// Unit vertex normals (#V by d): normalised sum of incident face normals weighted by that pose's face areas
// (3D) or edge lengths (2D).
Eigen::MatrixXd vertexNormals(const Cage& cage, const Eigen::MatrixXd& vertices);

// Per-face spread of the vertex normals (#F): 3D, the signed solid angle of the face's three vertex normals
// (van Oosterom-Strackee, 0 when they are equal, > 0 on convex patches); 2D, the signed angle from the normal at
// the edge's first vertex to the one at its second (> 0 where they diverge).
Eigen::VectorXd normalSpread(const Cage& cage, const Eigen::MatrixXd& unitVertexNormals);

struct BoundaryConditions {
  std::vector<Eigen::MatrixXd> faceRotations;    // R_j (#F of d by d)
  std::vector<Eigen::MatrixXd> vertexRotations;  // R_i (#V of d by d)
  Eigen::VectorXd tangentialStretch;             // lambda_j (#F)
  Eigen::VectorXd normalStretch;                 // eta_j (#F)
  Eigen::VectorXd tractionScales;                // s_j of Eq. 14, after Eq. 15 when enabled (#F)
  Similarity global;                             // the Umeyama fit of the whole cage
};

// Rotations, stretches and traction scales for the posed cage (#V by d) and the parameters.
BoundaryConditions computeBoundaryConditions(const Cage& restCage, const Eigen::MatrixXd& posedVertices,
                                             const DeformParams& params);

}  // namespace somicage
