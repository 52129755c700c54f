#include "geometry/kelvin_kernels.h"

#include <cmath>

namespace somicage {

double kelvinA(int dim) { return 1.0 / (std::pow(2.0, dim - 1) * M_PI); }

double kelvinB(int dim, double nu) { return std::isinf(nu) ? 0.0 : kelvinA(dim) / (4.0 * (1.0 - nu)); }

template <int Dim>
static Eigen::Matrix<double, Dim, Dim> tractionKernelImpl(const Eigen::Matrix<double, Dim, 1>& r,
                                                          const Eigen::Matrix<double, Dim, 1>& n, double nu) {
  const double a = kelvinA(Dim), b = kelvinB(Dim, nu);
  const double len = r.norm(), nr = n.dot(r);
  using Mat = Eigen::Matrix<double, Dim, Dim>;
  const Mat first = nr * Mat::Identity() + n * r.transpose() - r * n.transpose();
  return (a - 2 * b) / std::pow(len, Dim) * first + 2 * b * Dim / std::pow(len, Dim + 2) * nr * r * r.transpose();
}

Eigen::Matrix3d kelvinlet(const Eigen::Vector3d& r, double nu) {
  const double a = kelvinA(3), b = kelvinB(3, nu), len = r.norm();
  return (a - b) / len * Eigen::Matrix3d::Identity() + b / (len * len * len) * r * r.transpose();
}

Eigen::Matrix2d kelvinlet(const Eigen::Vector2d& r, double nu) {
  const double a = kelvinA(2), b = kelvinB(2, nu), len = r.norm();
  return (a - b) * std::log(1.0 / len) * Eigen::Matrix2d::Identity() + b / (len * len) * r * r.transpose();
}

Eigen::Matrix3d tractionKernel(const Eigen::Vector3d& r, const Eigen::Vector3d& n, double nu) {
  return tractionKernelImpl<3>(r, n, nu);
}

Eigen::Matrix2d tractionKernel(const Eigen::Vector2d& r, const Eigen::Vector2d& n, double nu) {
  return tractionKernelImpl<2>(r, n, nu);
}

}  // namespace somicage
