// What a view shows on its mesh besides shading (issue 12, polyscope's quantity model): a quantity is per-vertex
// scalars plus how to colour them. Each view (compare pane) has its own choice (ShowSettings). The J-based ones
// (det J, distortion, fold-overs, area ratio) come from core's exact deformation gradient
// (core/analysis/deformation_analysis.h), the coordinate field from core/analysis/coordinate_fields.h; both are
// measured on a worker (measure_worker.h). The difference to another view comes from the views' deformed points. No GL,
// no ImGui.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "analysis/deformation_analysis.h"

namespace somicage::editor {

// How scalars become colours (render/color_map.h draws them): a diverging map centred at 1 on a log scale for
// ratios, viridis for magnitudes, and fold-overs (det J <= 0) in a colour of their own in every map.
enum class ColorScale { LogDiverging, Viridis };

// Where a quantity's values come from.
enum class QuantitySource {
  None,        // shading only
  Jacobian,    // the exact J of the view's pose (measured on the worker)
  Difference,  // |x_view - x_other| in cage diameters, from the deformed points of two views
  Field,       // |T_i(x) n_i| (vertex) or |K_j(x) n_j| (face) of the selected cage element at the view's nu
};

struct QuantityDescriptor {
  const char* id;    // --show value
  const char* name;  // the Show menu and the legend
  ColorScale scale;
  QuantitySource source;
  double autoLow;  // Viridis: the low end of the automatic range (1 for distortion, 0 for magnitudes)
  // Jacobian: the per-vertex scalars of a measured pose (#V); null otherwise.
  Eigen::VectorXd (*values)(const DeformationAnalysis& analysis, const Eigen::MatrixXi& triangles);
  // Jacobian: the analysis measures the seams too (core/analysis/seam_jumps.h: J's jumps across a volume mesh's faces).
  bool seams;
};

// The "Show" choices; index 0 is shading only. Add a quantity by adding a descriptor (and its values) in
// view_quantity.cpp.
const std::vector<QuantityDescriptor>& quantityDescriptors();
const QuantityDescriptor& quantityDescriptor(int index);
// The index of the descriptor with this id; throws InputError(option, ...) listing the ids otherwise.
int quantityIndex(const std::string& id, const std::string& option);

// One view's measured quantity.
struct ViewMeasurement {
  Eigen::VectorXd values;  // #V scalars of the shown quantity (NaN: undefined)
  Eigen::VectorXd detJ;    // #V for a J-based quantity (fold-overs get their own colour); empty otherwise
  // #V by d: the view's deformed mesh at the measured pose, where the values are (hover picks on these, so the
  // value under the cursor is the vertex's even when the CPU points are stale: the in-place OpenGL device); empty
  // when the values belong to the displayed points anyway (a field of the rest mesh).
  Eigen::MatrixXd points;
  // J-based quantities only: the numbers under the view's label.
  bool closed = false;       // the mesh is closed (else volumeChange is of the capped mesh)
  double volumeChange = 0;   // deformed / rest - 1
  int foldovers = 0;         // vertices with det J <= 0
  double distortionP95 = 0;  // 95th percentile of sigma_max / sigma_min
  // 2D field: the field on a grid over the inside of the polygon, drawn as arrows (paper Fig. 3). Rest positions.
  Eigen::MatrixXd arrowPoints, arrowVectors;  // #A by 2 each
};

// The measured quantities of a pose at `quantity` (a Jacobian descriptor) from its analysis.
ViewMeasurement jacobianMeasurement(const DeformationAnalysis& analysis, const Eigen::MatrixXi& triangles,
                                    int quantity);

// The colour range of a quantity. LogDiverging: lo < 1 < hi, 1 at the centre of the map, log scale on each side;
// Viridis: linear from lo to hi.
struct ColorRange {
  double lo = 1, hi = 1;
};
// The automatic range over the views showing the quantity (a compare view colours its panes alike), robust to a
// few extreme vertices: each view's kRangeQuantile-quantile, the widest of them. LogDiverging: [1/m, m] with log m
// the quantile of |log v| (at least 1 + 1e-3); Viridis: [autoLow, the quantile of v] (at least autoLow + 1e-3).
// Fold-overs (det J <= 0) have their own colour and take no part. With the largest value instead, BEM's fold-overs
// (det J from 0.002 to 513 near them) set a range in which every other pane looked white (issue 24, row 8); the few
// vertices beyond the range take the end colours and the legend counts them (verticesBeyond).
constexpr double kRangeQuantile = 0.98;
ColorRange sharedRange(const std::vector<const ViewMeasurement*>& views, const QuantityDescriptor& quantity);
// How many vertices of the views (not fold-overs, not NaN) lie outside `range`: drawn in the end colours.
long verticesBeyond(const std::vector<const ViewMeasurement*>& views, const ColorRange& range);
// Empty when `range` is usable for the scale, else what is wrong with it ("min must be below 1 ...").
std::string rangeProblem(const ColorRange& range, ColorScale scale);
// Where a value falls in the range, in [0, 1]; -1 for a fold-over (det J <= 0), -2 for NaN.
float colorCoordinate(double value, double detJ, const ColorRange& range, ColorScale scale);

// A typed range for a quantity (the panel's "fixed range"); unused while `fixed` is off.
struct RangeSetting {
  bool fixed = false;
  ColorRange range{0.5, 2.0};
};

// What each view shows, and how it is coloured.
struct ViewShow {
  int quantity = 0;  // index into quantityDescriptors()
  int other = -1;    // Difference: the view compared with (-1: the first other view)
};
struct ShowSettings {
  std::vector<ViewShow> views{ViewShow{}};  // per view; a view past the end shows what the last entry shows
  std::map<int, RangeSetting> ranges;       // by quantity index; absent: automatic

  const ViewShow& view(std::size_t v) const { return views[std::min(v, views.size() - 1)]; }
  void setAll(int quantity) { views.assign(1, ViewShow{quantity, -1}); }
  void setView(std::size_t v, int quantity, std::size_t viewCount);  // gives every view its own entry first
  // The view a Difference view v compares with among `viewCount` views; -1 when there is none.
  int otherView(std::size_t v, std::size_t viewCount) const;
  bool anyShown(std::size_t viewCount) const;  // some view shows something besides shading
  // Whether view v draws its quantity's legend: one legend per quantity, in the last view showing it.
  bool drawsLegend(std::size_t v, std::size_t viewCount) const;
  bool usesSource(QuantitySource source, std::size_t viewCount) const;
};

// --show: one quantity id for every view, or a comma-separated id per view ("detj,detj,difference");
// "field:VERTEX" shows the coordinate field of cage vertex VERTEX (returned in fieldVertex, else -1). Throws
// InputError(option, ...) naming the bad entry.
ShowSettings parseShow(const std::string& value, const std::string& option, int& fieldVertex);

// The range quantity `quantity` is drawn with: the fixed one when set and usable, else sharedRange over the
// measurements of the views that show it (`measured[v]` may be null).
ColorRange quantityRange(const ShowSettings& show, int quantity, const std::vector<const ViewMeasurement*>& measured);
// The measurements of the views that show `quantity` (`measured[v]` may be null).
std::vector<const ViewMeasurement*> viewsShowing(const ShowSettings& show, int quantity,
                                                 const std::vector<const ViewMeasurement*>& measured);
// What the fixed-range fields show: the typed range while "fixed" is ticked, else the range drawn, so that they never
// show a stale typed range and ticking "fixed" starts from what the legend says.
ColorRange rangeFieldsValue(const ShowSettings& show, int quantity, const ColorRange& drawn);

}  // namespace somicage::editor
