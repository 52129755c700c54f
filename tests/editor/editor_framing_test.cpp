// Framing (OrbitCamera::frame with a FrameRoom, frameAll) keeps the framed scene clear of the panes' overlays (the
// legend, the label and the numbers: ui/pane_overlays.h) and the selection's gizmo ring inside the pane, in 2D and
// 3D, with one and two panes. The checks project the framed box (or the scene's points) with the camera and look
// at pixels: whether any lies in an overlay's box, and, for the whole editor, in the boxes ImGui actually drew.
#include <gtest/gtest.h>

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "editor_test_support.h"
#include "headless_imgui.h"
#include "interaction/camera.h"
#include "interaction/gizmo.h"
#include "model/app_state.h"
#include "ui/layout.h"
#include "ui/pane_overlays.h"
#include "ui/quantity_overlay.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

// Points on the box's surface: a 9 x 9 grid on each face (its projection's hull is the projected box's).
std::vector<Eigen::Vector3d> boxSurface(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  std::vector<Eigen::Vector3d> points;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side)
      for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j) {
          Eigen::Vector3d t;
          t[axis] = side;
          t[(axis + 1) % 3] = i / 8.0;
          t[(axis + 2) % 3] = j / 8.0;
          points.push_back(lo + t.cwiseProduct(hi - lo));
        }
  return points;
}

bool inside(const ViewRect& r, const Eigen::Vector2d& p) {
  return p.x() > r.x && p.x() < r.x + r.width && p.y() > r.y && p.y() < r.y + r.height;
}

// The projected points of `world` in a width x height pane that fall in one of `boxes`, or outside the pane.
int pointsInBoxesOrOut(const OrbitCamera& c, const std::vector<Eigen::Vector3d>& world, double width, double height,
                       const std::vector<ViewRect>& boxes) {
  int bad = 0;
  for (const Eigen::Vector3d& p : world) {
    Eigen::Vector2d s;
    if (!c.project(p, width, height, s) || s.x() < 0 || s.y() < 0 || s.x() > width || s.y() > height) {
      ++bad;
      continue;
    }
    for (const ViewRect& r : boxes)
      if (inside(r, s)) {
        ++bad;
        break;
      }
  }
  return bad;
}

// How many of `boxes` the projected bounding box of [lo, hi] (of its eight corners) overlaps, plus one if it leaves
// the pane.
int boundingBoxHits(const OrbitCamera& c, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double width,
                    double height, const std::vector<ViewRect>& boxes) {
  Eigen::Vector2d min = Eigen::Vector2d::Constant(1e300), max = -min;
  for (int k = 0; k < 8; ++k) {
    Eigen::Vector2d s;
    if (!c.project(Eigen::Vector3d((k & 1) ? hi.x() : lo.x(), (k & 2) ? hi.y() : lo.y(), (k & 4) ? hi.z() : lo.z()),
                   width, height, s))
      return 1;
    min = min.cwiseMin(s);
    max = max.cwiseMax(s);
  }
  int hits = min.x() < 0 || min.y() < 0 || max.x() > width || max.y() > height;
  for (const ViewRect& r : boxes)
    hits += min.x() < r.x + r.width && max.x() > r.x && min.y() < r.y + r.height && max.y() > r.y;
  return hits;
}

// The overlays of a pane as the editor has them with a quantity shown: the label, three lines of numbers and the
// legend at its widest ("grey: undefined (outside the cage)", 34 glyphs) with its "beyond the ends" line.
std::vector<ViewRect> overlays(double width, double height) {
  const ViewRect pane{0, 0, width, height};
  return {labelBox(pane, 40 * kGlyphWidth), numbersBox(pane, 36 * kGlyphWidth, 3),
          legendBox(pane, 34 * kGlyphWidth, true)};
}

struct Case {
  const char* name;
  double width, height;  // one pane of the window (two panes: half the window)
  Eigen::Vector3d lo, hi;
};

const Case kCases[] = {
    // Fig. 5's star (a square box) in three 340 x 340 panes, Fig. 3's wide rectangle in two, and larger panes.
    {"square, 340 x 340 panes", 340, 340, Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1)},
    {"wide, 340 x 340 panes", 340, 340, Eigen::Vector3d(-1.75, -0.5, -0.05), Eigen::Vector3d(1.75, 0.5, 0.05)},
    {"square, one 1380 x 800 pane", 1380, 800, Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1)},
    {"square, two 690 x 800 panes", 690, 800, Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d(1, 1, 1)},
    {"tall, two 500 x 400 panes", 500, 400, Eigen::Vector3d(-0.4, -1.5, -0.4), Eigen::Vector3d(0.4, 1.5, 0.4)},
};

}  // namespace

TEST(EditorFraming, TheFontMetricsAreImGuis) {
  createHeadlessImGui(800, 600);
  ImGui::NewFrame();  // the frame's font is set here
  const ImVec2 size = ImGui::CalcTextSize("det J  (log scale)\nfold");
  EXPECT_EQ(size.x, 18 * kGlyphWidth);
  EXPECT_EQ(size.y, 2 * kFontHeight);
  EXPECT_EQ(textWidth("det J  (log scale)\nfold"), 18 * kGlyphWidth);
  EXPECT_EQ(ImGui::GetTextLineHeightWithSpacing(), kNumbersTop - kLabelTop - 2);  // where the numbers start
  ImGui::EndFrame();
  ImGui::DestroyContext();
}

TEST(EditorFraming, TheFramedBoxsProjectedBoundsMissTheOverlaysIn2DAnd3D) {
  int movedBack = 0;
  for (bool twoD : {true, false})
    for (const Case& k : kCases) {
      SCOPED_TRACE(std::string(k.name) + (twoD ? ", 2D" : ", 3D"));
      const std::vector<ViewRect> boxes = overlays(k.width, k.height);
      OrbitCamera c;
      c.setMode2D(twoD);
      if (!twoD) c.setState({Eigen::Vector3d::Zero(), 1.0, 0.5, 0.3});
      OrbitCamera plain = c;
      plain.frame(k.lo, k.hi, k.width / k.height);
      FrameRoom room;
      room.width = k.width;
      room.height = k.height;
      room.keepClear = boxes;
      c.frame(k.lo, k.hi, room);
      EXPECT_EQ(boundingBoxHits(c, k.lo, k.hi, k.width, k.height, boxes), 0);
      EXPECT_EQ(pointsInBoxesOrOut(c, boxSurface(k.lo, k.hi), k.width, k.height, boxes), 0);
      EXPECT_GE(c.state().distance, plain.state().distance * (1 - 1e-12));  // never closer than without the overlays
      if (c.state().distance > plain.state().distance * (1 + 1e-9)) {  // moved back for them: no farther than needed
        ++movedBack;
        OrbitCamera closer = c;
        closer.zoom(std::log(1.06) / -std::log(0.85));  // 6 % closer: past the fit's 5 % margin
        EXPECT_GT(boundingBoxHits(closer, k.lo, k.hi, k.width, k.height, boxes), 0);
      } else {
        EXPECT_EQ(boundingBoxHits(plain, k.lo, k.hi, k.width, k.height, boxes), 0);
      }
    }
  EXPECT_GE(movedBack, 4);  // the 340-pixel panes and the 500 x 400 ones, in 2D and 3D
  // Without the room (the framing before, which knew only the aspect), the square ran under the legend and the
  // numbers in Fig. 5's panes, in 2D and 3D.
  for (bool twoD : {true, false}) {
    OrbitCamera c;
    c.setMode2D(twoD);
    if (!twoD) c.setState({Eigen::Vector3d::Zero(), 1.0, 0.5, 0.3});
    c.frame(kCases[0].lo, kCases[0].hi, 1.0);
    EXPECT_GT(boundingBoxHits(c, kCases[0].lo, kCases[0].hi, 340, 340, overlays(340, 340)), 0);
    EXPECT_GT(pointsInBoxesOrOut(c, boxSurface(kCases[0].lo, kCases[0].hi), 340, 340, overlays(340, 340)), 0);
  }
}

TEST(EditorFraming, TheSelectionsGizmoRingStaysInsideThePane) {
  const double ring = GizmoLayout::kRingPixels;
  const Eigen::Vector3d lo(-1.75, -0.5, 0), hi(1.75, 0.5, 0), corner = lo;  // Fig. 3: cage vertex 0, bottom left
  for (bool twoD : {true, false}) {
    SCOPED_TRACE(twoD ? "2D" : "3D");
    OrbitCamera c;
    c.setMode2D(twoD);
    if (!twoD) c.setState({Eigen::Vector3d::Zero(), 1.0, 0.4, 0.2});
    FrameRoom room;
    room.width = 400;
    room.height = 400;
    room.hasPoint = true;
    room.point = corner;
    room.pointPixels = ring;
    c.frame(lo, hi, room);
    Eigen::Vector2d s;
    ASSERT_TRUE(c.project(corner, 400, 400, s));
    EXPECT_GE(std::min({s.x(), s.y(), 400 - s.x(), 400 - s.y()}), ring - 1e-9);
    EXPECT_EQ(pointsInBoxesOrOut(c, boxSurface(lo, hi), 400, 400, {}), 0);
    c.frame(lo, hi, 1.0);  // without the point: the ring ran off the pane
    ASSERT_TRUE(c.project(corner, 400, 400, s));
    EXPECT_LT(std::min({s.x(), s.y(), 400 - s.x(), 400 - s.y()}), ring);
  }
}

namespace {

// The boxes ImGui drew into the foreground list with the overlays' fill (20, 20, 24; alpha 190 the legend, 170 the
// label and numbers; 0 their anti-aliased fringe), one per run of vertices of that colour: each is one rectangle.
std::vector<ViewRect> drawnBoxes() {
  std::vector<ViewRect> boxes;
  const ImDrawList& list = *ImGui::GetForegroundDrawList();
  bool open = false;
  for (int v = 0; v < list.VtxBuffer.Size; ++v) {
    const ImDrawVert& p = list.VtxBuffer[v];
    const bool fill = p.col == IM_COL32(20, 20, 24, 190) || p.col == IM_COL32(20, 20, 24, 170) ||
                      p.col == IM_COL32(20, 20, 24, 0);
    if (!fill) {
      open = false;
      continue;
    }
    if (!open) boxes.push_back({p.pos.x, p.pos.y, 0, 0});
    open = true;
    ViewRect& b = boxes.back();
    const double x1 = std::max(b.x + b.width, static_cast<double>(p.pos.x)),
                 y1 = std::max(b.y + b.height, static_cast<double>(p.pos.y));
    b.x = std::min(b.x, static_cast<double>(p.pos.x));
    b.y = std::min(b.y, static_cast<double>(p.pos.y));
    b.width = x1 - b.x;
    b.height = y1 - b.y;
  }
  return boxes;
}

// Fig. 3's scene (the 2D demo, cage vertex 0's field at nu = 0 and 0.45, no panel) in two panes of `width` x `height`
// each, or the 3D demo's det J: framed by frameAll once measured, then drawn headless.
void showAndFrame(AppState& state, int dim, const std::vector<ViewRect>& panes) {
  state.view.compare = true;
  state.view.compareViews = {parseViewSpec("somigliana:nu=0", "--view"), parseViewSpec("somigliana:nu=0.45", "--view")};
  requestDemo(state, dim);
  std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);
  ASSERT_TRUE(out.has_value());
  installOutcome(state, std::move(*out));
  ASSERT_TRUE(updateDeformation(state));
  state.view.hideUi = dim == 2;
  state.view.panes = panes;
  if (dim == 2) state.input.selection.setIndices({0});
  state.view.quantities.show.setAll(quantityIndex(dim == 2 ? "field" : "detj", "test"));
  measureViews(state);
  waitUntilDone(state.jobs.measure);
  measureViews(state);
  ASSERT_NE(state.view.quantities.measurement(1), nullptr);
  frameAll(state);
}

}  // namespace

TEST(EditorFraming, FrameAllKeepsTheSceneClearOfTheLegendAndNumbersImGuiDraws) {
  for (int dim : {2, 3}) {
    SCOPED_TRACE(dim == 2 ? "2D, Fig. 3" : "3D, det J");
    createHeadlessImGui(680, 340);
    AppState state;
    const std::vector<ViewRect> panes = layoutViews(680, 340, 0, 0, 0, 2);
    showAndFrame(state, dim, panes);
    ImGui::NewFrame();
    drawQuantityOverlay(state, panes);
    const std::vector<ViewRect> drawn = drawnBoxes();
    EXPECT_EQ(drawn.size(), 3u);  // two panes' numbers and one legend
    for (std::size_t v = 0; v < panes.size(); ++v) {
      std::vector<ViewRect> local;
      for (const ViewRect& b : drawn)
        if (panes[v].contains(b.origin())) local.push_back({b.x - panes[v].x, b.y - panes[v].y, b.width, b.height});
      std::vector<Eigen::Vector3d> scene;
      const Eigen::MatrixXd& points = displayedPoints(state, v);
      for (Eigen::Index i = 0; i < points.rows(); ++i) scene.push_back(points.row(i).transpose());
      for (Eigen::Index i = 0; i < state.document.pose.rows(); ++i) {
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        p.head(state.document.pose.cols()) = state.document.pose.row(i).transpose();
        scene.push_back(p);
      }
      EXPECT_EQ(pointsInBoxesOrOut(state.view.camera, scene, panes[v].width, panes[v].height, local), 0)
          << "pane " << v;
      if (dim == 2) {  // the selected vertex's gizmo: its ring inside the pane
        Eigen::Vector2d s;
        ASSERT_TRUE(state.view.camera.project(scene[points.rows()], panes[v].width, panes[v].height, s));
        EXPECT_GE(std::min({s.x(), s.y(), panes[v].width - s.x(), panes[v].height - s.y()}),
                  GizmoLayout::kRingPixels - 1e-9);
      }
    }
    ImGui::EndFrame();
    ImGui::DestroyContext();
  }
}
