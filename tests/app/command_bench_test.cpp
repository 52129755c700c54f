// somicage bench, run as a process: --json prints one object with exactly the documented keys, and its numbers
// are consistent (exact integrals at round-off, the baseline slower and less accurate, frames timed per variant).
#include <cmath>

#include "base/cpu_dispatch.h"
#include "cli_test_support.h"

namespace somicage {
namespace {

using namespace somicage::test;

TEST(CliBench, JsonHasExactlyTheDocumentedKeys) {
  const RunResult r = runSomicage({"bench", "--mesh", dataFile("pyramid_mesh.obj"), "--cage", dataFile("cube_cage.obj"),
                                   "--frames", "3", "--repeat", "2", "--baseline-quadrature", "8", "--baseline-points",
                                   "5", "--threads", "1", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r;
  const Json json = JsonParser::parse(r.out);
  ASSERT_EQ(json.type, Json::Type::Object);
  const std::vector<std::string> keys = {"mesh_vertices",      "cage_vertices",
                                         "cage_faces",         "threads",
                                         "precompute_s",       "pou_max",
                                         "pou_median",         "baseline_quadrature",
                                         "baseline_points",    "baseline_speedup",
                                         "baseline_pou_max",   "deform_ms",
                                         "nu_update_ms",       "coord_bytes",
                                         "peak_rss_bytes",     "analyze_ms",
                                         "detj_updates_per_s", "gradient_precompute_s",
                                         "gradient_bytes",     "bem_factor_ms",
                                         "editor_measure_ms",  "editor_detj_updates_per_s",
                                         "phong_factor_ms",    "phong_volume_vertices",
                                         "phong_coord_bytes",  "cpu_kernels"};
  EXPECT_EQ(json.object.size(), keys.size());
  for (const std::string& key : keys) ASSERT_TRUE(json.has(key)) << key;
  EXPECT_EQ(json["mesh_vertices"].number, 5);
  EXPECT_EQ(json["cage_vertices"].number, 8);
  EXPECT_EQ(json["threads"].number, 1);
  EXPECT_EQ(json["cpu_kernels"].string, dispatchedKernelTarget());  // the copy this process runs too
  EXPECT_EQ(json["baseline_quadrature"].number, 8);
  EXPECT_EQ(json["baseline_points"].number, 5);
  EXPECT_LE(json["pou_max"].number, 1e-12);
  EXPECT_GT(json["baseline_speedup"].number, 1.0);  // 192 Gauss points per triangle against one closed form
  ASSERT_EQ(json["deform_ms"].type, Json::Type::Object);
  EXPECT_TRUE(json["deform_ms"].has("cpu_global") && json["deform_ms"].has("cpu_local"));
  EXPECT_TRUE(json["deform_ms"].has("cpu_stable"));
  EXPECT_TRUE(json["deform_ms"].has("cpu_bem"));
  EXPECT_GT(json["bem_factor_ms"].number, 0);
  EXPECT_TRUE(json["deform_ms"].has("cpu_phong"));
  EXPECT_GT(json["phong_factor_ms"].number, 0);
  EXPECT_EQ(json["phong_volume_vertices"].number, 9);  // the cube's star: its 8 corners and its centre
  // Phong's C as sparse rows: 16 (float value, int32 column) pairs per row, a row per point (two more per point
  // outside the cage), not 4 x 9 + 4 columns.
  EXPECT_GE(json["phong_coord_bytes"].number, 5 * 16 * 8);
  EXPECT_EQ(std::fmod(json["phong_coord_bytes"].number, 16 * 8), 0.0);
  EXPECT_GT(json["coord_bytes"].number, 0);
  EXPECT_GE(json["peak_rss_bytes"].number, json["coord_bytes"].number);
  ASSERT_EQ(json["analyze_ms"].type, Json::Type::Object);
  EXPECT_TRUE(json["analyze_ms"].has("cpu_global") && json["analyze_ms"].has("cpu_local"));
  EXPECT_NEAR(json["detj_updates_per_s"].number, 1e3 / json["analyze_ms"]["cpu_local"].number, 1e-6);
  // Three gradient matrices of C's point rows (the bench stores C in float), plus one frame's J and outputs.
  EXPECT_GE(json["gradient_bytes"].number, 3 * json["coord_bytes"].number);
}

// --method phong times Phong's frame and factorisation (the deform_ms.cpu_phong and phong_factor_ms) and no
// other method's besides Somigliana's; an unknown name is refused before any work.
TEST(CliBench, MethodPhongReportsItsFrameAndFactorisationOnly) {
  const RunResult r = runSomicage({"bench", "--mesh", dataFile("pyramid_mesh.obj"), "--cage", dataFile("cube_cage.obj"),
                                   "--method", "phong", "--frames", "2", "--repeat", "1", "--baseline-quadrature", "4",
                                   "--baseline-points", "2", "--threads", "1", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r;
  const Json json = JsonParser::parse(r.out);
  EXPECT_TRUE(json["deform_ms"].has("cpu_phong")) << r.out;
  EXPECT_GT(json["deform_ms"]["cpu_phong"].number, 0) << r.out;
  EXPECT_GT(json["phong_factor_ms"].number, 0) << r.out;
  for (const char* other : {"cpu_green", "cpu_mvc", "cpu_bem"}) EXPECT_FALSE(json["deform_ms"].has(other)) << other;
  const RunResult green = runSomicage({"bench", "--mesh", dataFile("pyramid_mesh.obj"), "--cage",
                                       dataFile("cube_cage.obj"), "--method", "green", "--frames", "2", "--repeat",
                                       "1", "--baseline-quadrature", "4", "--baseline-points", "2", "--json"});
  ASSERT_EQ(green.exitCode, 0) << green;
  EXPECT_EQ(green.out.find("phong"), std::string::npos) << "no volume mesh without phong\n" << green.out;
  const RunResult bad = runSomicage({"bench", "--mesh", dataFile("pyramid_mesh.obj"), "--cage",
                                     dataFile("cube_cage.obj"), "--method", "fong"});
  EXPECT_EQ(bad.exitCode, 2) << bad;
  EXPECT_NE(bad.err.find("--method"), std::string::npos) << bad;
}

// --scale-points N times one more precompute of N points made from the mesh's, and holds their C meanwhile: the peak
// RSS grows by at least 90 % of N rows of the mesh's C over the same run without the option (whose JSON has no scale
// keys: the exact key list above).
TEST(CliBench, ScalePointsPrecomputesThatManyPoints) {
  const auto run = [](const std::string& count) {
    const RunResult r = runSomicage({"bench", "--mesh", dataFile("pyramid_mesh.obj"), "--cage",
                                     dataFile("cube_cage.obj"), "--method", "green", "--frames", "1", "--repeat", "1",
                                     "--baseline-points", "0", "--scale-points", count, "--threads", "1", "--json"});
    EXPECT_EQ(r.exitCode, 0) << r;
    return JsonParser::parse(r.out);
  };
  const Json plain = run("0"), scaled = run("100000");
  EXPECT_FALSE(plain.has("scale_points"));
  EXPECT_EQ(scaled["scale_points"].number, 100000);
  EXPECT_GT(scaled["scale_precompute_s"].number, 0);
  const double rowBytes = scaled["coord_bytes"].number / scaled["mesh_vertices"].number;
  EXPECT_GE(scaled["peak_rss_bytes"].number - plain["peak_rss_bytes"].number, 0.9 * 100000 * rowBytes);
}

TEST(CliBench, MissingMeshIsBadInput) {
  const RunResult r = runSomicage({"bench", "--cage", dataFile("cube_cage.obj")});
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_NE(r.err.find("--mesh"), std::string::npos) << r;
}

}  // namespace
}  // namespace somicage
