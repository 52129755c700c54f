#include "deform/boundary_conditions.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "base/errors.h"

namespace somicage {

namespace {
// Every SVD here is of a square d x d matrix, for which JacobiSVD skips its QR preconditioner: leaving the
// preconditioner out gives the same factors and compiles this file a third faster (CI time).
using SquareSvd = Eigen::JacobiSVD<Eigen::MatrixXd, Eigen::NoQRPreconditioner>;
// The stable variant's bound on a face's damped non-uniform volumetric traction (stabiliseVolumetricTractions):
// 0.5 is the largest of those measured (docs/engine.md) that leaves CACTUS's paper pose without fold-overs.
constexpr double kStableLimit = 0.5;
}  // namespace

Similarity fitSimilarity(const Eigen::MatrixXd& from, const Eigen::MatrixXd& to) {
  const int d = static_cast<int>(from.cols());
  const double n = static_cast<double>(from.rows());
  const Eigen::RowVectorXd meanFrom = from.colwise().mean(), meanTo = to.colwise().mean();
  const Eigen::MatrixXd X = from.rowwise() - meanFrom, Y = to.rowwise() - meanTo;
  const Eigen::MatrixXd covariance = Y.transpose() * X / n;
  SquareSvd svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::VectorXd signs = Eigen::VectorXd::Ones(d);
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0) signs(d - 1) = -1;  // no reflections
  Similarity fit;
  fit.rotation = svd.matrixU() * signs.asDiagonal() * svd.matrixV().transpose();
  const double varianceFrom = X.squaredNorm() / n;
  fit.scale = varianceFrom > 0 ? svd.singularValues().dot(signs) / varianceFrom : 1.0;
  fit.translation = meanTo.transpose() - fit.scale * fit.rotation * meanFrom.transpose();
  return fit;
}

AffineMap fitAffine(const Eigen::MatrixXd& from, const Eigen::MatrixXd& to) {
  const Eigen::RowVectorXd meanFrom = from.colwise().mean(), meanTo = to.colwise().mean();
  const Eigen::MatrixXd X = from.rowwise() - meanFrom, Y = to.rowwise() - meanTo;
  AffineMap fit;
  // Normal equations A (X^T X) = Y^T X; X^T X is d by d and positive definite for a cage with volume.
  fit.linear = (X.transpose() * X).ldlt().solve(X.transpose() * Y).transpose();
  fit.translation = meanTo.transpose() - fit.linear * meanFrom.transpose();
  return fit;
}

Eigen::MatrixXd closestRotation(const Eigen::MatrixXd& M) {
  SquareSvd svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::MatrixXd U = svd.matrixU();
  if ((U * svd.matrixV().transpose()).determinant() < 0) U.col(U.cols() - 1) *= -1;
  return U * svd.matrixV().transpose();
}

Eigen::MatrixXd cornerWeights(const Cage& cage, const Eigen::MatrixXd& vertices, NormalWeights weights) {
  const int d = cage.dim();
  if (weights == NormalWeights::Area) return faceAreas(cage, vertices).replicate(1, d);
  if (d == 2) return Eigen::MatrixXd::Ones(cage.numFaces(), 2);
  Eigen::MatrixXd angles(cage.numFaces(), 3);
  for (int j = 0; j < cage.numFaces(); ++j)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d v = vertices.row(cage.faces(j, k));
      const Eigen::Vector3d a = Eigen::Vector3d(vertices.row(cage.faces(j, (k + 1) % 3))) - v;
      const Eigen::Vector3d b = Eigen::Vector3d(vertices.row(cage.faces(j, (k + 2) % 3))) - v;
      angles(j, k) = std::atan2(a.cross(b).norm(), a.dot(b));  // accurate for small and near-pi angles
    }
  return angles;
}

Eigen::MatrixXd vertexNormals(const Cage& cage, const Eigen::MatrixXd& vertices, NormalWeights weights) {
  // With area weights, summing the unit normal times the area is summing the unnormalised normals.
  const Eigen::MatrixXd N = faceNormals(cage, vertices);
  const Eigen::MatrixXd W = cornerWeights(cage, vertices, weights);
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(cage.numVertices(), cage.dim());
  for (int j = 0; j < cage.numFaces(); ++j)
    for (int k = 0; k < cage.dim(); ++k) sum.row(cage.faces(j, k)) += W(j, k) * N.row(j);
  // Row by row: rowwise().normalize() divides by zero at a vertex whose faces all collapsed (normal 0 then).
  for (int i = 0; i < sum.rows(); ++i) sum.row(i).normalize();
  return sum;
}

Eigen::VectorXd normalSpread(const Cage& cage, const Eigen::MatrixXd& n, bool signedAngle) {
  Eigen::VectorXd spread(cage.numFaces());
  for (int j = 0; j < cage.numFaces(); ++j) {
    if (cage.dim() == 3) {
      const Eigen::Vector3d n1 = n.row(cage.faces(j, 0)), n2 = n.row(cage.faces(j, 1)), n3 = n.row(cage.faces(j, 2));
      const double det = n1.dot(n2.cross(n3));
      spread(j) = 2 * std::atan2(signedAngle ? det : std::abs(det), 1 + n1.dot(n2) + n2.dot(n3) + n3.dot(n1));
    } else {
      const Eigen::Vector2d na = n.row(cage.faces(j, 0)), nb = n.row(cage.faces(j, 1));
      spread(j) = std::atan2(na.x() * nb.y() - na.y() * nb.x(), na.dot(nb));
    }
  }
  return spread;
}

std::vector<int> planarPolygons(const Cage& cage) {
  const int m = cage.numFaces(), d = cage.dim();
  const Eigen::MatrixXd normals = faceNormals(cage, cage.vertices);
  std::vector<int> parent(static_cast<std::size_t>(m));
  for (int j = 0; j < m; ++j) parent[static_cast<std::size_t>(j)] = j;
  auto root = [&](int j) {
    while (parent[static_cast<std::size_t>(j)] != j) j = parent[static_cast<std::size_t>(j)];
    return j;
  };
  // The faces at each edge (3D: its sorted vertex pair) or vertex (2D).
  std::map<std::pair<int, int>, std::vector<int>> ridges;
  for (int j = 0; j < m; ++j)
    for (int k = 0; k < d; ++k) {
      const int a = cage.faces(j, k), b = d == 3 ? cage.faces(j, (k + 1) % 3) : a;
      ridges[{std::min(a, b), std::max(a, b)}].push_back(j);
    }
  for (const auto& [ridge, faces] : ridges)
    for (std::size_t k = 1; k < faces.size(); ++k) {
      const int f = faces.front(), g = faces[k];
      if (1 - normals.row(f).dot(normals.row(g)) > 1e-12) continue;
      const int a = root(f), b = root(g);
      parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);  // the smaller index is the root
    }
  std::vector<int> polygon(static_cast<std::size_t>(m));
  for (int j = 0; j < m; ++j) polygon[static_cast<std::size_t>(j)] = root(j);
  return polygon;
}

double sweptMeasure(const Cage& cage, const Eigen::MatrixXd& from, const Eigen::MatrixXd& to, int j) {
  if (cage.dim() == 2) {  // the quad (a, b, b_from, a_from), counter-clockwise when the edge moved outward
    const Eigen::Vector2d a = to.row(cage.faces(j, 0)), b = to.row(cage.faces(j, 1));
    const Eigen::Vector2d af = from.row(cage.faces(j, 0)), bf = from.row(cage.faces(j, 1));
    return signedTriangleArea(a, b, bf) + signedTriangleArea(a, bf, af);
  }
  Eigen::Vector3d v[3], r[3];
  for (int k = 0; k < 3; ++k) {
    v[k] = to.row(cage.faces(j, k));
    r[k] = from.row(cage.faces(j, k));
  }
  const Eigen::Vector3d o = (v[0] + v[1] + v[2]) / 3;  // the prism is closed: any origin, a near one for precision
  auto triangle = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    return signedTetrahedronVolume(o, a, b, c);
  };
  auto quad = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  const Eigen::Vector3d& e) { return triangle(a, b, c) + triangle(c, e, a); };
  return triangle(v[0], v[1], v[2]) + triangle(r[2], r[1], r[0]) + quad(v[2], v[1], r[1], r[2]) +
         quad(v[0], v[2], r[2], r[0]) + quad(v[1], v[0], r[0], r[1]);
}

namespace {

double wrapAngle(double angle) {  // to (-pi, pi]
  angle = std::remainder(angle, 2 * M_PI);
  return angle <= -M_PI ? angle + 2 * M_PI : angle;
}

Eigen::Matrix2d rotation2d(double angle) {
  Eigen::Matrix2d R;
  R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return R;
}

struct FaceMap {
  Eigen::MatrixXd rotation;
  double stretch;
};

// Local variant: the rotation and mean in-plane stretch of the map from the rest face to the posed face.
FaceMap localFaceMap(const Cage& cage, const Eigen::MatrixXd& posed, int j) {
  const Eigen::MatrixXd& rest = cage.vertices;
  if (cage.dim() == 2) {
    const Eigen::Vector2d e = rest.row(cage.faces(j, 1)) - rest.row(cage.faces(j, 0));
    const Eigen::Vector2d f = posed.row(cage.faces(j, 1)) - posed.row(cage.faces(j, 0));
    const double angle = std::atan2(e.x() * f.y() - e.y() * f.x(), e.dot(f));
    return {rotation2d(angle), f.norm() / e.norm()};
  }
  auto edges = [&](const Eigen::MatrixXd& V, Eigen::Matrix3d& frame) {
    const Eigen::Vector3d v0 = V.row(cage.faces(j, 0));
    const Eigen::Vector3d e1 = Eigen::Vector3d(V.row(cage.faces(j, 1))) - v0;
    const Eigen::Vector3d e2 = Eigen::Vector3d(V.row(cage.faces(j, 2))) - v0;
    frame << e1, e2, e1.cross(e2).normalized();
  };
  Eigen::Matrix3d E, F;
  edges(rest, E);
  edges(posed, F);
  // F_j = [f1 f2 n~][e1 e2 n]^-1 (docs/method.md, local variant).
  const Eigen::Matrix3d faceMap = F * E.inverse();
  const Eigen::Matrix2d G = E.leftCols<2>().transpose() * E.leftCols<2>();
  const Eigen::Matrix2d Gposed = F.leftCols<2>().transpose() * F.leftCols<2>();
  const double areaRatio =
      E.col(0).cross(E.col(1)).norm() > 0 ? F.col(0).cross(F.col(1)).norm() / E.col(0).cross(E.col(1)).norm() : 1.0;
  // Mean of the two singular values: (s1 + s2)^2 = tr(G~ G^-1) + 2 A~/A.
  const double stretch = 0.5 * std::sqrt((Gposed * G.inverse()).trace() + 2 * areaRatio);
  return {closestRotation(faceMap), stretch};
}

// R_j(t) = R exp(t log(R^T R_local)) (docs/method.md, blend).
Eigen::MatrixXd blendRotation(const Eigen::MatrixXd& global, const Eigen::MatrixXd& local, double t) {
  if (t == 0) return global;
  if (t == 1) return local;
  if (global.rows() == 2) {
    const Eigen::MatrixXd relative = global.transpose() * local;
    return global * rotation2d(t * std::atan2(relative(1, 0), relative(0, 0)));
  }
  const Eigen::AngleAxisd relative(Eigen::Matrix3d(global.transpose() * local));
  return global * Eigen::AngleAxisd(t * relative.angle(), relative.axis()).toRotationMatrix();
}

// The stable variant (docs/engine.md, "The stable variant"): Eq. 14's volumetric share p_j = 2 v q_j along R_j n_j,
// v = nu/(1-2nu), q_j = eta_j + (d-1) lambda_j, is split into its rest-area mean along the global frame, pbar R n_j,
// a uniform pressure whose displacement stays bounded as nu -> 1/2, and the rest, p_j R_j n_j - pbar R n_j, which
// per-face rotations and stretches make grow with v until the mesh folds. Face j keeps a share r_j of its rest, the
// larger of r = 1 / (1 + v^2), a fixed function of nu, and 1 / (1 + (v delta_j / kStableLimit)^2), delta_j =
// |q_j R_j n_j - qbar R n_j| / qbar the rest's size next to the uniform pressure: a face whose rest is small (a mild
// pose) keeps most of it, and v r_j delta_j, what drives the fold-overs, stays at most kStableLimit / 2 wherever
// the fixed r does not keep more. At nu = 0 (v = 0) r_j = 1: the local variant as it is. These are the fully damped
// tractions (s = 1); the Somigliana frame blends them with the local variant's by the least s its fold check needs
// (fold_check.h), so where the local variant does not fold, the stable variant is local.
void stabiliseVolumetricTractions(BoundaryConditions& bc, const Eigen::VectorXd& restAreas, double volumetric,
                                  const Eigen::MatrixXd& restNormals, int d) {
  const int m = static_cast<int>(bc.tractionScales.size());
  Eigen::VectorXd q(m);
  for (int j = 0; j < m; ++j) q(j) = bc.normalStretch(j) + (d - 1) * bc.tangentialStretch(j);
  const double mean = restAreas.dot(q) / restAreas.sum();  // > 0: every stretch is >= 0
  const double fixed = 1 / (1 + volumetric * volumetric);
  bc.globalScales.resize(m);
  for (int j = 0; j < m; ++j) {
    const Eigen::VectorXd n = restNormals.row(j).transpose();
    const double delta =
        mean > 0 ? (q(j) * bc.faceRotations[j] * n - mean * bc.global.rotation * n).norm() / mean : 0;
    const double x = volumetric * delta / kStableLimit, r = std::max(fixed, 1 / (1 + x * x));
    bc.tractionScales(j) = 2 * bc.normalStretch(j) + r * 2 * volumetric * q(j);
    bc.globalScales(j) = (1 - r) * 2 * volumetric * mean;
  }
}

// The normal stretch's exponents (#F), eta_j = lambda_j exp(e_j): bulging (section 4.4) in the chosen convention
// (docs/engine.md, "Bulging conventions").
Eigen::VectorXd bulgingExponents(const Cage& rest, const Eigen::MatrixXd& posed, const Similarity& global,
                                 const DeformParams& params) {
  const int d = rest.dim(), m = rest.numFaces();
  Eigen::VectorXd exponents(m);
  if (params.bulging == Bulging::SweptVolume) {
    // The face's sweep from the rest cage moved by the best-fit similarity, over that cage's volume s^d V_0 (the
    // authors' code divides by V_0: the same at s = 1, and this keeps similarity invariance).
    const Eigen::MatrixXd registered =
        ((global.scale * rest.vertices * global.rotation.transpose()).rowwise() + global.translation.transpose());
    const double volume = std::pow(global.scale, d) * signedMeasure(rest.vertices, rest.faces);
    for (int j = 0; j < m; ++j)
      exponents(j) = params.gamma * params.gamma * sweptMeasure(rest, registered, posed, j) / volume;
    return exponents;
  }
  // Solid angle: the change of spread of the vertex normals over 4 pi (3D) or 2 pi (2D, wrapped).
  const bool reference = params.bulging == Bulging::Reference;
  const Eigen::VectorXd spreadRest = normalSpread(rest, vertexNormals(rest, rest.vertices, params.normals), !reference);
  const Eigen::VectorXd spreadPosed = normalSpread(rest, vertexNormals(rest, posed, params.normals), !reference);
  const double normalisation = std::pow(2.0, d - 1) * M_PI;
  const double scale = reference ? params.gamma * params.gamma : params.gamma;  // the authors' code squares gamma
  for (int j = 0; j < m; ++j) {
    double bulge = spreadPosed(j) - spreadRest(j);
    if (d == 2) bulge = wrapAngle(bulge);
    exponents(j) = scale * bulge / normalisation;
  }
  if (params.bulging == Bulging::Polygon) {
    // One exponent per planar polygon, its faces' sum: signed solid angles (2D: angles) of triangles that share an
    // edge add up to the solid angle of their union, so the sum does not depend on how the polygon is split.
    const std::vector<int> polygon = planarPolygons(rest);
    Eigen::VectorXd sums = Eigen::VectorXd::Zero(m);
    for (int j = 0; j < m; ++j) sums(polygon[static_cast<std::size_t>(j)]) += exponents(j);
    for (int j = 0; j < m; ++j) exponents(j) = sums(polygon[static_cast<std::size_t>(j)]);
  }
  return exponents;
}

}  // namespace

BoundaryConditions computeBoundaryConditions(const Cage& rest, const Eigen::MatrixXd& posed,
                                             const DeformParams& params) {
  const int d = rest.dim(), m = rest.numFaces(), n = rest.numVertices();
  SOMICAGE_ASSERT(posed.rows() == n && posed.cols() == d, "posed cage matches the rest cage");
  const double t = params.kind == VariantKind::Stable ? 1.0 : params.blend;  // stable: the local rotations

  BoundaryConditions bc;
  bc.global = fitSimilarity(rest.vertices, posed);
  bc.faceRotations.resize(m);
  bc.tangentialStretch.resize(m);
  // nu/(1-2nu) -> -1/2 as nu -> +-infinity.
  const double volumetric = std::isinf(params.nu) ? -0.5 : params.nu / (1 - 2 * params.nu);
  const bool affine = params.kind == VariantKind::Affine;
  if (affine) {
    bc.affine = fitAffine(rest.vertices, posed);
    const Eigen::MatrixXd R = closestRotation(bc.affine.linear);
    const Eigen::MatrixXd RtA = R.transpose() * bc.affine.linear;
    const Eigen::MatrixXd S = 0.5 * (RtA + RtA.transpose());  // symmetric up to round-off already
    bc.stress = 2 * S + 2 * volumetric * S.trace() * Eigen::MatrixXd::Identity(d, d);
    for (int j = 0; j < m; ++j) {
      bc.faceRotations[j] = R;
      bc.tangentialStretch(j) = S.trace() / d;  // bulging's reference stretch: the similarity's s when A = s R
    }
  }
  for (int j = 0; j < m && !affine; ++j) {
    if (t == 0) {
      bc.faceRotations[j] = bc.global.rotation;
      bc.tangentialStretch(j) = bc.global.scale;
    } else {
      const FaceMap local = localFaceMap(rest, posed, j);
      bc.faceRotations[j] = blendRotation(bc.global.rotation, local.rotation, t);
      bc.tangentialStretch(j) = t * local.stretch + (1 - t) * bc.global.scale;
    }
  }

  // Vertex rotations: polar rotation of the weighted sum of incident face rotations (rest areas or rest angles).
  const Eigen::VectorXd restAreas = faceAreas(rest, rest.vertices);
  const Eigen::MatrixXd restWeights = cornerWeights(rest, rest.vertices, params.normals);
  std::vector<Eigen::MatrixXd> sums(n, Eigen::MatrixXd::Zero(d, d));
  for (int j = 0; j < m; ++j)
    for (int k = 0; k < d; ++k) sums[rest.faces(j, k)] += restWeights(j, k) * bc.faceRotations[j];
  bc.vertexRotations.resize(n);
  for (int i = 0; i < n; ++i) bc.vertexRotations[i] = closestRotation(sums[i]);

  const Eigen::VectorXd exponents = bulgingExponents(rest, posed, bc.global, params);
  bc.normalStretch.resize(m);
  for (int j = 0; j < m; ++j) bc.normalStretch(j) = bc.tangentialStretch(j) * std::exp(exponents(j));

  // Eq. 14: s_j = 2 [eta + nu/(1-2nu) (eta + (d-1) lambda)]. The affine variant keeps what bulging adds to it,
  // s_j - s_j(eta = lambda) = 2 (1 + nu/(1-2nu)) (eta - lambda): sigma(S) n_j is the rest.
  bc.tractionScales.resize(m);
  for (int j = 0; j < m; ++j) {
    const double eta = bc.normalStretch(j), lambda = bc.tangentialStretch(j);
    bc.tractionScales(j) = affine ? 2 * (1 + volumetric) * (eta - lambda)
                                  : 2 * (eta + volumetric * (eta + (d - 1) * lambda));
  }
  const Eigen::MatrixXd restNormals = faceNormals(rest, rest.vertices);
  if (params.kind == VariantKind::Stable) stabiliseVolumetricTractions(bc, restAreas, volumetric, restNormals, d);

  // Eq. 15: the area-weighted least change of s_j that makes the corotated tractions sum to zero (the stable
  // variant's global-frame tractions included; they are left as they are).
  if (params.tractionCorrection) {
    Eigen::MatrixXd system = Eigen::MatrixXd::Zero(d, d);
    Eigen::VectorXd imbalance = Eigen::VectorXd::Zero(d);
    std::vector<Eigen::VectorXd> w(m);
    for (int j = 0; j < m; ++j) {
      w[j] = bc.faceRotations[j] * restNormals.row(j).transpose();
      system += restAreas(j) * w[j] * w[j].transpose();
      imbalance += restAreas(j) * bc.tractionScales(j) * w[j];
      if (bc.globalScales.size() > 0)
        imbalance += restAreas(j) * bc.globalScales(j) * bc.global.rotation * restNormals.row(j).transpose();
    }
    const Eigen::VectorXd multiplier = system.ldlt().solve(imbalance);
    for (int j = 0; j < m; ++j) bc.tractionScales(j) -= multiplier.dot(w[j]);
  }
  return bc;
}

}  // namespace somicage
