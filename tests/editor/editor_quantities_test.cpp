// The views' quantities (view_quantity.h, measure_worker.h, quantity_overlay.h): colour ranges shared by the views
// that show a quantity and typed ranges, the difference view against independently deformed points, the coordinate
// field view against the coordinate columns, stale worker results dropped, the J bytes freed and counted.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <thread>

#include "analysis/coordinate_fields.h"
#include "base/errors.h"
#include "coordinates/somigliana_coordinates.h"
#include "editor_test_support.h"
#include "engine/engine.h"
#include "jobs/background_job.h"
#include "methods/method_descriptors.h"
#include "model/app_state.h"
#include "model/scene.h"
#include "ui/quantity_overlay.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

ViewMeasurement withValues(std::initializer_list<double> values) {
  ViewMeasurement m;
  m.values = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double v : values) m.values[i++] = v;
  return m;
}

// The demo scene of `dim` with every view's deformer installed.
void loadDemo(AppState& state, int dim, bool compare) {
  state.view.compare = compare;
  requestDemo(state, dim);
  std::optional<PrecomputeOutcome> out = waitForOutcome(state.jobs.precompute);
  ASSERT_TRUE(out.has_value());
  installOutcome(state, std::move(*out));
  ASSERT_TRUE(state.status.errors.empty()) << state.status.errors.front();
  ASSERT_TRUE(updateDeformation(state));
}

// Lifts the right end of the 3D demo cage (a bend) and deforms.
void bend(AppState& state, double lift) {
  Eigen::MatrixXd pose = state.document.pose;
  for (Eigen::Index i = 0; i < pose.rows(); ++i)
    if (pose(i, 0) > 2.0) pose(i, 1) += lift;
  setPose(state, pose);
  ASSERT_TRUE(updateDeformation(state));
}

int quantity(const char* id) { return quantityIndex(id, "test"); }

}  // namespace

TEST(EditorQuantities, ViewsShowingAQuantityShareItsRangeAndATypedRangeReplacesIt) {
  // Each view's values alike, so that its quantile is that value (the robust rule is tested below).
  const ViewMeasurement a = withValues({0.5, 0.5}), b = withValues({3.0, 3.0}), c = withValues({7.0, 7.0});
  ShowSettings show;
  show.setView(0, quantity("detj"), 3);
  show.setView(1, quantity("detj"), 3);
  show.setView(2, quantity("distortion"), 3);
  const std::vector<const ViewMeasurement*> views{&a, &b, &c};
  // det J over views 0 and 1: the largest ratio away from 1 is 3 (view 1), so [1/3, 3]; view 2's 7 is not det J.
  ColorRange r = quantityRange(show, quantity("detj"), views);
  EXPECT_DOUBLE_EQ(r.lo, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(r.hi, 3.0);
  r = quantityRange(show, quantity("distortion"), views);
  EXPECT_DOUBLE_EQ(r.lo, 1.0);
  EXPECT_DOUBLE_EQ(r.hi, 7.0);
  // A typed range replaces the shared one; one the scale cannot use (a ratio range not around 1) does not.
  show.ranges[quantity("detj")] = RangeSetting{true, ColorRange{0.5, 4.0}};
  r = quantityRange(show, quantity("detj"), views);
  EXPECT_EQ(r.lo, 0.5);
  EXPECT_EQ(r.hi, 4.0);
  // Each side of 1 on its own log scale: 0.5 -> 0, 1 -> 1/2, 2 -> 1/2 + log 2 / (2 log 4) = 3/4, 4 -> 1.
  EXPECT_NEAR(colorCoordinate(0.5, 1, r, ColorScale::LogDiverging), 0.0, 1e-7);
  EXPECT_NEAR(colorCoordinate(1.0, 1, r, ColorScale::LogDiverging), 0.5, 1e-7);
  EXPECT_NEAR(colorCoordinate(2.0, 1, r, ColorScale::LogDiverging), 0.75, 1e-7);
  EXPECT_NEAR(colorCoordinate(4.0, 1, r, ColorScale::LogDiverging), 1.0, 1e-7);
  EXPECT_EQ(colorCoordinate(2.0, -0.1, r, ColorScale::LogDiverging), -1.0f);  // a fold-over has its own colour
  show.ranges[quantity("detj")].range = ColorRange{2.0, 4.0};
  EXPECT_FALSE(rangeProblem(show.ranges[quantity("detj")].range, ColorScale::LogDiverging).empty());
  r = quantityRange(show, quantity("detj"), views);
  EXPECT_DOUBLE_EQ(r.hi, 3.0);  // the automatic range again
  EXPECT_FALSE(rangeProblem(ColorRange{3, 1}, ColorScale::Viridis).empty());
  EXPECT_TRUE(rangeProblem(ColorRange{0, 0.1}, ColorScale::Viridis).empty());

  // Issue 24, row 8: the fields showed a typed range after "fixed" was unticked; they show the range drawn then.
  const ColorRange drawn = quantityRange(show, quantity("detj"), views);
  show.ranges[quantity("detj")] = RangeSetting{true, ColorRange{0.5, 4.0}};
  EXPECT_EQ(rangeFieldsValue(show, quantity("detj"), drawn).hi, 4.0);
  show.ranges[quantity("detj")].fixed = false;
  EXPECT_DOUBLE_EQ(rangeFieldsValue(show, quantity("detj"), drawn).lo, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(rangeFieldsValue(show, quantity("detj"), drawn).hi, 3.0);
}

// Issue 24, row 8: comparing SC, GC and BEM, BEM's 145 fold-overs (det J from 0.00195 to 512.9 next to them) set the
// shared det J range, and the other panes looked white. The range is each view's 98th percentile of |log det J|, the
// widest: a pane whose det J lies log-uniformly in [1/1.5, 1.5] with 1 % of extreme vertices and some fold-overs
// sets [1/m, m] with m just below 1.5 (the percentile of a uniform |log| on [0, log 1.5], 1009 values with 10 above
// it), not 512.9; a second pane within [1/1.2, 1.2] then spans more than 0.2 of the map on each side of the centre.
TEST(EditorQuantities, TheSharedRangeIsRobustToAFewExtremeVerticesOfOnePane) {
  const int n = 1000;
  ViewMeasurement sc, bem;
  sc.values.resize(n);
  bem.values.resize(n + 20);
  bem.detJ.resize(n + 20);
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * i / (n - 1) - 1;  // -1 .. 1
    sc.values[i] = std::pow(1.2, t);
    bem.values[i] = std::pow(1.5, t);
  }
  for (int k = 0; k < 20; ++k) bem.values[n + k] = k < 5 ? 0.00195 : k < 10 ? 512.9 : -0.25 * k;  // 10 fold-overs
  bem.detJ = bem.values;
  sc.detJ = sc.values;
  ShowSettings show;
  show.setAll(quantity("detj"));
  const ColorRange r = quantityRange(show, quantity("detj"), {&sc, &bem});
  EXPECT_GT(r.hi, 1.47);
  EXPECT_LE(r.hi, 1.5);
  EXPECT_NEAR(r.lo * r.hi, 1.0, 1e-12);
  EXPECT_LE(colorCoordinate(1 / 1.2, 1, r, ColorScale::LogDiverging), 0.5 - 0.2);
  EXPECT_GE(colorCoordinate(1.2, 1, r, ColorScale::LogDiverging), 0.5 + 0.2);
  // The extreme ones take the end colours and are counted (the legend says so); fold-overs keep their own colour.
  EXPECT_EQ(colorCoordinate(512.9, 512.9, r, ColorScale::LogDiverging), 1.0f);
  EXPECT_EQ(colorCoordinate(0.00195, 0.00195, r, ColorScale::LogDiverging), 0.0f);
  const long beyond = verticesBeyond({&sc, &bem}, r);
  EXPECT_GE(beyond, 10);
  EXPECT_LE(beyond, 10 + 2 * n / 100);  // the bulk's top 2 % at most
  // The same for a magnitude (viridis): the largest 1 % of one view leave the top of the range.
  ViewMeasurement dist;
  dist.values = Eigen::VectorXd::LinSpaced(n, 1.0, 3.0);
  dist.values.tail(10).setConstant(1e6);
  show.setAll(quantity("distortion"));
  const ColorRange d = quantityRange(show, quantity("distortion"), {&dist});
  EXPECT_EQ(d.lo, 1.0);
  EXPECT_GT(d.hi, 2.9);
  EXPECT_LE(d.hi, 3.0);
}

TEST(EditorQuantities, ShowParsesOnePerViewAndTheFieldVertex) {
  int vertex = -1;
  ShowSettings s = parseShow("detj,difference", "--show", vertex);
  EXPECT_EQ(s.view(0).quantity, quantity("detj"));
  EXPECT_EQ(s.view(1).quantity, quantity("difference"));
  EXPECT_EQ(s.view(2).quantity, quantity("difference"));  // past the end: as the last
  EXPECT_EQ(vertex, -1);
  s = parseShow("field:12", "--show", vertex);
  EXPECT_EQ(s.view(0).quantity, quantity("field"));
  EXPECT_EQ(vertex, 12);
  for (const char* bad : {"field:", "field:x", "field:-1", "detj,,area", "volume"}) {
    try {
      parseShow(bad, "--show", vertex);
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "--show") << bad;
    }
  }
}

namespace {

// The bounding-box diagonal of the rest cage, computed here.
double restCageDiameter(const Scene& scene) {
  Eigen::Vector3d lo, hi;
  bounds3(scene.restCage.vertices, lo, hi);
  return (hi - lo).norm();
}

// |x_v - x_w| / diameter per vertex from two deform calls made here; the largest, after checking m against it.
double expectDifference(const AppState& state, const ViewMeasurement* m, std::size_t v, std::size_t w) {
  EXPECT_NE(m, nullptr);
  if (!m) return 0;
  const std::vector<ViewSpec> views = state.views();
  const Eigen::MatrixXd a = state.model.deformers.at(views[v].method)->deform(state.document.pose, state.viewParams(v));
  const Eigen::MatrixXd b = state.model.deformers.at(views[w].method)->deform(state.document.pose, state.viewParams(w));
  const double diameter = restCageDiameter(*state.model.scene);
  EXPECT_EQ(m->values.size(), a.rows());
  // where hover picks the vertex: the view's mesh at the measured pose, whatever the CPU points of the device
  EXPECT_TRUE(m->points.rows() == a.rows() && (m->points - a).cwiseAbs().maxCoeff() < 1e-12);
  double largest = 0;
  for (Eigen::Index p = 0; p < a.rows() && p < m->values.size(); ++p) {
    const double expected = (a.row(p) - b.row(p)).norm() / diameter;
    EXPECT_NEAR(m->values[p], expected, 1e-12) << "vertex " << p;
    largest = std::max(largest, expected);
  }
  return largest;
}

}  // namespace

// The Somigliana view's difference to the Green view, measured on the worker, against both views deformed here
// over the cage's bounding-box diagonal; another pose measures it again.
TEST(EditorQuantities, DifferenceViewIsTheDistanceToTheOtherViewInCageDiameters) {
  AppState state;
  loadDemo(state, 3, true);
  bend(state, 0.6);
  state.view.quantities.show.setView(0, quantity("difference"), 3);
  state.view.quantities.show.views[0].other = 1;  // Green
  measureViews(state);
  EXPECT_EQ(state.view.quantities.measurement(0), nullptr);  // on the worker, not in this call
  waitForMeasurements(state);
  EXPECT_GT(expectDifference(state, state.view.quantities.measurement(0), 0, 1), 1e-3);  // the methods differ on a bend
  EXPECT_EQ(state.view.quantities.measurement(1), nullptr);  // the other views show shading only
  bend(state, -0.3);
  waitForMeasurements(state);
  EXPECT_GT(expectDifference(state, state.view.quantities.measurement(0), 0, 1), 1e-3);
  EXPECT_EQ(state.view.quantities.droppedStale, 0);
}

// With the in-place OpenGL device the UI thread's CPU points stay stale (the Renderer deforms): the difference is
// measured on the worker all the same, and nothing on the UI thread deforms on the CPU for it (cpuStale untouched).
TEST(EditorQuantities, DifferenceWithTheInPlaceOpenGlDeviceIsMeasuredOnTheWorker) {
  AppState state;
  loadDemo(state, 3, true);
  ASSERT_EQ(chooseDevice(state.model.devices, {cpuFrameDevice(), inPlaceDevice()}, std::nullopt, kInPlaceDevice, ""),
            "");
  bend(state, 0.6);
  const std::vector<std::size_t> stale = state.model.cpuStale;
  ASSERT_EQ(stale.size(), 3u);
  state.view.quantities.show.setView(2, quantity("difference"), 3);
  state.view.quantities.show.views[2].other = 0;  // the third method to the first
  waitForMeasurements(state);
  EXPECT_EQ(state.model.cpuStale, stale);
  EXPECT_GT(expectDifference(state, state.view.quantities.measurement(2), 2, 0), 1e-3);
}

// The field of a selected cage vertex (and face) is |T_i(x) n_i| (|K_j(x) n_j|) of the full coordinate matrix.
TEST(EditorQuantities, FieldViewIsTheNormOfTheSelectedElementsCoordinateColumns) {
  AppState state;
  loadDemo(state, 2, false);
  state.document.params.nu = 0.25;
  const int vertex = 4;
  state.input.selection.setIndices({vertex});
  state.view.quantities.show.setAll(quantity("field"));
  measureViews(state);
  EXPECT_TRUE(state.jobs.measure.busy() || state.jobs.measure.ready());
  waitUntilDone(state.jobs.measure);
  measureViews(state);
  const ViewMeasurement* m = state.view.quantities.measurement(0);
  ASSERT_NE(m, nullptr);
  const Scene& scene = *state.model.scene;
  const SomiglianaCoordinates all = computeSomiglianaCoordinates(scene.restCage, scene.meshVertices);
  const Eigen::MatrixXd field = vertexCoordinateField(all, scene.restCage, vertex, 0.25);
  int inside = 0;
  for (Eigen::Index p = 0; p < field.rows(); ++p) {
    if (all.winding[p] < 0.5) {
      EXPECT_TRUE(std::isnan(m->values[p]));
      continue;
    }
    ++inside;
    EXPECT_NEAR(m->values[p], field.row(p).norm(), 1e-12 * (1 + field.row(p).norm())) << "point " << p;
  }
  EXPECT_GT(inside, 100);
  // Face mode with a whole face selected: that face's K_j n_j.
  const int face = 2;
  state.input.elementMode = ElementMode::Face;
  state.input.selection.setIndices({scene.restCage.faces(face, 0), scene.restCage.faces(face, 1)});
  measureViews(state);
  waitUntilDone(state.jobs.measure);
  measureViews(state);
  const Eigen::MatrixXd faceField = faceCoordinateField(all, face, 0.25);
  m = state.view.quantities.measurement(0);
  ASSERT_NE(m, nullptr);
  for (Eigen::Index p = 0; p < faceField.rows(); p += 7)
    if (all.winding[p] >= 0.5) {
      EXPECT_NEAR(m->values[p], faceField.row(p).norm(), 1e-12 * (1 + faceField.row(p).norm()));
    }
}

// A result measured for a pose that is gone by the time it arrives is dropped, the current pose measured next; the
// installed det J is the current pose's. Turning the quantity off frees the gradients.
TEST(EditorQuantities, StaleWorkerResultsAreDroppedAndTheCurrentPoseIsMeasured) {
  AppState state;
  loadDemo(state, 3, false);
  bend(state, 0.4);
  state.view.quantities.show.setAll(quantity("detj"));
  measureViews(state);  // starts on the 0.4 bend
  ASSERT_TRUE(state.jobs.measure.busy() || state.jobs.measure.ready());
  bend(state, 0.4);  // the pose moves on while it runs
  waitUntilDone(state.jobs.measure);
  measureViews(state);
  EXPECT_EQ(state.view.quantities.droppedStale, 1);
  EXPECT_EQ(state.view.quantities.measurement(0), nullptr);
  ASSERT_TRUE(state.jobs.measure.busy() || state.jobs.measure.ready());  // measuring the current pose
  waitUntilDone(state.jobs.measure);
  measureViews(state);
  EXPECT_EQ(state.view.quantities.droppedStale, 1);
  const ViewMeasurement* m = state.view.quantities.measurement(0);
  ASSERT_NE(m, nullptr);
  EXPECT_TRUE(state.view.quantities.installed == measureKey(measureRequest(state)));
  // det J of the current pose (the 0.8 bend), not of the first one.
  const Scene& scene = *state.model.scene;
  const DeformationGradients gradients(*state.model.deformers.at(methods::somigliana()), scene.meshVertices);
  Eigen::MatrixXd positions, jacobians;
  gradients.evaluate(state.document.pose, state.document.params, positions, jacobians);
  double largest = 0;
  for (Eigen::Index p = 0; p < jacobians.rows(); ++p) {
    const Eigen::Matrix<double, 1, 9> row = jacobians.row(p);
    const Eigen::Matrix3d jt = Eigen::Map<const Eigen::Matrix3d>(row.data());  // row-major J read column-major: J^T
    if (!std::isfinite(jt(0, 0))) continue;
    EXPECT_NEAR(m->detJ[p], jt.determinant(), 1e-9 * std::abs(jt.determinant())) << "vertex " << p;
    largest = std::max(largest, std::abs(std::log(jt.determinant())));
  }
  EXPECT_GT(largest, 0.05);  // the bend changes volumes: the test sees something
  EXPECT_GT(state.jobs.measure.heldBytes(), 0u);
  const CageDeformer& deformer = *state.model.deformers.at(methods::somigliana());
  EXPECT_EQ(deformer.gradientIntegrations(), 1) << "three measurements at two poses: the gradients kept with C";
  EXPECT_NE(deformer.keptGradients(), nullptr) << "what an export takes without integrating";
  state.view.quantities.show.setAll(0);
  measureViews(state);
  EXPECT_EQ(state.jobs.measure.heldBytes(), 0u);
  EXPECT_EQ(deformer.keptGradients(), nullptr) << "freed from the deformer too";
  EXPECT_EQ(state.view.quantities.measurement(0), nullptr);
}

// The J bytes count in the memory check: with too little free memory the quantity is refused, with the estimate.
TEST(EditorQuantities, GradientsThatWouldNotFitAreRefusedWithTheirSize) {
  AppState state;
  loadDemo(state, 3, false);
  setenv("SOMICAGE_MEMORY_LIMIT_BYTES", "100000", 1);
  state.view.quantities.show.setAll(quantity("detj"));
  measureViews(state);
  waitUntilDone(state.jobs.measure);
  measureViews(state);
  unsetenv("SOMICAGE_MEMORY_LIMIT_BYTES");
  ASSERT_EQ(state.status.errors.size(), 1u);
  EXPECT_NE(state.status.errors.front().find("measuring the pose failed"), std::string::npos)
      << state.status.errors.front();
  EXPECT_NE(state.status.errors.front().find("free"), std::string::npos) << state.status.errors.front();
  EXPECT_EQ(state.view.quantities.show.view(0).quantity, 0);  // turned off
  EXPECT_EQ(state.view.quantities.measurement(0), nullptr);
}

// The worker pattern under the measurements: progress and stage are visible while a job runs, Cancel reaches it at
// its next report, and a new start cancels the running job and drops its outcome.
TEST(EditorBackgroundJob, CancelReachesTheJobAndANewStartDropsTheOldOutcome) {
  BackgroundJob<std::string> job;
  std::atomic<bool> running{false};
  job.start(
      [&](JobContext& context) {
        context.setStage("spinning");
        running = true;
        while (context.report(0.25)) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        return std::string("stopped");
      },
      1);
  while (!running) std::this_thread::yield();
  EXPECT_TRUE(job.busy());
  EXPECT_EQ(job.stage(), "spinning");
  EXPECT_FALSE(job.poll().has_value());  // nothing while it runs
  job.cancel();
  const std::optional<std::string> out = waitForOutcome(job);
  ASSERT_TRUE(out.has_value());
  EXPECT_EQ(*out, "stopped");
  EXPECT_EQ(job.progress(), 0.25);
  EXPECT_FALSE(job.busy());

  running = false;
  job.start(
      [&](JobContext& context) {
        running = true;
        while (context.report(0.5)) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        return std::string("superseded");
      },
      1);
  while (!running) std::this_thread::yield();
  job.start([](JobContext&) { return std::string("second"); }, 1);
  EXPECT_EQ(waitForOutcome(job).value_or(""), "second");  // the first one's outcome never shows
  EXPECT_FALSE(job.poll().has_value());
}

namespace {

// Runs the requested nu sweep on the worker and installs it, as the frame loop does.
void sweep(AppState& state) {
  sweepNuNow(state);
  measureViews(state);
  waitUntilDone(state.jobs.measure);
  measureViews(state);
  ASSERT_EQ(state.view.quantities.nuSweep.size(), 25u);
}

}  // namespace

// Issue 24, row 9: the plot said "(pose changed: sweep again)" after a click on it set nu (nothing it depends on had
// changed), and it stayed after another model was opened or compare was turned off. Now it is stale only when the
// pose or a parameter other than nu changed, and it goes with the scene and the compare toggle. (The 2D demo: each
// sweep runs five lines since issue 26, which on the 3D demo's 4,658 points took seconds.)
TEST(EditorNuSweep, ThePlotFollowsThePoseAndParametersNotNuAndGoesWithTheScene) {
  AppState state;
  loadDemo(state, 2, false);
  updateDeformation(state);
  sweep(state);
  EXPECT_TRUE(nuSweepCurrent(state));
  DeformParams p = state.document.params;
  p.nu = 0.3;  // what a click on the plot does
  setParams(state, p);
  updateDeformation(state);
  EXPECT_TRUE(nuSweepCurrent(state)) << "a new nu does not make the sweep stale";
  p.gamma = 1.5;
  setParams(state, p);
  EXPECT_FALSE(nuSweepCurrent(state)) << "gamma changes every point of the sweep";
  p.gamma = state.view.quantities.nuSweepParams.gamma;
  setParams(state, p);
  EXPECT_TRUE(nuSweepCurrent(state));
  // The named choices and the variant too (before issue 26 only gamma, blend and the traction fix were compared).
  DeformParams other = p;
  other.bulging = Bulging::Reference;
  setParams(state, other);
  EXPECT_FALSE(nuSweepCurrent(state)) << "another bulging convention";
  other = p;
  other.normals = NormalWeights::Angle;
  setParams(state, other);
  EXPECT_FALSE(nuSweepCurrent(state)) << "other normal weights";
  other = p;
  other.kind = VariantKind::Stable;  // the volume line is the panel's variant's
  setParams(state, other);
  EXPECT_FALSE(nuSweepCurrent(state)) << "another variant";
  setParams(state, p);
  EXPECT_TRUE(nuSweepCurrent(state));
  Eigen::MatrixXd moved = state.document.pose;
  moved.row(0).array() += 0.2;
  setPose(state, moved);
  EXPECT_FALSE(nuSweepCurrent(state)) << "another pose";

  sweep(state);
  EXPECT_TRUE(nuSweepCurrent(state));
  setCompare(state, false);  // off already: the plot stays
  EXPECT_FALSE(state.view.quantities.nuSweep.empty());
  setCompare(state, true);
  EXPECT_TRUE(state.view.quantities.nuSweep.empty()) << "compare turned on";
  sweep(state);  // of the panel's method, whose deformer the compare view keeps
  setCompare(state, false);
  EXPECT_TRUE(state.view.quantities.nuSweep.empty()) << "compare turned off";

  sweep(state);
  requestDemo(state, 3);
  installNextOutcome(state);
  EXPECT_TRUE(state.view.quantities.nuSweep.empty()) << "another scene";
}

// The seams view (Fig. 8): per vertex the largest jump of J across the tetrahedra's faces on its edges. Phong's J jumps
// there; Somigliana's is one function, so its view is 0 wherever defined; the shared legend spans Phong's jumps, and
// they are what analyze measures (prepareSeamJumps) for the same pose.
TEST(EditorQuantities, SeamsViewShowsPhongsJumpsAndNoneForSomigliana) {
  AppState state;
  state.view.compareViews = viewsOf({methods::somigliana(), methods::phong()});
  loadDemo(state, 3, true);
  bend(state, 0.6);
  state.view.quantities.show.setAll(quantity("seams"));
  measureViews(state);
  waitForMeasurements(state);
  const ViewMeasurement* smooth = state.view.quantities.measurement(0);
  const ViewMeasurement* phong = state.view.quantities.measurement(1);
  ASSERT_TRUE(smooth && phong);
  double smoothMax = 0, phongMax = 0;
  for (Eigen::Index i = 0; i < smooth->values.size(); ++i)
    if (std::isfinite(smooth->values[i])) smoothMax = std::max(smoothMax, smooth->values[i]);
  for (Eigen::Index i = 0; i < phong->values.size(); ++i)
    if (std::isfinite(phong->values[i])) phongMax = std::max(phongMax, phong->values[i]);
  EXPECT_LE(smoothMax, 1e-12);
  EXPECT_GT(phongMax, 1e-2);
  const ColorRange range = sharedRange({smooth, phong}, quantityDescriptor(quantity("seams")));
  EXPECT_EQ(range.lo, 0);
  EXPECT_EQ(range.hi, quantile(phong->values, kRangeQuantile));  // Phong's 98th percentile: the widest view's
  EXPECT_GT(range.hi, 0.1 * phongMax);

  const Scene& scene = *state.model.scene;
  std::vector<std::vector<int>> faces;
  for (Eigen::Index f = 0; f < scene.meshTriangles.rows(); ++f)
    faces.push_back({scene.meshTriangles(f, 0), scene.meshTriangles(f, 1), scene.meshTriangles(f, 2)});
  int found = 0;
  for (const auto& entry : state.model.deformers) {
    const CageDeformer& d = *entry.second;
    if (d.method() != methods::phong()) continue;
    const auto seams = prepareSeamJumps(d, scene.restCage, scene.meshVertices, faces, {}, "demo");
    EXPECT_EQ(quantile(seams->evaluate(state.document.pose, state.viewParams(1)).vertices, 1.0), phongMax);
    ++found;
  }
  EXPECT_EQ(found, 1);
}
