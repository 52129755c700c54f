#include "view_quantity.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "errors.h"

namespace somicage::editor {

namespace {

// Per vertex, the geometric mean of the area ratios of its faces (the mean of logs: a ratio and its inverse cancel).
Eigen::VectorXd vertexAreaRatio(const DeformationAnalysis& a, const Eigen::MatrixXi& triangles) {
  const Eigen::VectorXd& faceRatio = a.faces.areaRatio;
  const Eigen::Index n = a.points.detJ.size();
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(n), count = Eigen::VectorXd::Zero(n);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    if (!(faceRatio[f] > 0)) continue;
    for (int k = 0; k < 3; ++k) {
      sum[triangles(f, k)] += std::log(faceRatio[f]);
      count[triangles(f, k)] += 1;
    }
  }
  Eigen::VectorXd out(n);
  for (Eigen::Index i = 0; i < n; ++i)
    out[i] = count[i] > 0 ? std::exp(sum[i] / count[i]) : std::numeric_limits<double>::quiet_NaN();
  return out;
}

Eigen::VectorXd detJ(const DeformationAnalysis& a, const Eigen::MatrixXi&) { return a.points.detJ; }
Eigen::VectorXd distortion(const DeformationAnalysis& a, const Eigen::MatrixXi&) { return a.points.distortion; }
// Fold-overs only: every unfolded vertex at the neutral centre of the map.
Eigen::VectorXd foldovers(const DeformationAnalysis& a, const Eigen::MatrixXi&) {
  return a.points.detJ.unaryExpr([](double d) { return d > 0 ? 1.0 : d; });
}

std::vector<std::vector<int>> faceLists(const Eigen::MatrixXi& triangles) {
  std::vector<std::vector<int>> faces(static_cast<std::size_t>(triangles.rows()));
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    faces[static_cast<std::size_t>(f)] = {triangles(f, 0), triangles(f, 1), triangles(f, 2)};
  return faces;
}

}  // namespace

const std::vector<QuantityDescriptor>& quantityDescriptors() {
  static const std::vector<QuantityDescriptor> descriptors{
      {"shading", "shading only", ColorScale::Viridis, false, nullptr},
      {"detj", "det J", ColorScale::LogDiverging, true, detJ},
      {"distortion", "conformal distortion", ColorScale::Viridis, true, distortion},
      {"foldover", "fold-overs", ColorScale::LogDiverging, true, foldovers},
      {"area", "area ratio", ColorScale::LogDiverging, true, vertexAreaRatio},
  };
  return descriptors;
}

int quantityIndex(const std::string& id, const std::string& option) {
  const std::vector<QuantityDescriptor>& d = quantityDescriptors();
  std::string ids;
  for (std::size_t i = 0; i < d.size(); ++i) {
    if (id == d[i].id) return static_cast<int>(i);
    ids += (i ? "|" : "") + std::string(d[i].id);
  }
  throw InputError(option, -1, "unknown quantity '" + id + "', expected " + ids, "--show detj");
}

ColorRange sharedRange(const std::vector<const ViewMeasurement*>& views, ColorScale scale) {
  double hi = 1.0;
  for (const ViewMeasurement* m : views) {
    for (Eigen::Index i = 0; m && i < m->values.size(); ++i) {
      const double v = m->values[i];
      if (!std::isfinite(v)) continue;
      if (scale == ColorScale::Viridis)
        hi = std::max(hi, v);
      else if (v > 0)
        hi = std::max(hi, std::max(v, 1.0 / v));
    }
  }
  if (scale == ColorScale::Viridis) return {1.0, std::max(hi, 1.0 + 1e-3)};
  hi = std::max(hi, 1.0 + 1e-3);
  return {1.0 / hi, hi};
}

float colorCoordinate(double value, double detJ, const ColorRange& range, ColorScale scale) {
  if (detJ <= 0) return -1.0f;
  if (!std::isfinite(value)) return -2.0f;
  const double t = scale == ColorScale::LogDiverging ? std::log(value / range.lo) / std::log(range.hi / range.lo)
                                                     : (value - range.lo) / (range.hi - range.lo);
  return static_cast<float>(std::clamp(t, 0.0, 1.0));
}

void ViewQuantities::update(const std::map<Method, std::shared_ptr<const CageDeformer>>& deformers,
                            const std::vector<Method>& methods, const Eigen::MatrixXd& restMesh,
                            const Eigen::MatrixXi& triangles, const Eigen::MatrixXd& pose, const DeformParams& params,
                            int quantity, std::uint64_t generation) {
  if (quantity == 0 || !quantityDescriptors()[static_cast<std::size_t>(quantity)].usesJacobian) {
    if (!entries_.empty()) ++generation_;
    entries_.clear();  // the gradients are held only while a J-based quantity is shown
    quantity_ = quantity;
    return;
  }
  bool changed = generation != measured_ || quantity != quantity_;
  for (Method m : methods) {
    auto d = deformers.find(m);
    if (d == deformers.end()) continue;
    Entry& e = entries_[m];
    if (e.deformer != d->second) {  // a new deformer (scene): new gradients
      e.deformer = d->second;
      e.gradients = std::make_unique<DeformationGradients>(*e.deformer, restMesh);
      changed = true;
    }
  }
  if (!changed) return;
  const std::vector<std::vector<int>> faces = faceLists(triangles);
  for (auto& [method, e] : entries_) {
    if (!e.gradients) continue;
    const DeformationAnalysis a = analyzeDeformation(*e.gradients, restMesh, faces, pose, params);
    ViewMeasurement& out = e.measurement;
    out.detJ = a.points.detJ;
    out.values = quantityDescriptors()[static_cast<std::size_t>(quantity)].values(a, triangles);
    out.closed = a.volume.closed;
    out.volumeChange = a.volume.change();
    out.foldovers = a.points.foldovers;
    out.distortionP95 = quantile(a.points.distortion, 0.95);
  }
  measured_ = generation;
  quantity_ = quantity;
  ++generation_;
}

void ViewQuantities::sweepNu(const std::shared_ptr<const CageDeformer>& deformer, const Eigen::MatrixXd& restMesh,
                             const Eigen::MatrixXi& triangles, const Eigen::MatrixXd& pose, const DeformParams& params,
                             const std::vector<double>& nus, std::uint64_t generation) {
  std::unique_ptr<DeformationGradients> own;
  const DeformationGradients* gradients = nullptr;
  for (const auto& [method, e] : entries_)
    if (e.deformer == deformer && e.gradients) gradients = e.gradients.get();
  if (!gradients) {
    own = std::make_unique<DeformationGradients>(*deformer, restMesh);
    gradients = own.get();
  }
  nuSweep_ = somicage::sweepNu(*gradients, restMesh, faceLists(triangles), pose, params, nus);
  nuSweepGeneration_ = generation;
}

const ViewMeasurement* ViewQuantities::measurement(Method method) const {
  auto it = entries_.find(method);
  return it == entries_.end() || !it->second.gradients ? nullptr : &it->second.measurement;
}

}  // namespace somicage::editor
