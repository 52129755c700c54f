#include "model/view_quantity.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "analysis/deformation_quantities.h"
#include "base/errors.h"

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

// Per vertex, the largest jump of J over its edges that cross a face between tetrahedra (0 where none does).
Eigen::VectorXd seamJumps(const DeformationAnalysis& a, const Eigen::MatrixXi&) {
  if (a.seams.vertices.size() == a.points.detJ.size()) return a.seams.vertices;
  return Eigen::VectorXd::Constant(a.points.detJ.size(), std::numeric_limits<double>::quiet_NaN());
}

}  // namespace

const std::vector<QuantityDescriptor>& quantityDescriptors() {
  using S = QuantitySource;
  static const std::vector<QuantityDescriptor> descriptors{
      {"shading", "shading only", ColorScale::Viridis, S::None, 0, nullptr, false},
      {"detj", "det J", ColorScale::LogDiverging, S::Jacobian, 1, detJ, false},
      {"distortion", "conformal distortion", ColorScale::Viridis, S::Jacobian, 1, distortion, false},
      {"foldover", "fold-overs", ColorScale::LogDiverging, S::Jacobian, 1, foldovers, false},
      {"area", "area ratio", ColorScale::LogDiverging, S::Jacobian, 1, vertexAreaRatio, false},
      {"seams", "seam jump |J+ - J-| / |J| (tetrahedra)", ColorScale::Viridis, S::Jacobian, 0, seamJumps, true},
      {"difference", "difference (cage diameters)", ColorScale::Viridis, S::Difference, 0, nullptr, false},
      {"field", "coordinate field |T n|", ColorScale::Viridis, S::Field, 0, nullptr, false},
  };
  return descriptors;
}

const QuantityDescriptor& quantityDescriptor(int index) {
  return quantityDescriptors()[static_cast<std::size_t>(index)];
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

ViewMeasurement jacobianMeasurement(const DeformationAnalysis& a, const Eigen::MatrixXi& triangles, int quantity) {
  ViewMeasurement out;
  out.detJ = a.points.detJ;
  out.points = a.positions;
  out.values = quantityDescriptor(quantity).values(a, triangles);
  out.closed = a.volume.closed;
  out.volumeChange = a.volume.change();
  out.foldovers = a.points.foldovers;
  out.distortionP95 = quantile(a.points.distortion, 0.95);
  return out;
}

ColorRange sharedRange(const std::vector<const ViewMeasurement*>& views, const QuantityDescriptor& quantity) {
  const bool log = quantity.scale == ColorScale::LogDiverging;
  double extent = 0;  // LogDiverging: the widest view's quantile of |log v|; Viridis: of v
  for (const ViewMeasurement* m : views) {
    if (!m || m->values.size() == 0) continue;
    Eigen::VectorXd spread(m->values.size());
    for (Eigen::Index i = 0; i < m->values.size(); ++i) {
      const double v = m->values[i];
      const bool folded = m->detJ.size() == m->values.size() && m->detJ[i] <= 0;
      spread[i] = folded || !std::isfinite(v) || (log && !(v > 0)) ? std::numeric_limits<double>::quiet_NaN()
                  : log                                            ? std::abs(std::log(v))
                                                                   : v;
    }
    const double q = quantile(spread, kRangeQuantile);  // NaN when the view has no usable value
    if (std::isfinite(q)) extent = std::max(extent, q);
  }
  if (!log) return {quantity.autoLow, std::max(extent, quantity.autoLow + 1e-3)};
  const double hi = std::max(std::exp(extent), 1.0 + 1e-3);
  return {1.0 / hi, hi};
}

long verticesBeyond(const std::vector<const ViewMeasurement*>& views, const ColorRange& range) {
  long n = 0;
  for (const ViewMeasurement* m : views)
    for (Eigen::Index i = 0; m && i < m->values.size(); ++i) {
      const double v = m->values[i];
      const bool folded = m->detJ.size() == m->values.size() && m->detJ[i] <= 0;
      n += !folded && std::isfinite(v) && (v < range.lo || v > range.hi);
    }
  return n;
}

std::string rangeProblem(const ColorRange& range, ColorScale scale) {
  if (!std::isfinite(range.lo) || !std::isfinite(range.hi)) return "min and max must be numbers";
  if (scale == ColorScale::LogDiverging && !(range.lo > 0 && range.lo < 1 && range.hi > 1))
    return "a ratio's range must have 0 < min < 1 < max (the map is centred at 1)";
  if (!(range.lo < range.hi)) return "min must be below max";
  return "";
}

float colorCoordinate(double value, double detJ, const ColorRange& range, ColorScale scale) {
  if (detJ <= 0) return -1.0f;
  if (!std::isfinite(value)) return -2.0f;
  double t;
  if (scale == ColorScale::LogDiverging)  // each side of 1 on its own log scale, so 1 stays at the centre
    t = value < 1 ? 0.5 - 0.5 * std::log(value) / std::log(range.lo) : 0.5 + 0.5 * std::log(value) / std::log(range.hi);
  else
    t = (value - range.lo) / (range.hi - range.lo);
  return static_cast<float>(std::clamp(t, 0.0, 1.0));
}

void ShowSettings::setView(std::size_t v, int quantity, std::size_t viewCount) {
  const ViewShow last = views.back();
  views.resize(std::max(views.size(), std::max(viewCount, v + 1)), last);
  views[v].quantity = quantity;
}

int ShowSettings::otherView(std::size_t v, std::size_t viewCount) const {
  const int other = view(v).other;
  if (other >= 0 && static_cast<std::size_t>(other) < viewCount && static_cast<std::size_t>(other) != v) return other;
  for (std::size_t w = 0; w < viewCount; ++w)
    if (w != v) return static_cast<int>(w);
  return -1;
}

bool ShowSettings::anyShown(std::size_t viewCount) const {
  for (std::size_t v = 0; v < viewCount; ++v)
    if (view(v).quantity > 0) return true;
  return false;
}

bool ShowSettings::drawsLegend(std::size_t v, std::size_t viewCount) const {
  const int quantity = view(v).quantity;
  if (quantity <= 0) return false;
  for (std::size_t w = v + 1; w < viewCount; ++w)
    if (view(w).quantity == quantity) return false;
  return true;
}

bool ShowSettings::usesSource(QuantitySource source, std::size_t viewCount) const {
  for (std::size_t v = 0; v < viewCount; ++v)
    if (quantityDescriptor(view(v).quantity).source == source) return true;
  return false;
}

ShowSettings parseShow(const std::string& value, const std::string& option, int& fieldVertex) {
  ShowSettings show;
  show.views.clear();
  fieldVertex = -1;
  std::size_t start = 0;
  while (start <= value.size()) {
    const std::size_t end = std::min(value.find(',', start), value.size());
    std::string id = value.substr(start, end - start);
    if (id.rfind("field:", 0) == 0) {
      const std::string index = id.substr(6);
      char* stop = nullptr;
      const long vertex = std::strtol(index.c_str(), &stop, 10);
      if (index.empty() || *stop != '\0' || vertex < 0 || vertex > 1000000000)
        throw InputError(option, -1, "expected a cage vertex index after 'field:', got '" + index + "'",
                         "--show field:3");
      fieldVertex = static_cast<int>(vertex);
      id = "field";
    }
    show.views.push_back(ViewShow{quantityIndex(id, option), -1});
    start = end + 1;
  }
  return show;
}

std::vector<const ViewMeasurement*> viewsShowing(const ShowSettings& show, int quantity,
                                                 const std::vector<const ViewMeasurement*>& measured) {
  std::vector<const ViewMeasurement*> views;
  for (std::size_t v = 0; v < measured.size(); ++v)
    if (show.view(v).quantity == quantity) views.push_back(measured[v]);
  return views;
}

ColorRange quantityRange(const ShowSettings& show, int quantity, const std::vector<const ViewMeasurement*>& measured) {
  const QuantityDescriptor& d = quantityDescriptor(quantity);
  auto fixed = show.ranges.find(quantity);
  if (fixed != show.ranges.end() && fixed->second.fixed && rangeProblem(fixed->second.range, d.scale).empty())
    return fixed->second.range;
  return sharedRange(viewsShowing(show, quantity, measured), d);
}

ColorRange rangeFieldsValue(const ShowSettings& show, int quantity, const ColorRange& drawn) {
  const auto it = show.ranges.find(quantity);
  return it != show.ranges.end() && it->second.fixed ? it->second.range : drawn;
}

}  // namespace somicage::editor
