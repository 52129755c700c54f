#include "boundary_conditions.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>

#include "errors.h"

namespace somicage {

Similarity fitSimilarity(const Eigen::MatrixXd& from, const Eigen::MatrixXd& to) {
  const int d = static_cast<int>(from.cols());
  const double n = static_cast<double>(from.rows());
  const Eigen::RowVectorXd meanFrom = from.colwise().mean(), meanTo = to.colwise().mean();
  const Eigen::MatrixXd X = from.rowwise() - meanFrom, Y = to.rowwise() - meanTo;
  const Eigen::MatrixXd covariance = Y.transpose() * X / n;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::VectorXd signs = Eigen::VectorXd::Ones(d);
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0) signs(d - 1) = -1;  // no reflections
  Similarity fit;
  fit.rotation = svd.matrixU() * signs.asDiagonal() * svd.matrixV().transpose();
  const double varianceFrom = X.squaredNorm() / n;
  fit.scale = varianceFrom > 0 ? svd.singularValues().dot(signs) / varianceFrom : 1.0;
  fit.translation = meanTo.transpose() - fit.scale * fit.rotation * meanFrom.transpose();
  return fit;
}

Eigen::MatrixXd closestRotation(const Eigen::MatrixXd& M) {
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::MatrixXd U = svd.matrixU();
  if ((U * svd.matrixV().transpose()).determinant() < 0) U.col(U.cols() - 1) *= -1;
  return U * svd.matrixV().transpose();
}

Eigen::MatrixXd vertexNormals(const Cage& cage, const Eigen::MatrixXd& vertices) {
  // Summing the unit normal times the area is summing the unnormalised normals (up to a common factor).
  const Eigen::MatrixXd N = faceNormals(cage, vertices);
  const Eigen::VectorXd A = faceAreas(cage, vertices);
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(cage.numVertices(), cage.dim());
  for (int j = 0; j < cage.numFaces(); ++j)
    for (int k = 0; k < cage.dim(); ++k) sum.row(cage.faces(j, k)) += A(j) * N.row(j);
  // Row by row: rowwise().normalize() divides by zero at a vertex whose faces all collapsed (normal 0 then).
  for (int i = 0; i < sum.rows(); ++i) sum.row(i).normalize();
  return sum;
}

Eigen::VectorXd normalSpread(const Cage& cage, const Eigen::MatrixXd& n) {
  Eigen::VectorXd spread(cage.numFaces());
  for (int j = 0; j < cage.numFaces(); ++j) {
    if (cage.dim() == 3) {
      const Eigen::Vector3d n1 = n.row(cage.faces(j, 0)), n2 = n.row(cage.faces(j, 1)), n3 = n.row(cage.faces(j, 2));
      spread(j) = 2 * std::atan2(n1.dot(n2.cross(n3)), 1 + n1.dot(n2) + n2.dot(n3) + n3.dot(n1));
    } else {
      const Eigen::Vector2d na = n.row(cage.faces(j, 0)), nb = n.row(cage.faces(j, 1));
      spread(j) = std::atan2(na.x() * nb.y() - na.y() * nb.x(), na.dot(nb));
    }
  }
  return spread;
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

}  // namespace

BoundaryConditions computeBoundaryConditions(const Cage& rest, const Eigen::MatrixXd& posed,
                                             const DeformParams& params) {
  const int d = rest.dim(), m = rest.numFaces(), n = rest.numVertices();
  SOMICAGE_ASSERT(posed.rows() == n && posed.cols() == d, "posed cage matches the rest cage");
  const double t = params.blend;

  BoundaryConditions bc;
  bc.global = fitSimilarity(rest.vertices, posed);
  bc.faceRotations.resize(m);
  bc.tangentialStretch.resize(m);
  for (int j = 0; j < m; ++j) {
    if (t == 0) {
      bc.faceRotations[j] = bc.global.rotation;
      bc.tangentialStretch(j) = bc.global.scale;
    } else {
      const FaceMap local = localFaceMap(rest, posed, j);
      bc.faceRotations[j] = blendRotation(bc.global.rotation, local.rotation, t);
      bc.tangentialStretch(j) = t * local.stretch + (1 - t) * bc.global.scale;
    }
  }

  // Vertex rotations: polar rotation of the rest-area-weighted sum of incident face rotations.
  const Eigen::VectorXd restAreas = faceAreas(rest, rest.vertices);
  std::vector<Eigen::MatrixXd> sums(n, Eigen::MatrixXd::Zero(d, d));
  for (int j = 0; j < m; ++j)
    for (int k = 0; k < d; ++k) sums[rest.faces(j, k)] += restAreas(j) * bc.faceRotations[j];
  bc.vertexRotations.resize(n);
  for (int i = 0; i < n; ++i) bc.vertexRotations[i] = closestRotation(sums[i]);

  // Normal stretch from the change of normal spread (bulging, section 4.4).
  const Eigen::VectorXd spreadRest = normalSpread(rest, vertexNormals(rest, rest.vertices));
  const Eigen::VectorXd spreadPosed = normalSpread(rest, vertexNormals(rest, posed));
  const double normalisation = std::pow(2.0, d - 1) * M_PI;
  bc.normalStretch.resize(m);
  for (int j = 0; j < m; ++j) {
    double bulge = spreadPosed(j) - spreadRest(j);
    if (d == 2) bulge = wrapAngle(bulge);
    bc.normalStretch(j) = bc.tangentialStretch(j) * std::exp(params.gamma * bulge / normalisation);
  }

  // Eq. 14: s_j = 2 [eta + nu/(1-2nu) (eta + (d-1) lambda)]; nu/(1-2nu) -> -1/2 as nu -> +-infinity.
  const double volumetric = std::isinf(params.nu) ? -0.5 : params.nu / (1 - 2 * params.nu);
  bc.tractionScales.resize(m);
  for (int j = 0; j < m; ++j) {
    const double eta = bc.normalStretch(j), lambda = bc.tangentialStretch(j);
    bc.tractionScales(j) = 2 * (eta + volumetric * (eta + (d - 1) * lambda));
  }

  // Eq. 15: the area-weighted least change of s_j that makes the corotated tractions sum to zero.
  if (params.tractionCorrection) {
    const Eigen::MatrixXd restNormals = faceNormals(rest, rest.vertices);
    Eigen::MatrixXd system = Eigen::MatrixXd::Zero(d, d);
    Eigen::VectorXd imbalance = Eigen::VectorXd::Zero(d);
    std::vector<Eigen::VectorXd> w(m);
    for (int j = 0; j < m; ++j) {
      w[j] = bc.faceRotations[j] * restNormals.row(j).transpose();
      system += restAreas(j) * w[j] * w[j].transpose();
      imbalance += restAreas(j) * bc.tractionScales(j) * w[j];
    }
    const Eigen::VectorXd multiplier = system.ldlt().solve(imbalance);
    for (int j = 0; j < m; ++j) bc.tractionScales(j) -= multiplier.dot(w[j]);
  }
  return bc;
}

}  // namespace somicage
