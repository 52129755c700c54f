// The compare view as a list of views (view_spec.h): each view a method with, optionally, its own nu / gamma /
// variant / traction fix. Positions and quantities per view against the deformer evaluated independently at that
// view's parameters; views without their own values follow the panel; --view parsing; the session's "views".
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "analysis/coordinate_fields.h"
#include "base/errors.h"
#include "base/json.h"
#include "coordinates/somigliana_coordinates.h"
#include "editor_options.h"
#include "editor_test_support.h"
#include "engine/session.h"
#include "methods/method_descriptors.h"
#include "model/app_state.h"
#include "model/fig8_demo.h"
#include "ui/quantity_overlay.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

ViewSpec somiglianaAt(double nu) { return ViewSpec{methods::somigliana(), {{"nu", nu}}, {}}; }
// A choice's value as a view holds it (parameter_schema.h): its index among the row's names.
double choiceValue(const char* key, const char* name) { return parseParameter(*findParameter(key), name, "test"); }

// The 3D demo with views: Somigliana at nu 0, Somigliana at nu 0.45, Somigliana with the panel's nu; bent.
void loadTwoNu(AppState& state) {
  state.view.compare = true;
  state.view.compareViews = {somiglianaAt(0.0), somiglianaAt(0.45), ViewSpec{methods::somigliana(), {}, {}}};
  state.document.params.nu = 0.2;
  openDemoScene(state, 3);
  ASSERT_EQ(state.model.deformers.size(), 1u);  // one precompute: nu never re-integrates
  Eigen::MatrixXd pose = state.document.pose;
  for (Eigen::Index i = 0; i < pose.rows(); ++i)
    if (pose(i, 0) > 2.0) pose(i, 0) += 1.0, pose(i, 1) += 0.6;  // stretch and lift the right end
  setPose(state, pose);
  ASSERT_TRUE(updateDeformation(state));
}

DeformParams withNu(DeformParams p, double nu) {
  p.nu = nu;
  return p;
}

double maxDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).cwiseAbs().maxCoeff(); }

// The signed volume of a closed triangle mesh: the sum of its triangles' tetrahedra from the origin.
double signedVolume(const Eigen::MatrixXd& x, const Eigen::MatrixXi& triangles) {
  double volume = 0;
  for (Eigen::Index f = 0; f < triangles.rows(); ++f) {
    const Eigen::Vector3d a = x.row(triangles(f, 0)), b = x.row(triangles(f, 1)), c = x.row(triangles(f, 2));
    volume += a.dot(b.cross(c)) / 6;
  }
  return volume;
}

std::string viewError(const std::vector<std::string>& args) {
  try {
    parseEditorArgs(args);
  } catch (const InputError& e) {
    EXPECT_EQ(e.source().rfind("--view", 0), 0u) << e.what();
    return e.what();
  }
  return "accepted";
}

}  // namespace

TEST(EditorViews, TwoViewsOfOneMethodDeformAtTheirOwnNuAndTheOthersFollowThePanel) {
  AppState state;
  loadTwoNu(state);
  const CageDeformer& deformer = *state.model.deformers.at(methods::somigliana());
  const Eigen::MatrixXd at0 = deformer.deform(state.document.pose, withNu(state.document.params, 0.0));
  const Eigen::MatrixXd at45 = deformer.deform(state.document.pose, withNu(state.document.params, 0.45));
  const Eigen::MatrixXd shared = deformer.deform(state.document.pose, state.document.params);
  EXPECT_LE(maxDifference(displayedPoints(state, 0), at0), 1e-12);
  EXPECT_LE(maxDifference(displayedPoints(state, 1), at45), 1e-12);
  EXPECT_LE(maxDifference(displayedPoints(state, 2), shared), 1e-12);
  EXPECT_GT(maxDifference(displayedPoints(state, 0), displayedPoints(state, 1)), 1e-3);  // nu shows
  // The panel's nu moves the view without its own only.
  setParams(state, withNu(state.document.params, -0.5));
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_LE(maxDifference(displayedPoints(state, 0), at0), 1e-12);
  EXPECT_LE(maxDifference(displayedPoints(state, 1), at45), 1e-12);
  EXPECT_LE(maxDifference(displayedPoints(state, 2), deformer.deform(state.document.pose, state.document.params)),
            1e-12);
  EXPECT_GT(maxDifference(displayedPoints(state, 2), shared), 1e-3);
  // The labels say which nu is the view's own.
  EXPECT_NE(viewLabel(state, 1).find("nu=0.45 (own)"), std::string::npos) << viewLabel(state, 1);
  EXPECT_NE(viewLabel(state, 2).find("nu=-0.50"), std::string::npos) << viewLabel(state, 2);
  EXPECT_EQ(viewLabel(state, 2).find("(own)"), std::string::npos) << viewLabel(state, 2);
}

TEST(EditorViews, AViewsOwnGammaVariantAndTractionFixReplaceThePanelsOnly) {
  ViewSpec view{
      methods::somigliana(), {{"gamma", 1.5}, {"variant", choiceValue("variant", "local")}, {"traction-fix", 0}}, {}};
  DeformParams shared;
  shared.nu = 0.3;
  shared.blend = 0.25;
  const DeformParams p = view.params(shared);
  EXPECT_EQ(p.nu, 0.3);
  EXPECT_EQ(p.gamma, 1.5);
  EXPECT_EQ(p.blend, 1.0);
  EXPECT_FALSE(p.tractionCorrection);
  EXPECT_EQ(p.bulging, Bulging::SolidAngle);  // the panel's, as the view has none of its own
  // The named choices (bulging, normals) are a view's own as the numbers are.
  view.own["bulging"] = choiceValue("bulging", "swept-volume");
  view.own["normals"] = choiceValue("normals", "angle");
  const DeformParams q = view.params(shared);
  EXPECT_EQ(q.bulging, Bulging::SweptVolume);
  EXPECT_EQ(q.normals, NormalWeights::Angle);
  EXPECT_EQ(q.gamma, 1.5);
  // Another method keeps only what it reads: Green reads none of them.
  const ViewSpec green = withMethod(view, methods::green());
  EXPECT_FALSE(green.overrides());
  EXPECT_NO_THROW(validateViewSpec(green, "test"));
}

// Issue 26: views compare the bulging conventions and normal weights side by side. Each pane's points are the
// deformer's at the panel's parameters with that pane's choice (deformed here, outside the editor), and the two
// conventions differ visibly at gamma = 2 on the bent demo.
TEST(EditorViews, TwoViewsOfOneMethodDeformWithTheirOwnBulgingAndNormals) {
  AppState state;
  state.view.compare = true;
  state.view.compareViews =
      parseEditorArgs({"--view", "somigliana", "--view", "somigliana:bulging=reference:normals=angle"}).views;
  state.document.params.gamma = 2.0;
  openDemoScene(state, 3);
  Eigen::MatrixXd pose = state.document.pose;
  for (Eigen::Index i = 0; i < pose.rows(); ++i)
    if (pose(i, 0) > 2.0) pose(i, 1) += 0.8;  // lift the right end: the cage bends, its normals turn
  setPose(state, pose);
  ASSERT_TRUE(updateDeformation(state));
  const CageDeformer& deformer = *state.model.deformers.at(methods::somigliana());
  DeformParams own = state.document.params;
  own.bulging = Bulging::Reference;
  own.normals = NormalWeights::Angle;
  EXPECT_LE(maxDifference(displayedPoints(state, 0), deformer.deform(state.document.pose, state.document.params)),
            1e-12);
  EXPECT_LE(maxDifference(displayedPoints(state, 1), deformer.deform(state.document.pose, own)), 1e-12);
  EXPECT_GT(maxDifference(displayedPoints(state, 0), displayedPoints(state, 1)), 1e-3);  // gamma^2 = 4 shows
  EXPECT_NE(viewLabel(state, 1).find("bulging reference (own)  normals angle (own)"), std::string::npos)
      << viewLabel(state, 1);
  EXPECT_EQ(viewLabel(state, 0).find("bulging"), std::string::npos) << viewLabel(state, 0);
  // The session keeps them.
  EXPECT_TRUE(sessionFromJson(sessionToJson(makeSession(state)), "s.json").compareViews == state.view.compareViews);
}

// det J and the volume change under each pane are those of its own nu: det J against the exact J evaluated here at
// that nu, the volume change against the signed volume of the mesh deformed at that nu.
TEST(EditorViews, EachViewsQuantitiesAreMeasuredAtItsOwnNu) {
  AppState state;
  loadTwoNu(state);
  state.view.quantities.show.setAll(quantityIndex("detj", "test"));
  waitForMeasurements(state);
  const Scene& scene = *state.model.scene;
  const CageDeformer& deformer = *state.model.deformers.at(methods::somigliana());
  const DeformationGradients gradients(deformer, scene.meshVertices);
  const double restVolume = signedVolume(scene.meshVertices, scene.meshTriangles);
  double changes[2];
  for (std::size_t v = 0; v < 2; ++v) {
    const double nu = v == 0 ? 0.0 : 0.45;
    const ViewMeasurement* m = state.view.quantities.measurement(v);
    ASSERT_NE(m, nullptr) << "view " << v;
    Eigen::MatrixXd positions, jacobians;
    gradients.evaluate(state.document.pose, withNu(state.document.params, nu), positions, jacobians);
    for (Eigen::Index p = 0; p < jacobians.rows(); p += 5) {
      const Eigen::Matrix<double, 1, 9> row = jacobians.row(p);
      const double det = Eigen::Map<const Eigen::Matrix3d>(row.data()).determinant();
      if (!std::isfinite(det)) continue;
      EXPECT_NEAR(m->detJ[p], det, 1e-9 * std::abs(det)) << "view " << v << " vertex " << p;
    }
    ASSERT_TRUE(m->closed);
    const Eigen::MatrixXd points = deformer.deform(state.document.pose, withNu(state.document.params, nu));
    // hover picks on the measured points: the mesh at this nu (to the editor's float storage of C, docs/engine.md)
    ASSERT_EQ(m->points.rows(), points.rows());
    EXPECT_LT((m->points - points).cwiseAbs().maxCoeff(), 1e-5 * cageDiameter(scene.restCage.vertices));
    const double deformed = signedVolume(points, scene.meshTriangles);
    EXPECT_NEAR(m->volumeChange, deformed / restVolume - 1, 1e-9) << "view " << v;
    changes[v] = m->volumeChange;
    std::printf("view %d (nu %.2f): volume change %+.4f %%\n", static_cast<int>(v), nu, 100 * m->volumeChange);
  }
  EXPECT_GT(std::abs(changes[0] - changes[1]), 1e-2);  // nu changes how much volume the pose gains
}

// Paper Fig. 3: the field |T_i(x) n_i| of one cage vertex in two panes at nu 0 and 0.45, each against the
// coordinate columns at its nu.
TEST(EditorViews, TheCoordinateFieldOfEachViewIsAtItsOwnNu) {
  AppState state;
  state.view.compare = true;
  state.view.compareViews = {somiglianaAt(0.0), somiglianaAt(0.45)};
  openDemoScene(state, 2);
  const int vertex = 0;
  state.input.selection.setIndices({vertex});
  state.view.quantities.show.setAll(quantityIndex("field", "test"));
  waitForMeasurements(state);
  const Scene& scene = *state.model.scene;
  const SomiglianaCoordinates all = computeSomiglianaCoordinates(scene.restCage, scene.meshVertices);
  double largestChange = 0;
  for (std::size_t v = 0; v < 2; ++v) {
    const ViewMeasurement* m = state.view.quantities.measurement(v);
    ASSERT_NE(m, nullptr) << "view " << v;
    const Eigen::MatrixXd field = vertexCoordinateField(all, scene.restCage, vertex, v == 0 ? 0.0 : 0.45);
    for (Eigen::Index p = 0; p < field.rows(); ++p) {
      if (all.winding[p] < 0.5) continue;
      EXPECT_NEAR(m->values[p], field.row(p).norm(), 1e-12 * (1 + field.row(p).norm())) << "view " << v;
      if (v == 1)
        largestChange =
            std::max(largestChange, std::abs(m->values[p] - state.view.quantities.measurement(0)->values[p]));
    }
  }
  EXPECT_GT(largestChange, 1e-3);  // nu changes the field
}

// One method at two nu: the difference between the panes (measured on the worker, each deformed at its own nu)
// against |x(nu 0) - x(nu 0.45)| / the rest cage's bounding-box diagonal from two deform calls made here; picking
// the third pane (the panel's nu 0.2) as the other one measures that instead.
TEST(EditorViews, TheDifferenceBetweenTwoViewsOfOneMethodIsAtEachViewsNu) {
  AppState state;
  loadTwoNu(state);
  const CageDeformer& deformer = *state.model.deformers.at(methods::somigliana());
  const Eigen::MatrixXd rest = state.model.scene->restCage.vertices;
  const double diameter = (rest.colwise().maxCoeff() - rest.colwise().minCoeff()).norm();
  for (int other : {1, 2}) {
    state.view.quantities.show.setView(0, quantityIndex("difference", "test"), 3);
    state.view.quantities.show.views[0].other = other;
    waitForMeasurements(state);
    const ViewMeasurement* m = state.view.quantities.measurement(0);
    ASSERT_NE(m, nullptr) << "to view " << other;
    const Eigen::MatrixXd a = deformer.deform(state.document.pose, withNu(state.document.params, 0.0));
    const Eigen::MatrixXd b =
        deformer.deform(state.document.pose, withNu(state.document.params, other == 1 ? 0.45 : 0.2));
    ASSERT_EQ(m->values.size(), a.rows());
    double largest = 0;
    for (Eigen::Index p = 0; p < a.rows(); ++p) {
      const double expected = (a.row(p) - b.row(p)).norm() / diameter;
      EXPECT_NEAR(m->values[p], expected, 1e-12) << "to view " << other << ", vertex " << p;
      largest = std::max(largest, expected);
    }
    EXPECT_GT(largest, 1e-3) << "to view " << other;  // nu shows
  }
}

TEST(EditorViews, ViewOptionGivesEachViewItsOwnParameters) {
  const EditorOptions o = parseEditorArgs({"--demo", "2d", "--view", "somigliana:nu=0", "--view",
                                           "somigliana:nu=0.45:gamma=2:variant=local:traction=off", "--view", "mvc"});
  ASSERT_EQ(o.views.size(), 3u);
  EXPECT_TRUE(o.views[0] == somiglianaAt(0.0));
  EXPECT_TRUE(
      o.views[1] ==
      (ViewSpec{methods::somigliana(),
                {{"nu", 0.45}, {"gamma", 2.0}, {"variant", choiceValue("variant", "local")}, {"traction-fix", 0}},
                {}}));
  EXPECT_TRUE(o.views[2] == (ViewSpec{methods::mvc(), {}, {}}));
  EXPECT_TRUE(
      parseEditorArgs({"--view", "somigliana:normals=angle:bulging=swept-volume", "--view", "green"}).views[0] ==
      (ViewSpec{methods::somigliana(),
                {{"bulging", choiceValue("bulging", "swept-volume")}, {"normals", choiceValue("normals", "angle")}},
                {}}));
  EXPECT_TRUE(parseEditorArgs({"--view", "somigliana:nu=-inf", "--view", "green"}).views[0] ==
              somiglianaAt(-std::numeric_limits<double>::infinity()));
  // A method's own options (method.h): views of Phong with their own tetrahedral mesh level.
  const EditorOptions t = parseEditorArgs({"--view", "phong:tet-level=2:nu=0.3", "--view", "phong"});
  EXPECT_EQ(t.views[0].options, (MethodOptions{{"tet-level", "2"}}));
  EXPECT_EQ(t.views[0].value("nu"), 0.3);
  EXPECT_TRUE(t.views[1].options.empty());
  // --compare is the list of views without their own values.
  const EditorOptions c = parseEditorArgs({"--compare", "somigliana,green"});
  EXPECT_TRUE(c.views == viewsOf({methods::somigliana(), methods::green()}));
}

TEST(EditorViews, BadViewOptionsNameWhatIsWrong) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--view", "somigliana:nu=0.7", "--view", "green"}, "out of range"},
      {{"--view", "somigliana:nu=abc", "--view", "green"}, "'abc' is not a number"},
      {{"--view", "somigliana:gamma=-1", "--view", "green"}, "gamma"},
      {{"--view", "somigliana:variant=middle", "--view", "green"},
       "variant: 'middle' is not a choice (use global, local, affine or stable"},
      {{"--view", "somigliana:traction=yes", "--view", "green"}, "traction: 'yes' is not on or off"},
      {{"--view", "somigliana:nu", "--view", "green"}, "expected KEY=VALUE"},
      {{"--view", "somigliana:nu=0:nu=0.1", "--view", "green"}, "'nu' given twice"},
      {{"--view", "somigliana:color=red", "--view", "green"},
       "unknown key 'color' in 'somigliana:color=red' (expected variant, blend, nu, gamma, traction, corotational, "
       "bulging, normals)"},
      {{"--view", "somigliana:bulging=squared", "--view", "green"},
       "bulging: 'squared' is not a choice (use solid-angle, reference, swept-volume or polygon"},
      {{"--view", "somigliana:normals=angle:normals=area", "--view", "green"}, "'normals' given twice"},
      {{"--view", "green:normals=angle", "--view", "somigliana"}, "green does not read normals"},
      {{"--view", "somigliana:tet-level=2", "--view", "green"}, "unknown key 'tet-level'"},
      {{"--view", "phong:level=2", "--view", "green"},
       "(expected variant, blend, nu, gamma, traction, corotational, bulging, normals, or tets, tet-level)"},
      {{"--view", "phong:tet-level=1:tet-level=2", "--view", "green"}, "'tet-level' given twice"},
      // The level is checked as the option is read, not at the precompute that makes the tetrahedra.
      {{"--view", "phong:tet-level=7", "--view", "green"},
       "phong tet-level: '7' is not a tetrahedral mesh level (use a whole number from 0 (coarse) to 4)"},
      {{"--view", "phong:tet-level=fine", "--view", "green"},
       "phong tet-level: 'fine' is not a tetrahedral mesh level"},
      {{"--view", "harmonic", "--view", "green"}, "unknown method 'harmonic'"},
      {{"--view", "green:nu=0.3", "--view", "somigliana"}, "green does not read nu"},
      {{"--view", "bem:nu=0.5", "--view", "somigliana"}, "bem nu: the boundary element method cannot use nu = 0.5"},
      {{"--view", "somigliana:nu=0"}, "one view given"},
      {{"--view", "mvc", "--view", "mvc", "--view", "mvc", "--view", "mvc"}, "at most 3 views"},
      {{"--compare", "somigliana,green", "--view", "mvc"}, "given with --compare"},
  };
  for (const auto& [args, expected] : cases) {
    const std::string message = viewError(args);
    EXPECT_NE(message.find(expected), std::string::npos) << args[1] << ": " << message;
  }
}

TEST(EditorViews, SessionKeepsTheViewsExactlyAndReadsOldSessions) {
  Session a;
  a.compare = true;
  a.compareViews = {somiglianaAt(1.0 / 3.0),
                    ViewSpec{methods::somigliana(),
                             {{"nu", -std::numeric_limits<double>::infinity()},
                              {"gamma", 0.1 + 0.2},
                              {"variant", choiceValue("variant", "global")},
                              {"traction-fix", 1},
                              {"bulging", choiceValue("bulging", "reference")},
                              {"normals", choiceValue("normals", "angle")}},
                             {}},
                    ViewSpec{methods::phong(), {}, {{"tet-level", "2"}, {"tets", "a \"b\".mesh"}}}};
  const Session b = sessionFromJson(sessionToJson(a), "s.json");
  ASSERT_EQ(b.compareViews.size(), 3u);
  for (std::size_t v = 0; v < 3; ++v) EXPECT_TRUE(b.compareViews[v] == a.compareViews[v]) << "view " << v;
  // A session from before "views": its compareMethods, following the shared parameters.
  JsonValue old = parseJson(sessionToJson(a), "s.json");
  JsonValue withoutViews = JsonValue::object();
  for (const auto& [key, value] : old.members())
    if (key != "views") withoutViews.set(key, value);
  const Session c = sessionFromJson(withoutViews.dump(2), "s.json");
  EXPECT_TRUE(c.compareViews == viewsOf({methods::somigliana(), methods::somigliana(), methods::phong()}));
  // The state takes them over and gives them back.
  AppState state;
  state.view.compareViews = b.compareViews;
  EXPECT_TRUE(makeSession(state).compareViews == b.compareViews);
}

TEST(EditorViews, AMalformedViewsEntryIsRefusedNamingTheSessionFile) {
  Session a;
  a.compareViews = viewsOf({methods::somigliana(), methods::green()});
  const std::string good = sessionToJson(a);
  const std::string entry = "{\n      \"method\": \"green\"\n    }";
  ASSERT_NE(good.find(entry), std::string::npos) << good;
  const std::vector<std::pair<std::string, std::string>> cases{
      {"{\"method\": \"green\", \"nu\": 0.3}", "\"views\" entry 1: green does not read nu"},
      {"{\"method\": \"somigliana\", \"nu\": 2}", "\"views\" entry 1: somigliana nu: Poisson ratio"},
      {"{\"method\": \"somigliana\", \"nu\": \"x\"}",
       "\"views\" entry 1: \"nu\" must be a value in (-1, 0.5), or inf / -inf"},
      {"{\"method\": \"somigliana\", \"variant\": \"mid\"}",
       "\"views\" entry 1: \"variant\" must be global, local, affine or stable"},
      {"{\"method\": \"somigliana\", \"colour\": 1}", "\"views\" entry 1 has an unknown field \"colour\""},
      {"{\"method\": \"somigliana\", \"bulging\": \"squared\"}",
       "\"views\" entry 1: \"bulging\" must be solid-angle, reference, swept-volume or polygon"},
      {"{\"method\": \"green\", \"normals\": \"angle\"}", "\"views\" entry 1: green does not read normals"},
      {"{\"method\": \"phong\", \"options\": 2}", "\"views\" entry 1: field \"options\" must be an object"},
      {"{\"method\": \"phong\", \"options\": {\"tet-level\": 2}}", "\"tet-level\" is not one"},
      {"{\"method\": \"green\", \"options\": {\"tet-level\": \"2\"}}", "green has no option tet-level"},
      {"{\"nu\": 0}", "\"views\" entry 1 needs \"method\""},
      {"{\"method\": \"harmonic\"}", "unknown method \"harmonic\""},
      {"3", "\"views\" entry 1 must be an object"},
  };
  for (const auto& [replacement, expected] : cases) {
    std::string text = good;
    text.replace(text.find(entry), entry.size(), replacement);
    try {
      sessionFromJson(text, "my_session.json");
      ADD_FAILURE() << replacement << " accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "my_session.json");
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << replacement << ": " << e.what();
    }
  }
  std::string one = good;
  const std::size_t first = one.find("{\n      \"method\": \"somigliana\"\n    },");
  ASSERT_NE(first, std::string::npos);
  one.erase(first, one.find('{', first + 1) - first);
  try {
    sessionFromJson(one, "my_session.json");
    ADD_FAILURE() << "one view accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"views\" must be an array of 2 to 3 views"), std::string::npos) << e.what();
  }
}

TEST(EditorViews, AddingAndRemovingViewsKeepsTwoToThree) {
  AppState state;
  state.view.compare = true;
  setCompareViews(state, {somiglianaAt(0.0)});  // one: refused
  EXPECT_TRUE(state.view.compareViews == viewsOf(defaultCompareMethods()));
  setCompareViews(state, {somiglianaAt(0.0), somiglianaAt(0.45), ViewSpec{methods::mvc(), {}, {}}});
  ASSERT_EQ(state.views().size(), 3u);
  state.view.quantities.show.setView(2, quantityIndex("detj", "test"), 3);
  removeCompareView(state, 1);
  ASSERT_EQ(state.views().size(), 2u);
  EXPECT_TRUE(state.views()[1] == (ViewSpec{methods::mvc(), {}, {}}));
  EXPECT_EQ(state.view.quantities.show.view(1).quantity,
            quantityIndex("detj", "test"));                                          // its Show choice moved with it
  removeCompareView(state, 0);                                                       // two stay
  EXPECT_EQ(state.views().size(), 2u);
  EXPECT_EQ(state.deformerKeys().size(), 2u);
}

// The single view (no compare) has the method's own options too: the panel's tetrahedra (setMethodOptions) and a
// session's top-level "methodOptions", which the editor writes and reads; a method without them ignores them.
TEST(EditorViews, TheSingleViewTakesTheMethodsOwnOptionsFromThePanelAndSessions) {
  AppState state;
  state.document.method = methods::phong();
  openDemoScene(state, 3);
  const int cageVertices = state.model.scene->restCage.numVertices();
  ASSERT_EQ(state.model.deformers.size(), 1u);
  EXPECT_EQ(state.model.deformers.begin()->second->volumeMesh()->numVertices(), cageVertices + 1) << "the star";
  setMethodOptions(state, {{"tet-level", "1"}});
  installNextOutcome(state);
  ViewSpec level1{methods::phong(), {}, {{"tet-level", "1"}}};
  EXPECT_TRUE(state.views() == std::vector<ViewSpec>{level1});
  ASSERT_TRUE(hasDeformer(state, deformerKey(level1)));
  EXPECT_GT(state.model.deformers.at(deformerKey(level1))->volumeMesh()->numVertices(), cageVertices + 1) << "CGAL's";
  EXPECT_NE(viewLabel(state, 0).find("tet-level 1"), std::string::npos) << viewLabel(state, 0);
  // A session keeps them at its top level and gives them back.
  const Session saved = sessionFromJson(sessionToJson(makeSession(state)), "s.json");
  EXPECT_EQ(saved.methodOptions, (MethodOptions{{"tet-level", "1"}}));
  AppState reopened;
  applySession(reopened, saved);
  installNextOutcome(reopened);  // the session's views are set with its scene
  EXPECT_TRUE(reopened.views() == std::vector<ViewSpec>{level1});
  // Somigliana has no such option: its view and sessions have none.
  setMethod(state, methods::somigliana());
  installNextOutcome(state);
  EXPECT_TRUE(state.views().front().options.empty());
  EXPECT_TRUE(makeSession(state).methodOptions.empty());
}

// Views that differ in a method option (the Fig. 8 demo's coarse and finer tetrahedra) have deformers of their own,
// each made with its options: the star (no tet-level, one Steiner vertex) and CGAL's level 1; views with equal
// options share one.
TEST(EditorViews, ViewsWithTheirOwnMethodOptionsHaveTheirOwnDeformers) {
  AppState state;
  ViewSpec star{methods::phong(), {}, {}}, level1 = star, level1AtNu = star;
  level1.options["tet-level"] = "1";
  level1AtNu.options["tet-level"] = "1";
  level1AtNu.own["nu"] = 0.3;
  state.view.compare = true;
  state.view.compareViews = {star, level1, level1AtNu};
  openDemoScene(state, 3);
  ASSERT_EQ(state.model.deformers.size(), 2u);
  const CageDeformer& a = *state.model.deformers.at(DeformerKey(methods::phong()));
  const CageDeformer& b = *state.model.deformers.at(deformerKey(level1));
  EXPECT_EQ(a.volumeMesh()->numVertices(), state.model.scene->restCage.numVertices() + 1) << "the star";
  EXPECT_GT(b.volumeMesh()->numVertices(), a.volumeMesh()->numVertices()) << "CGAL's mesh";
  EXPECT_EQ(deformerKey(level1), deformerKey(level1AtNu));
  EXPECT_NE(viewLabel(state, 1).find("tet-level 1 (own)"), std::string::npos) << viewLabel(state, 1);
  // The panes show what their own deformers give.
  Eigen::MatrixXd pose = state.document.pose;
  for (Eigen::Index i = 0; i < pose.rows(); ++i) pose(i, 1) += 0.3 * pose(i, 0) * pose(i, 0);
  setPose(state, pose);
  ASSERT_TRUE(updateDeformation(state));
  EXPECT_LE(maxDifference(state.model.deformed[0], a.deform(pose, state.viewParams(0))), 1e-12);
  EXPECT_LE(maxDifference(state.model.deformed[1], b.deform(pose, state.viewParams(1))), 1e-12);
  EXPECT_GT(maxDifference(state.model.deformed[0], state.model.deformed[1]), 1e-3) << "two meshes, two deformations";
}

// The Fig. 8 demo opens posed (the opened state: nothing to undo, nothing unsaved) with its three panes and three
// deformers; its pose is a twist about x (x and the distance to the arched axis kept) plus the arch.
TEST(EditorViews, TheFig8DemoOpensTwistedWithPhongOnTwoMeshesBesideSomigliana) {
  AppState state;
  requestFig8Demo(state);
  installNextOutcome(state);
  ASSERT_TRUE(state.model.scene) << (state.status.errors.empty() ? "no scene" : state.status.errors.front());
  EXPECT_TRUE(state.view.compare);
  EXPECT_TRUE(state.views() == fig8Views());
  EXPECT_EQ(state.model.deformers.size(), 3u);
  EXPECT_FALSE(state.document.history.canUndo());
  EXPECT_FALSE(hasUnsavedChanges(state));
  const Eigen::MatrixXd& rest = state.model.scene->restCage.vertices;
  ASSERT_EQ(state.document.pose.rows(), rest.rows());
  const double half = rest.col(0).cwiseAbs().maxCoeff();
  double largestTurn = 0;
  for (Eigen::Index v = 0; v < rest.rows(); ++v) {
    const double t = rest(v, 0) / half, arch = kFig8ArchHeight * (1 - t * t);
    EXPECT_EQ(state.document.pose(v, 0), rest(v, 0));
    const Eigen::Vector2d before(rest(v, 1), rest(v, 2)),
        after(state.document.pose(v, 1) - arch, state.document.pose(v, 2));
    EXPECT_NEAR(after.norm(), before.norm(), 1e-12);
    const double turn = std::atan2(before.x() * after.y() - before.y() * after.x(), before.dot(after));
    EXPECT_NEAR(turn, kFig8TwistRadians * t, 1e-12) << "vertex " << v;
    largestTurn = std::max(largestTurn, std::abs(turn));
  }
  EXPECT_NEAR(largestTurn, kFig8TwistRadians, 1e-12);
  // The first pane's tetrahedra are the bar's star (no options of its own), the second CGAL's at the fine level.
  EXPECT_NE(viewLabel(state, 0).find("star tetrahedra"), std::string::npos) << viewLabel(state, 0);
  EXPECT_NE(viewLabel(state, 1).find(std::string("tet-level ") + kFig8FineTetLevel), std::string::npos)
      << viewLabel(state, 1);
  EXPECT_EQ(viewLabel(state, 1).find("star"), std::string::npos) << viewLabel(state, 1);
  EXPECT_EQ(viewLabel(state, 2).find("tetrahedra"), std::string::npos) << viewLabel(state, 2);
  // The opened session keeps the panes' options.
  EXPECT_TRUE(sessionFromJson(sessionToJson(makeSession(state)), "s.json").compareViews == fig8Views());
}
