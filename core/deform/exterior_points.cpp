#include "deform/exterior_points.h"

#include <omp.h>

#include <algorithm>
#include <utility>

#include "base/errors.h"
#include "base/parallel_failure.h"

namespace somicage {

PointRegion classifyPoint(double winding, bool reliableIntegrals) {
  if (winding >= 0.5 && reliableIntegrals) return PointRegion::Inside;
  return winding < 0.5 ? PointRegion::Outside : PointRegion::OnCage;  // a NaN winding number: on the cage
}

double exteriorWeight(double distance, double band) {
  const double t = std::clamp(distance / band, 0.0, 1.0);
  return 1 - t * t * t * (t * (6 * t - 15) + 10);
}

ExteriorPlan planExteriorPoints(const Cage& restCage, const Eigen::MatrixXd& points,
                                const std::vector<PointRegion>& regions, int threads) {
  SOMICAGE_ASSERT(regions.size() == static_cast<std::size_t>(points.rows()), "a region per point");
  ExteriorPlan plan;
  for (int p = 0; p < static_cast<int>(regions.size()); ++p)
    if (regions[static_cast<std::size_t>(p)] != PointRegion::Inside) plan.blends.push_back({p, 1.0});
  const int count = static_cast<int>(plan.blends.size());
  plan.closest.resize(static_cast<std::size_t>(count));
  plan.proxies.resize(count, restCage.dim());
  if (count == 0) return plan;
  const double diameter = cageDiameter(restCage.vertices);
  const CageProximity proximity(restCage);
  ParallelFailure failure;  // the closest-point search allocates
#pragma omp parallel for schedule(dynamic, 16) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (int e = 0; e < count; ++e) {
    if (failure.failed()) continue;
    failure.run([&] {
      ExteriorBlend& blend = plan.blends[static_cast<std::size_t>(e)];
      const CageProximity::Closest& c = plan.closest[static_cast<std::size_t>(e)] =
          proximity.closest(points.row(blend.point).transpose());
      if (regions[static_cast<std::size_t>(blend.point)] == PointRegion::Outside)
        blend.weight = exteriorWeight(c.distance, kExteriorBand * diameter);  // OnCage: d = 0, w = 1
      plan.proxies.row(e) = (c.point - kProxyDepth * diameter * c.normal).transpose();
    });
  }
  failure.rethrow();
  return plan;
}

void integrateProxies(const Cage& restCage, ExteriorPlan& plan, const ProxyIntegrator& integrate) {
  const double depth = kProxyDepth * cageDiameter(restCage.vertices);
  const CageProximity proximity(restCage);
  std::vector<int> pending(plan.blends.size());
  for (std::size_t e = 0; e < pending.size(); ++e) pending[e] = static_cast<int>(e);
  while (!pending.empty()) {  // at most three rounds: face, edge, corner
    Eigen::MatrixXd proxies(static_cast<Eigen::Index>(pending.size()), restCage.dim());
    for (std::size_t k = 0; k < pending.size(); ++k)
      proxies.row(static_cast<Eigen::Index>(k)) = plan.proxies.row(pending[k]);
    const std::vector<bool> reliable = integrate(proxies, pending);
    std::vector<int> failed;
    for (std::size_t k = 0; k < pending.size(); ++k) {
      CageProximity::Closest& c = plan.closest[static_cast<std::size_t>(pending[k])];
      if (reliable[k] || !proximity.coarsen(c)) continue;
      plan.proxies.row(pending[k]) = (c.point - depth * c.normal).transpose();
      failed.push_back(pending[k]);
    }
    pending = std::move(failed);
  }
}

}  // namespace somicage
