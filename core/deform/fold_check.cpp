#include "deform/fold_check.h"

#include <cmath>
#include <vector>

#include "geometry/cage_proximity.h"

namespace somicage {

Eigen::MatrixXd foldCheckSamples(const Cage& restCage) {
  const int d = restCage.dim();
  const Eigen::VectorXd lo = restCage.vertices.colwise().minCoeff(), hi = restCage.vertices.colwise().maxCoeff();
  const double measure = std::abs(signedMeasure(restCage.vertices, restCage.faces));
  const double h = std::pow(measure / kFoldCheckCells, 1.0 / d);
  Eigen::VectorXi counts(d);
  for (int a = 0; a < d; ++a) counts(a) = std::max(1, static_cast<int>(std::ceil((hi(a) - lo(a)) / h)));
  const CageProximity proximity(restCage);
  std::vector<Eigen::VectorXd> inside;
  Eigen::VectorXi index = Eigen::VectorXi::Zero(d);
  for (;;) {
    const Eigen::VectorXd x = lo + h * (index.cast<double>().array() + 0.5).matrix();
    const CageProximity::Closest c = proximity.closest(x);
    // The outward pseudo-normal at the closest point tells inside from outside (Baerentzen & Aanaes 2005).
    if ((x - c.point).dot(c.normal) < 0 && c.distance >= 0.5 * h) inside.push_back(x);
    int a = 0;
    while (a < d && ++index(a) == counts(a)) index(a++) = 0;
    if (a == d) break;
  }
  Eigen::MatrixXd samples(static_cast<int>(inside.size()), d);
  for (std::size_t p = 0; p < inside.size(); ++p) samples.row(static_cast<int>(p)) = inside[p].transpose();
  return samples;
}

bool foldFree(const Eigen::MatrixXd& J, double minDet) {
  const int d = J.cols() == 9 ? 3 : 2;  // row-major d by d
  for (int p = 0; p < J.rows(); ++p) {
    if (std::isnan(J(p, 0))) continue;
    const auto j = J.row(p);
    const double det = d == 2 ? j(0) * j(3) - j(1) * j(2)
                              : j(0) * (j(4) * j(8) - j(5) * j(7)) - j(1) * (j(3) * j(8) - j(5) * j(6)) +
                                    j(2) * (j(3) * j(7) - j(4) * j(6));
    if (!(det > minDet)) return false;  // a NaN elsewhere in the row fails too
  }
  return true;
}

double leastFoldFreeBlend(const Eigen::MatrixXd& J0, const Eigen::MatrixXd& J1, double minDet) {
  constexpr int kSteps = 32, kBisections = 10;
  auto passes = [&](double s) { return foldFree(J0 + s * (J1 - J0), minDet); };
  if (passes(0)) return 0;
  for (int k = 1; k <= kSteps; ++k) {
    double pass = static_cast<double>(k) / kSteps;
    if (!passes(pass)) continue;
    double fail = static_cast<double>(k - 1) / kSteps;
    for (int i = 0; i < kBisections; ++i) {
      const double mid = 0.5 * (fail + pass);
      (passes(mid) ? pass : fail) = mid;
    }
    return pass;
  }
  return 1;
}

}  // namespace somicage
