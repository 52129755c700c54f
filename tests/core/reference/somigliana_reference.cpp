// The reference evaluation of somigliana_reference.h (test code only; see there).
#include "somigliana_reference.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>

namespace somicage::reference {

// ---------------------------------------------------------------------------------------------------------------
// Kernels (Eqs. 3, 4) and coordinates (Eq. 8)
// ---------------------------------------------------------------------------------------------------------------

KernelScalars kernelScalars(int d, double nu) {
  const double a = 1 / (std::pow(2.0, d - 1) * M_PI);
  return {a, std::isinf(nu) ? 0.0 : a / (4 * (1 - nu))};
}

namespace {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;
template <int D>
using Mat = Eigen::Matrix<double, D, D>;

// Eq. 3: the Kelvinlet K(y, x), r = y - x.
template <int D>
Mat<D> kelvinKernel(const KernelScalars& k, const Vec<D>& r) {
  const double length = r.norm();
  if constexpr (D == 3)
    return (k.a - k.b) / length * Mat<D>::Identity() + k.b / std::pow(length, 3) * r * r.transpose();
  return (k.a - k.b) * std::log(1 / length) * Mat<D>::Identity() + k.b / (length * length) * r * r.transpose();
}

// Eq. 4: the traction kernel T(y, x) with the boundary normal n = n(y), r = y - x.
template <int D>
Mat<D> tractionKernel(const KernelScalars& k, const Vec<D>& r, const Vec<D>& n) {
  const double length = r.norm(), nr = n.dot(r);
  return (k.a - 2 * k.b) / std::pow(length, D) * (nr * Mat<D>::Identity() + n * r.transpose() - r * n.transpose()) +
         2 * k.b * D / std::pow(length, D + 2) * nr * r * r.transpose();
}

}  // namespace

// Unit outward normal and area (3D) or length (2D) of face j for the cage's faces at the vertex positions V.
void faceGeometry(const Cage& cage, const Eigen::MatrixXd& V, int j, Eigen::VectorXd& normal, double& area) {
  if (cage.dim() == 3) {
    const Eigen::Vector3d p0 = V.row(cage.faces(j, 0)), p1 = V.row(cage.faces(j, 1)), p2 = V.row(cage.faces(j, 2));
    const Eigen::Vector3d cross = (p1 - p0).cross(p2 - p0);
    area = cross.norm() / 2;
    normal.resize(3);
    normal << cross.x() / (2 * area), cross.y() / (2 * area), cross.z() / (2 * area);
  } else {
    const Eigen::Vector2d e = V.row(cage.faces(j, 1)) - V.row(cage.faces(j, 0));
    area = e.norm();
    normal.resize(2);
    normal << e.y() / area, -e.x() / area;  // (e_y, -e_x)/|e|: outward for a counter-clockwise polygon
  }
}

namespace {

template <int D>
std::vector<Coordinates> integrateCoordinatesIn(const Cage& cage, const Vec<D>& x, const std::vector<double>& nus,
                                                const QuadratureOptions& options) {
  const size_t count = nus.size();
  std::vector<KernelScalars> scalars;
  std::vector<std::vector<Mat<D>>> T(count, std::vector<Mat<D>>(cage.numVertices(), Mat<D>::Zero()));
  std::vector<std::vector<Mat<D>>> K(count, std::vector<Mat<D>>(cage.numFaces(), Mat<D>::Zero()));
  for (double nu : nus) scalars.push_back(kernelScalars(D, nu));
  const GaussRule rule = gaussLegendre(options.order);
  for (int j = 0; j < cage.numFaces(); ++j) {
    Eigen::VectorXd normal;
    double area;
    faceGeometry(cage, cage.vertices, j, normal, area);
    const Vec<D> n = normal;
    auto node = [&](const Vec<D>& y, const Vec<D>& phi, double weight) {
      const Vec<D> r = y - x;
      for (size_t k = 0; k < count; ++k) {
        const Mat<D> traction = weight * tractionKernel<D>(scalars[k], r, n);
        for (int c = 0; c < D; ++c) T[k][cage.faces(j, c)] += phi[c] * traction;  // Eq. 8a
        K[k][j] += weight * kelvinKernel<D>(scalars[k], r);                       // Eq. 8b
      }
    };
    Vec<D> p[D];
    for (int c = 0; c < D; ++c) p[c] = cage.vertices.row(cage.faces(j, c));
    if constexpr (D == 3)
      forEachTriangleNode(p, x, options, rule, node);
    else
      forEachSegmentNode(p, x, options, rule, node);
  }
  std::vector<Coordinates> out(count);
  for (size_t k = 0; k < count; ++k) {
    out[k].T.assign(T[k].begin(), T[k].end());
    out[k].K.assign(K[k].begin(), K[k].end());
  }
  return out;
}

}  // namespace

std::vector<Coordinates> integrateCoordinates(const Cage& cage, const Eigen::VectorXd& x,
                                              const std::vector<double>& nus, const QuadratureOptions& options) {
  if (cage.dim() == 3) return integrateCoordinatesIn<3>(cage, x, nus, options);
  return integrateCoordinatesIn<2>(cage, x, nus, options);
}

// ---------------------------------------------------------------------------------------------------------------
// Boundary conditions (Eqs. 12-15, docs/method.md "Deformer")
// ---------------------------------------------------------------------------------------------------------------

namespace {

// The rotation of the polar decomposition of M (reflection-safe).
Eigen::MatrixXd polarRotation(const Eigen::MatrixXd& M) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::MatrixXd flip = Eigen::MatrixXd::Identity(M.rows(), M.cols());
  flip(M.rows() - 1, M.cols() - 1) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
  return svd.matrixU() * flip * svd.matrixV().transpose();
}

Eigen::Matrix2d rotation2(double angle) { return Eigen::Rotation2Dd(angle).toRotationMatrix(); }

// Umeyama (1991): the least-squares similarity rest -> posed with equal vertex weights, det R = +1.
void umeyama(const Eigen::MatrixXd& rest, const Eigen::MatrixXd& posed, Eigen::MatrixXd& R, double& s) {
  const Eigen::MatrixXd X = rest.rowwise() - rest.colwise().mean(), Y = posed.rowwise() - posed.colwise().mean();
  const double n = static_cast<double>(rest.rows());
  const Eigen::MatrixXd covariance = Y.transpose() * X / n;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::VectorXd sign = Eigen::VectorXd::Ones(rest.cols());
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0) sign(rest.cols() - 1) = -1;
  R = svd.matrixU() * sign.asDiagonal() * svd.matrixV().transpose();
  s = svd.singularValues().dot(sign) / (X.squaredNorm() / n);
}

// Area-weighted unit vertex normals of the cage's faces at positions V (zero where every incident face is).
std::vector<Eigen::VectorXd> vertexNormals(const Cage& cage, const Eigen::MatrixXd& V) {
  std::vector<Eigen::VectorXd> normals(cage.numVertices(), Eigen::VectorXd::Zero(cage.dim()));
  for (int j = 0; j < cage.numFaces(); ++j) {
    Eigen::VectorXd n;
    double area;
    faceGeometry(cage, V, j, n, area);
    for (int c = 0; c < cage.dim(); ++c) normals[cage.faces(j, c)] += area * n;
  }
  for (auto& n : normals)
    if (n.norm() > 0) n.normalize();
  return normals;
}

// The solid angle (3D) / angle (2D) spanned by face j's vertex normals, signed as docs/method.md says.
double normalSpan(const Cage& cage, const std::vector<Eigen::VectorXd>& N, int j) {
  if (cage.dim() == 3) {
    const Eigen::Vector3d n1 = N[cage.faces(j, 0)], n2 = N[cage.faces(j, 1)], n3 = N[cage.faces(j, 2)];
    return 2 * std::atan2(n1.dot(n2.cross(n3)), 1 + n1.dot(n2) + n2.dot(n3) + n3.dot(n1));
  }
  const Eigen::Vector2d n0 = N[cage.faces(j, 0)], n1 = N[cage.faces(j, 1)];
  return std::atan2(n0.x() * n1.y() - n0.y() * n1.x(), n0.dot(n1));
}

}  // namespace

BoundaryConditions boundaryConditions(const Cage& rest, const Eigen::MatrixXd& posed, const PoseParameters& p) {
  const int d = rest.dim(), F = rest.numFaces();
  Eigen::MatrixXd R;
  double s;
  umeyama(rest.vertices, posed, R, s);
  const std::vector<Eigen::VectorXd> restNormals = vertexNormals(rest, rest.vertices);
  const std::vector<Eigen::VectorXd> posedNormals = vertexNormals(rest, posed);
  const double kappa = std::isinf(p.nu) ? -0.5 : p.nu / (1 - 2 * p.nu);  // nu / (1 - 2 nu) and its limit

  BoundaryConditions bc;
  std::vector<Eigen::VectorXd> n(F);
  std::vector<double> area(F);
  for (int j = 0; j < F; ++j) {
    Eigen::VectorXd posedNormal;
    double posedArea;
    faceGeometry(rest, rest.vertices, j, n[j], area[j]);
    faceGeometry(rest, posed, j, posedNormal, posedArea);
    // Local variant: the face's own rotation and mean in-plane stretch.
    Eigen::MatrixXd localRotation;
    double localStretch;
    if (d == 3) {
      const Eigen::Vector3d v0 = rest.vertices.row(rest.faces(j, 0)), w0 = posed.row(rest.faces(j, 0));
      Eigen::Matrix<double, 3, 2> E, Fm;
      E << Eigen::Vector3d(rest.vertices.row(rest.faces(j, 1))) - v0,
          Eigen::Vector3d(rest.vertices.row(rest.faces(j, 2))) - v0;
      Fm << Eigen::Vector3d(posed.row(rest.faces(j, 1))) - w0, Eigen::Vector3d(posed.row(rest.faces(j, 2))) - w0;
      Eigen::Matrix3d restFrame, posedFrame;
      restFrame << E, n[j];
      posedFrame << Fm, posedNormal;
      localRotation = polarRotation(posedFrame * restFrame.inverse());
      // The in-plane map rest face -> posed face: F (E^T E)^-1 E^T; its two non-zero singular values.
      const Eigen::Matrix3d inPlane = Fm * (E.transpose() * E).inverse() * E.transpose();
      const Eigen::Vector3d sigma = Eigen::JacobiSVD<Eigen::Matrix3d>(inPlane).singularValues();
      localStretch = (sigma[0] + sigma[1]) / 2;
    } else {
      const Eigen::Vector2d e = rest.vertices.row(rest.faces(j, 1)) - rest.vertices.row(rest.faces(j, 0));
      const Eigen::Vector2d f = posed.row(rest.faces(j, 1)) - posed.row(rest.faces(j, 0));
      localRotation = rotation2(std::atan2(e.x() * f.y() - e.y() * f.x(), e.dot(f)));
      localStretch = f.norm() / e.norm();
    }
    // Blend (Fig. 4): the geodesic from R to the local rotation, and the stretches linearly.
    const Eigen::MatrixXd relative = R.transpose() * localRotation;
    if (d == 3) {
      const Eigen::AngleAxisd log{Eigen::Matrix3d(relative)};
      bc.faceRotation.push_back(R * Eigen::AngleAxisd(p.blend * log.angle(), log.axis()).toRotationMatrix());
    } else {
      bc.faceRotation.push_back(R * rotation2(p.blend * std::atan2(relative(1, 0), relative(0, 0))));
    }
    const double lambda = p.blend * localStretch + (1 - p.blend) * s;
    // Bulging (section 4.4): the change of the span of the vertex normals, wrapped to (-pi, pi] in 2D.
    double beta = normalSpan(rest, posedNormals, j) - normalSpan(rest, restNormals, j);
    if (d == 2) beta = std::remainder(beta, 2 * M_PI);
    const double eta = lambda * std::exp(p.gamma * beta / (std::pow(2.0, d - 1) * M_PI));
    bc.tractionScale.push_back(2 * (eta + kappa * (eta + (d - 1) * lambda)));  // Eq. 14
  }
  if (p.tractionCorrection) {  // Eq. 15: min sum A_j (s'_j - s_j)^2 subject to sum A_j s'_j R_j n_j = 0
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(d, d);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(d);
    for (int j = 0; j < F; ++j) {
      const Eigen::VectorXd w = bc.faceRotation[j] * n[j];
      M += area[j] * w * w.transpose();
      rhs += area[j] * bc.tractionScale[j] * w;
    }
    const Eigen::VectorXd multiplier = M.fullPivLu().solve(rhs);
    for (int j = 0; j < F; ++j) bc.tractionScale[j] -= multiplier.dot(bc.faceRotation[j] * n[j]);
  }
  // Vertex rotations: the polar rotation of the rest-area-weighted sum of the incident face rotations.
  std::vector<Eigen::MatrixXd> sum(rest.numVertices(), Eigen::MatrixXd::Zero(d, d));
  for (int j = 0; j < F; ++j)
    for (int c = 0; c < d; ++c) sum[rest.faces(j, c)] += area[j] * bc.faceRotation[j];
  for (const Eigen::MatrixXd& m : sum) bc.vertexRotation.push_back(polarRotation(m));
  return bc;
}

// ---------------------------------------------------------------------------------------------------------------
// The deformed point (Eq. 11)
// ---------------------------------------------------------------------------------------------------------------

Eigen::VectorXd deformPoint(const Cage& rest, const Eigen::MatrixXd& posed, const Coordinates& coordinates,
                            const BoundaryConditions& bc) {
  const int d = rest.dim();
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(d, d);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(d);
  for (int i = 0; i < rest.numVertices(); ++i) {
    const Eigen::MatrixXd rotated = bc.vertexRotation[i] * coordinates.T[i] * bc.vertexRotation[i].transpose();
    T += rotated;
    b += rotated * posed.row(i).transpose();
  }
  for (int j = 0; j < rest.numFaces(); ++j) {
    Eigen::VectorXd n;
    double area;
    faceGeometry(rest, rest.vertices, j, n, area);
    b += bc.tractionScale[j] * bc.faceRotation[j] * coordinates.K[j] * n;
  }
  return T.fullPivLu().solve(b);
}

// ---------------------------------------------------------------------------------------------------------------
// Helpers for choosing test points
// ---------------------------------------------------------------------------------------------------------------

// Generalised winding number of x with respect to the cage (1 inside, 0 outside): signed solid angles
// (van Oosterom-Strackee) / 4 pi in 3D, signed angles / 2 pi in 2D.
double windingNumber(const Cage& cage, const Eigen::VectorXd& x) {
  double sum = 0;
  for (int j = 0; j < cage.numFaces(); ++j) {
    if (cage.dim() == 3) {
      const Eigen::Vector3d a = Eigen::Vector3d(cage.vertices.row(cage.faces(j, 0))) - x,
                            b = Eigen::Vector3d(cage.vertices.row(cage.faces(j, 1))) - x,
                            c = Eigen::Vector3d(cage.vertices.row(cage.faces(j, 2))) - x;
      const double la = a.norm(), lb = b.norm(), lc = c.norm();
      sum += 2 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
    } else {
      const Eigen::Vector2d a = Eigen::Vector2d(cage.vertices.row(cage.faces(j, 0))) - x,
                            b = Eigen::Vector2d(cage.vertices.row(cage.faces(j, 1))) - x;
      sum += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    }
  }
  return sum / (cage.dim() == 3 ? 4 * M_PI : 2 * M_PI);
}

double distanceToCage(const Cage& cage, const Eigen::VectorXd& x) {
  double distance = INFINITY;
  for (int j = 0; j < cage.numFaces(); ++j) {
    if (cage.dim() == 3)
      distance = std::min(distance,
                          triangleDistance(Eigen::Vector3d(x), cage.vertices.row(cage.faces(j, 0)),
                                           cage.vertices.row(cage.faces(j, 1)), cage.vertices.row(cage.faces(j, 2))));
    else
      distance = std::min(distance, segmentDistance<Eigen::Vector2d>(x, cage.vertices.row(cage.faces(j, 0)),
                                                                     cage.vertices.row(cage.faces(j, 1))));
  }
  return distance;
}

}  // namespace somicage::reference
