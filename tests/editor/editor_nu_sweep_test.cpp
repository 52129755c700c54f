// The editor's nu sweep (the panel's "Sweep nu", measure_worker.h) against an independent front end: the same
// scene and pose written to OBJ files and measured by the somicage executable's `analyze --variant V --nu-sweep`,
// one process per Somigliana variant. The editor stores its coordinates in float and analyze in double, so the
// volume changes agree to float's rounding and the fold-over counts up to the few vertices whose det J is within
// that rounding of 0.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

#include "app/cli_test_support.h"
#include "base/json.h"
#include "core/test_shapes.h"
#include "deform/deform_choices.h"
#include "editor_test_support.h"
#include "io/obj_io.h"
#include "model/app_state.h"
#include "ui/quantity_overlay.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

// The 3D demo's cage (a bar of four box segments along x) around an ellipsoid of 642 vertices that nearly fills it:
// the demo's own mesh has 4,658, which made the four `analyze` runs take seconds each.
std::shared_ptr<const Scene> ellipsoidInBar() {
  auto scene = std::make_shared<Scene>(makeDemoScene(3));
  const Cage sphere = test::makeIcosphere(3);
  scene->meshVertices = sphere.vertices.rowwise().normalized() * Eigen::Vector3d(2.2, 0.65, 0.65).asDiagonal();
  scene->meshTriangles = sphere.faces;
  scene->name = "ellipsoid in the demo bar";
  return scene;
}

// The demo bar's cage twisted about its axis, 0.8 rad at its right end (linear in x), and bent up by 0.5 there:
// the local variant folds at high nu, the others do not (docs/engine.md, "The stable variant").
Eigen::MatrixXd twistedBar(const Eigen::MatrixXd& rest) {
  Eigen::MatrixXd pose = rest;
  const double right = rest.col(0).maxCoeff(), left = rest.col(0).minCoeff();
  for (Eigen::Index i = 0; i < pose.rows(); ++i) {
    const double t = (rest(i, 0) - left) / (right - left);
    const Eigen::Vector3d p = Eigen::AngleAxisd(0.8 * t, Eigen::Vector3d::UnitX()) * rest.row(i).transpose();
    pose.row(i) = p.transpose();
    pose(i, 1) += 0.5 * t * t;
  }
  return pose;
}

// somicage analyze's nu sweep of one variant: (nu, volume change, fold-overs) per entry.
std::vector<NuSweepEntry> analyzeSweep(const test::ScratchDir& dir, const std::string& variant) {
  const test::RunResult r =
      test::runSomicage({"analyze", "--cage", dir.file("rest.obj"), "--posed", dir.file("posed.obj"), "--mesh",
                         dir.file("mesh.obj"), "--variant", variant, "--nu-sweep", "-0.95:0.49:25", "--json"});
  EXPECT_EQ(r.exitCode, 0) << r;
  std::vector<NuSweepEntry> sweep;
  if (r.exitCode != 0) return sweep;
  const JsonValue json = parseJson(r.out, "analyze --json");
  EXPECT_EQ(json.find("variant")->asString(), variant);
  for (const JsonValue& e : json.find("nu_sweep")->items())
    sweep.push_back({e.find("nu")->asNumber(), e.find("volume_change")->asNumber(),
                     static_cast<int>(e.find("foldover_vertices")->asNumber())});
  return sweep;
}

}  // namespace

TEST(EditorNuSweep, EachVariantsFoldOverLineIsWhatAnalyzeCountsForThatVariant) {
  AppState state;
  requestScene(state, ellipsoidInBar());
  installNextOutcome(state);
  ASSERT_TRUE(state.model.scene) << (state.status.errors.empty() ? "no scene" : state.status.errors.front());
  const Scene& scene = *state.model.scene;
  setPose(state, twistedBar(scene.restCage.vertices));
  DeformParams p = state.document.params;
  p.kind = VariantKind::Stable;  // the panel's variant: its volume line is the stable variant's
  setParams(state, p);
  ASSERT_TRUE(updateDeformation(state));
  sweepNuNow(state);
  measureViews(state);
  ASSERT_TRUE(state.jobs.measure.busy()) << "the sweep runs on the worker";
  waitUntilDone(state.jobs.measure);
  measureViews(state);
  const ViewQuantities& q = state.view.quantities;
  ASSERT_EQ(q.nuSweep.size(), 25u);
  ASSERT_EQ(q.nuSweepVariants.size(), variantChoices().size());

  test::ScratchDir dir;
  saveObj(dir.file("rest.obj"), scene.restCage.vertices, cageTopology(scene.restCage));
  saveObj(dir.file("posed.obj"), state.document.pose, cageTopology(scene.restCage));
  PolygonMesh mesh;
  for (Eigen::Index f = 0; f < scene.meshTriangles.rows(); ++f)
    mesh.faces.push_back({scene.meshTriangles(f, 0), scene.meshTriangles(f, 1), scene.meshTriangles(f, 2)});
  saveObj(dir.file("mesh.obj"), scene.meshVertices, mesh);

  const int vertices = static_cast<int>(scene.meshVertices.rows());
  std::map<std::string, int> mostFolds;
  for (std::size_t k = 0; k < variantChoices().size(); ++k) {
    const std::string variant = variantChoices()[k].name;
    const VariantSweep& line = q.nuSweepVariants[k];
    EXPECT_EQ(line.variant, variant);
    const std::vector<NuSweepEntry> reference = analyzeSweep(dir, variant);
    ASSERT_EQ(line.entries.size(), reference.size()) << variant;
    for (std::size_t i = 0; i < reference.size(); ++i) {
      const NuSweepEntry &e = line.entries[i], &r = reference[i];
      EXPECT_NEAR(e.nu, r.nu, 1e-12) << variant;
      EXPECT_NEAR(e.volumeChange, r.volumeChange, 1e-4) << variant << " at nu " << r.nu;
      // 0.2 % of the vertices: those whose det J is within float's rounding of 0.
      EXPECT_LE(std::abs(e.foldovers - r.foldovers), 1 + vertices / 500) << variant << " at nu " << r.nu;
      mostFolds[variant] = std::max(mostFolds[variant], r.foldovers);
    }
    if (variant == "stable") {  // the panel's variant: the volume line is its sweep
      for (std::size_t i = 0; i < reference.size(); ++i) EXPECT_EQ(q.nuSweep[i].foldovers, line.entries[i].foldovers);
    }
  }
  // The lines differ where the variants do: the local one folds at high nu on this pose, the others far less.
  EXPECT_GT(mostFolds["local"], vertices / 20);
  EXPECT_LT(mostFolds["stable"], mostFolds["local"] / 10);
  EXPECT_LT(mostFolds["global"], mostFolds["local"] / 10);
}
