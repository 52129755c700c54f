// Headless screenshot tests: run the real somicage executable under xvfb-run (Mesa llvmpipe), read the PNG
// back, and check properties of the picture. They skip visibly when neither xvfb-run nor a display exists.
//
// The meshes' silhouettes are checked against where the editor's camera puts the mesh `somicage deform` makes (an
// independent front end), to a few percent of outline pixels, so that driver differences do not matter;
// gui_golden_screenshot_test.cpp compares whole pictures with references.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gui_screenshot_support.h"
#include "interaction/camera.h"
#include "io/obj_io.h"
#include "model/scene.h"

using namespace gui_test;

namespace {

// ---- silhouettes against an independent deformation ----
//
// Where a mesh must appear: its triangles filled at pixel centres as the editor's camera sees them, in its starting
// direction, framed on the box [lo, hi] (the editor frames the first view's deformed mesh and the posed cage at
// start: app_state.cpp frameAll). The mesh comes from `somicage deform` (another front end of the engine) or, at
// rest, from the mesh file itself, so a picture of the wrong pose, the wrong method or a mesh in the wrong place
// disagrees with it.
struct Box {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
  void add(const Eigen::MatrixXd& points) {
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
      const Eigen::Vector3d p = points.row(i).transpose();
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
};

std::vector<char> projectedMask(const somicage::PolygonMesh& mesh, const Box& frame, int width, int height) {
  somicage::editor::OrbitCamera camera;
  camera.frame(frame.lo, frame.hi, static_cast<double>(width) / height);
  std::vector<Eigen::Vector2d> p(static_cast<std::size_t>(mesh.vertices.rows()));
  for (Eigen::Index i = 0; i < mesh.vertices.rows(); ++i)
    camera.project(mesh.vertices.row(i).transpose(), width, height, p[static_cast<std::size_t>(i)]);
  std::vector<char> mask(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
  const auto edge = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, double x, double y) {
    return (b.x() - a.x()) * (y - a.y()) - (b.y() - a.y()) * (x - a.x());
  };
  for (const std::vector<int>& f : mesh.faces)
    for (std::size_t k = 1; k + 1 < f.size(); ++k) {
      const Eigen::Vector2d &a = p[static_cast<std::size_t>(f[0])], &b = p[static_cast<std::size_t>(f[k])],
                            &c = p[static_cast<std::size_t>(f[k + 1])];
      const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
      const int x1 = std::min(width - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
      const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
      const int y1 = std::min(height - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const double e0 = edge(a, b, x + 0.5, y + 0.5), e1 = edge(b, c, x + 0.5, y + 0.5),
                       e2 = edge(c, a, x + 0.5, y + 0.5);
          if ((e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0))
            mask[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] = 1;
        }
    }
  return mask;
}

// Of the pixels where the picture's columns [x0, x0 + width) show the mesh or the mask has it, the share where the
// two disagree (0: the same silhouette; 1: nothing in common).
double silhouetteMismatch(const Image& img, int x0, const std::vector<char>& mask, int width) {
  long either = 0, differ = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < width; ++x) {
      const bool shown = img.isMesh(x0 + x, y);
      const bool expected = mask[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                 static_cast<std::size_t>(x)] != 0;
      either += shown || expected;
      differ += shown != expected;
    }
  return either ? static_cast<double>(differ) / static_cast<double>(either) : 1.0;
}

// `somicage deform` of the test scene with `method` and extra options: the deformed mesh it writes.
somicage::PolygonMesh deformedByCli(const TestFiles& f, const std::string& method, const std::string& options) {
  const std::string out = (outputDir() / ("silhouette_" + method + ".obj")).string();
  const int rc = runSomicage("deform --cage " + quote(f.cage) + " --posed " + quote(f.posed) + " --mesh " +
                                 quote(f.mesh) + " --out " + quote(out) + " --method " + method + " " + options,
                             "silhouette_" + method);
  EXPECT_EQ(rc, 0) << readLog("silhouette_" + method);
  return somicage::loadMesh(out);
}

// Below this share the picture shows the expected silhouette: its outline pixels (antialiasing, the darkest shading
// where red no longer beats blue) disagree, measured 0.7-1.5 % on these scenes; another method's mesh of the same
// pose disagrees by 6.6-10.7 %, the rest mesh in place of the posed one by 58 %.
constexpr double kSameSilhouette = 0.04;

}  // namespace

TEST(GuiScreenshot, DemoIsNotBlank) {
  REQUIRE_DISPLAY();
  const Image full = screenshot("", "demo_ui");
  ASSERT_GT(full.width, 0);
  EXPECT_EQ(full.width, 1600);
  EXPECT_EQ(full.height, 900);
  const double withUi = full.coverage();
  EXPECT_GT(withUi, 0.03);
  EXPECT_LT(withUi, 0.6);

  // Without the UI and the cage, the demo at rest is its mesh where the camera framing the mesh and the cage puts it.
  const Image bare = screenshot("--hide-ui --hide-cage --size 800x600", "demo_bare");
  ASSERT_EQ(bare.width, 800);
  const somicage::editor::Scene demo = somicage::editor::makeDemoScene(3);
  somicage::PolygonMesh mesh;
  mesh.vertices = demo.meshVertices;
  for (Eigen::Index t = 0; t < demo.meshTriangles.rows(); ++t)
    mesh.faces.push_back({demo.meshTriangles(t, 0), demo.meshTriangles(t, 1), demo.meshTriangles(t, 2)});
  Box frame;
  frame.add(demo.meshVertices);
  frame.add(demo.restCage.vertices);
  const double mismatch = silhouetteMismatch(bare, 0, projectedMask(mesh, frame, 800, 600), 800);
  std::printf("demo silhouette mismatch %.4f\n", mismatch);
  EXPECT_LT(mismatch, kSameSilhouette);
  EXPECT_GT(bare.coverage(), 0.05) << "the demo mesh should cover a fair part of the view";
}

// The posed picture shows the mesh where `somicage deform` moves it, the rest picture where the file has it; the
// posed picture is far from the rest mesh's silhouette (so the check has power), and the same run twice draws the
// same pixels.
TEST(GuiScreenshot, PosedSilhouetteIsWhereDeformMovesTheMesh) {
  REQUIRE_DISPLAY();
  const TestFiles f = writeTestFiles();
  const std::string files = quote(f.mesh) + " " + quote(f.cage);
  const std::string view = " --hide-ui --hide-cage --size 640x480";
  const Image rest = screenshot(files + view, "sphere_rest");
  const Image posed = screenshot(files + " " + quote(f.posed) + view, "sphere_posed");
  ASSERT_EQ(rest.width, 640);
  ASSERT_EQ(posed.width, 640);
  const somicage::PolygonMesh restMesh = somicage::loadMesh(f.mesh);
  const somicage::PolygonMesh deformed = deformedByCli(f, "somigliana", "");
  Box restFrame, posedFrame;
  restFrame.add(restMesh.vertices);
  restFrame.add(somicage::loadMesh(f.cage).vertices);
  posedFrame.add(deformed.vertices);
  posedFrame.add(somicage::loadMesh(f.posed).vertices);
  const double atRest = silhouetteMismatch(rest, 0, projectedMask(restMesh, restFrame, 640, 480), 640);
  const double moved = silhouetteMismatch(posed, 0, projectedMask(deformed, posedFrame, 640, 480), 640);
  const double notMoved = silhouetteMismatch(posed, 0, projectedMask(restMesh, posedFrame, 640, 480), 640);
  std::printf("silhouette mismatch: rest %.4f, posed %.4f, posed against the rest mesh %.4f\n", atRest, moved,
              notMoved);
  EXPECT_LT(atRest, kSameSilhouette);
  EXPECT_LT(moved, kSameSilhouette);
  EXPECT_GT(notMoved, 3 * kSameSilhouette);
  // Rendering is deterministic: the same rest pose twice gives the same mask.
  const Image again = screenshot(files + view, "sphere_rest_again");
  EXPECT_LT(maskDifference(rest, 0, again, 0, rest.width), 1e-4);
}

// Three panes, three methods on one pose: each pane shows its own method's mesh as `somicage deform --method` makes
// it (one camera for all panes, framed on the first pane's mesh and the posed cage), closer to it than to either
// other method's.
TEST(GuiScreenshot, CompareViewShowsEachMethodsMesh) {
  REQUIRE_DISPLAY();
  const TestFiles f = writeTestFiles();
  const Image img = screenshot(
      f.posedFiles() + " --compare somigliana,green,mvc --nu 0.3 --gamma 1 --hide-ui --hide-cage --size 1200x400",
      "sphere_compare");
  ASSERT_EQ(img.width, 1200);
  const int w = img.width / 3;
  const std::vector<somicage::PolygonMesh> meshes{deformedByCli(f, "somigliana", "--nu 0.3 --gamma 1"),
                                                  deformedByCli(f, "green", ""), deformedByCli(f, "mvc", "")};
  Box frame;
  frame.add(meshes[0].vertices);
  frame.add(somicage::loadMesh(f.posed).vertices);
  std::vector<std::vector<char>> masks;
  for (const somicage::PolygonMesh& m : meshes) masks.push_back(projectedMask(m, frame, w, img.height));
  for (int v = 0; v < 3; ++v) {
    double mismatch[3];
    for (int m = 0; m < 3; ++m) mismatch[m] = silhouetteMismatch(img, v * w, masks[static_cast<std::size_t>(m)], w);
    std::printf("pane %d against somigliana %.4f, green %.4f, mvc %.4f\n", v, mismatch[0], mismatch[1], mismatch[2]);
    EXPECT_LT(mismatch[v], kSameSilhouette) << "pane " << v;
    for (int m = 0; m < 3; ++m)
      if (m != v) {
        EXPECT_LT(mismatch[v], mismatch[m]) << "pane " << v << " looks more like method " << m;
      }
  }
}

TEST(GuiScreenshot, FireHydrantCompareWithPanels) {
  REQUIRE_DISPLAY();
  const std::string dir = kModels + "/firehydrant/";
  if (!fs::exists(dir + "fireHydrant.obj")) GTEST_SKIP() << "shared models not found at " << kModels;
  const Image img =
      screenshot(quote(dir + "fireHydrant.obj") + " " + quote(dir + "fireHydrant_cages_triangulated.obj") + " " +
                     quote(dir + "fireHydrant_cages_triangulated_deformed.obj") +
                     " --compare somigliana,green,mvc --nu 0.3 --gamma 1",
                 "firehydrant_compare");
  ASSERT_GT(img.width, 0);
  // Each narrow pane is framed on the posed cage, which is much wider than the hydrant (measured 0.022).
  EXPECT_GT(img.coverage(), 0.012);
}

// The opengl device (in place: a compute shader writing the vertex buffers, normals included) draws what the cpu
// device draws: the same silhouette, and the same shading up to a few grey levels (float positions and normals on
// the GPU).
TEST(GuiScreenshot, OpenGlDeviceLooksLikeTheCpuDevice) {
  REQUIRE_DISPLAY();
  const TestFiles f = writeTestFiles();
  const std::string args = quote(f.mesh) + " " + quote(f.cage) + " " + quote(f.posed) +
                           " --compare somigliana,green --nu 0.3 --gamma 1 --local --hide-ui --size 960x480";
  const Image gpu = screenshot(args + " --device opengl", "sphere_posed_gpu");
  if (readLog("sphere_posed_gpu").find("device: opengl") == std::string::npos)
    GTEST_SKIP() << "no OpenGL 4.3 compute shaders here:\n" << readLog("sphere_posed_gpu");
  const Image cpu = screenshot(args + " --device cpu", "sphere_posed_cpu");
  ASSERT_NE(readLog("sphere_posed_cpu").find("device: cpu"), std::string::npos) << readLog("sphere_posed_cpu");
  ASSERT_GT(gpu.width, 0);
  ASSERT_EQ(gpu.width, cpu.width);
  ASSERT_EQ(gpu.height, cpu.height);
  // Framed with the posed cage included, the mesh fills less of each view (measured 0.027).
  EXPECT_GT(gpu.coverage(0, gpu.width / 2), 0.015);
  EXPECT_GT(gpu.coverage(gpu.width / 2, gpu.width), 0.015);
  EXPECT_LT(maskDifference(gpu, 0, cpu, 0, gpu.width), 1e-3);
  EXPECT_LT(colourDifference(gpu, cpu, 6), 2e-3);
  // And it moved with the cage (not the rest mesh).
  const Image rest = screenshot(
      quote(f.mesh) + " " + quote(f.cage) + " --compare somigliana,green --hide-ui --size 960x480 --device opengl",
      "sphere_rest_gpu");
  EXPECT_GT(maskDifference(rest, 0, gpu, 0, gpu.width), 0.01);
}

TEST(GuiScreenshot, BadFilesFailCleanly) {
  REQUIRE_DISPLAY();
  const int rc = runSomicage(
      "/nonexistent/mesh.obj /nonexistent/cage.obj --screenshot " + quote((outputDir() / "never.png").string()),
      "bad_files");
  EXPECT_EQ(rc, 2) << readLog("bad_files");
  EXPECT_NE(readLog("bad_files").find("nonexistent"), std::string::npos);
  EXPECT_FALSE(fs::exists(outputDir() / "never.png"));
}

TEST(GuiScreenshot, BadOptionsFailBeforeOpeningAWindow) {
  // No display needed: the command line is checked first.
  const std::string log = (outputDir() / "bad_option.log").string();
  const int status = std::system((quote(kExe) + " --nu 0.9 > " + quote(log) + " 2>&1").c_str());
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2);
  // An unknown device is named with the devices this executable offers (main.cpp: the CLI's list).
  const int device = std::system((quote(kExe) + " --device gpu > " + quote(log) + " 2>&1").c_str());
  EXPECT_EQ(WIFEXITED(device) ? WEXITSTATUS(device) : -1, 2);
  const std::string text = readLog("bad_option");
  EXPECT_NE(text.find("--device"), std::string::npos) << text;
  EXPECT_NE(text.find("'gpu'"), std::string::npos) << text;
  EXPECT_NE(text.find("cpu, opengl, cuda"), std::string::npos) << text;
}

// A device that cannot run here (CUDA in a build without it, or without an NVIDIA GPU) is refused with its reason
// and the CPU deforms: the frame is written, nothing crashes.
TEST(GuiScreenshot, UnusableDeviceFallsBackToTheCpu) {
  REQUIRE_DISPLAY();
  const TestFiles f = writeTestFiles();
  const fs::path png = outputDir() / "device_cuda.png";
  fs::remove(png);
  const int rc = runSomicage(quote(f.mesh) + " " + quote(f.cage) + " --device cuda --hide-ui --size 320x240 " +
                                 "--screenshot " + quote(png.string()),
                             "device_cuda");
  const std::string log = readLog("device_cuda");
  if (log.find("device: cuda") != std::string::npos) GTEST_SKIP() << "CUDA runs here: nothing to refuse";
  EXPECT_EQ(rc, 0) << log;
  EXPECT_TRUE(fs::exists(png)) << log;
  EXPECT_NE(log.find("--device cuda: "), std::string::npos) << log;
  EXPECT_NE(log.find("deforming on the CPU"), std::string::npos) << log;
  EXPECT_NE(log.find("device: cpu"), std::string::npos) << log;
}

// ---- the Show quantities (issue 12) ----
namespace {

// The fraction of the pixels in the centre half of the image that differ from the view background (the mesh,
// with --hide-cage), and of those how many satisfy `want`. The overlay (numbers top left, legend bottom right)
// lies outside that box.
template <class Want>
std::pair<double, double> centreMeshPixels(const Image& img, Want want) {
  const int bg[3] = {69, 71, 82};  // editor_renderer.cpp: kViewBackground
  long mesh = 0, good = 0, all = 0;
  for (int y = img.height / 4; y < 3 * img.height / 4; ++y)
    for (int x = img.width / 4; x < 3 * img.width / 4; ++x, ++all) {
      const unsigned char* p =
          &img.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x)) *
                    4];
      if (std::abs(p[0] - bg[0]) + std::abs(p[1] - bg[1]) + std::abs(p[2] - bg[2]) < 40) continue;
      ++mesh;
      good += want(p[0], p[1], p[2]);
    }
  return {static_cast<double>(mesh) / static_cast<double>(all),
          mesh ? static_cast<double>(good) / static_cast<double>(mesh) : 0.0};
}

}  // namespace

TEST(GuiScreenshot, DetJAtRestIsTheNeutralCentreOfTheMap) {
  REQUIRE_DISPLAY();
  const TestFiles f = writeTestFiles();
  const Image img = screenshot(
      quote(f.mesh) + " " + quote(f.cage) + " --show detj --hide-ui --hide-cage --size 640x480", "detj_rest");
  // det J = 1 everywhere: the diverging map's centre, grey (221, 221, 221), under grey shading stays neutral.
  const auto [coverage, neutral] =
      centreMeshPixels(img, [](int r, int g, int b) { return std::abs(r - g) <= 10 && std::abs(r - b) <= 10; });
  EXPECT_GT(coverage, 0.06);  // 0.10: the sphere, framed with its (hidden) cage clear of the legend and numbers
  EXPECT_GT(neutral, 0.99);
  const auto [lo, hi] = legendRange(readLog("detj_rest"));
  EXPECT_NEAR(hi, 1.0, 2e-3);  // the smallest range the legend takes, [1/1.001, 1.001]
  EXPECT_NEAR(lo * hi, 1.0, 1e-9);
}

// Issue 24, row 8: the fold-over legend was the det J colour bar from 0.999 to 1.001 (blue to red). It is two
// swatches now, the neutral grey and magenta: no blue and no red in the legend's corner (the mesh at rest is
// neutral, the cage hidden, the background grey).
TEST(GuiScreenshot, FoldOverLegendIsTwoSwatchesNotAColourBar) {
  REQUIRE_DISPLAY();
  const TestFiles f = writeTestFiles();
  const Image img = screenshot(
      quote(f.mesh) + " " + quote(f.cage) + " --show foldover --hide-ui --hide-cage --size 640x480", "foldover_legend");
  ASSERT_EQ(img.width, 640);
  int coloured = 0, magenta = 0;
  for (int y = 480 - 90; y < 480; ++y) {
    for (int x = 640 - 300; x < 640; ++x) {
      const unsigned char* p = &img.rgba[(static_cast<std::size_t>(y) * 640 + x) * 4];
      const int r = p[0], g = p[1], b = p[2];
      magenta += r > 150 && b > 150 && g < 60;
      coloured += (b > r + 60 && b > g + 40) || (r > b + 60 && r > g + 60);  // the map's blue or red end
    }
  }
  EXPECT_EQ(coloured, 0) << "a colour bar in the fold-over legend";
  EXPECT_GT(magenta, 50) << "no fold-over swatch";
}

TEST(GuiScreenshot, DetJOfAUniformScaleIsTheCubeOfTheScale) {
  REQUIRE_DISPLAY();
  const TestFiles f = writeTestFiles();
  const double s = 1.25;  // det J = s^3 = 1.953125 at every vertex
  const std::string scaled = f.files(writeScaledCage(f.cage, s, outputDir() / "cube_cage_scaled.obj"));
  const Image img = screenshot(scaled + " --show detj --hide-ui --hide-cage --size 640x480", "detj_scaled");
  const auto [lo, hi] = legendRange(readLog("detj_scaled"));
  EXPECT_NEAR(hi, s * s * s, 1e-6 * s * s * s);
  EXPECT_NEAR(lo, 1 / (s * s * s), 1e-6);
  // Every vertex at the top of the range: the map's red end (180, 4, 38), shaded.
  const auto [coverage, red] = centreMeshPixels(img, [](int r, int g, int b) { return r > g + 50 && r > b + 40; });
  EXPECT_GT(coverage, 0.06);  // 0.10, as at rest
  EXPECT_GT(red, 0.99);
  // Every triangle's area grows by s^2. 1e-4: the area ratio comes from positions, whose rounding-sized error (the
  // editor's interactive integration) is divided by triangles with edges of ~0.08.
  const auto [areaLo, areaHi] =
      screenshotLegend(scaled + " --show area --hide-ui --size 320x240", "area_scaled", "area");
  EXPECT_NEAR(areaHi, s * s, 1e-4 * s * s);
  EXPECT_NEAR(areaLo, 1 / (s * s), 1e-4);
}

TEST(GuiScreenshot, DetJLegendRangeIsWhatAnalyzeReports) {
  REQUIRE_DISPLAY();
  const TestFiles f = writeTestFiles();
  const auto [lo, hi] =
      screenshotLegend(f.posedFiles() + " --show detj --nu 0.3 --gamma 1 --hide-ui --size 640x480", "detj_posed");
  const std::string csv = (outputDir() / "detj_posed_fields.csv").string();
  ASSERT_EQ(runSomicage("analyze --cage " + quote(f.cage) + " --posed " + quote(f.posed) + " --mesh " + quote(f.mesh) +
                            " --nu 0.3 --gamma 1 --fields " + quote(csv),
                        "detj_posed_analyze"),
            0)
      << readLog("detj_posed_analyze");
  // analyze's det J per vertex (vertex,det_j,...): the legend is [1/m, m] with log m the 98th percentile of
  // |log det J| (view_quantity.h, linear interpolation between order statistics), computed here from the CSV.
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<double> spread;
  double largest = 0;
  while (std::getline(in, line)) {
    const double d = std::strtod(line.c_str() + line.find(',') + 1, nullptr);
    if (d > 0) spread.push_back(std::abs(std::log(d))), largest = std::max(largest, spread.back());
  }
  ASSERT_GT(spread.size(), 1000u);
  std::sort(spread.begin(), spread.end());
  const double at = 0.98 * static_cast<double>(spread.size() - 1);
  const std::size_t k = static_cast<std::size_t>(at);
  const double m = std::exp(spread[k] + (at - static_cast<double>(k)) * (spread[k + 1] - spread[k]));
  // 1e-6: the editor precomputes with its interactive integration options, analyze with the default ones (they
  // differ by ~1e-7 here). The twist's most stretched 2 % lie beyond: the range is narrower than the extremes.
  EXPECT_NEAR(hi, m, 1e-6 * m);
  EXPECT_NEAR(lo, 1 / m, 1e-6);
  EXPECT_LT(std::log(hi), largest);
}

// File > Make cage... (--make-cage N): the candidate is drawn in green over the mesh in place of the scene's cage, and
// the green outline contains the mesh in the picture (the cage encloses it).
TEST(GuiScreenshot, MakeCageShowsTheCandidateAroundTheMesh) {
  REQUIRE_DISPLAY();
  const auto isPreview = [](const Image& img, int x, int y) {
    const unsigned char* p = &img.rgba[(static_cast<std::size_t>(y) * img.width + x) * 4];
    return p[1] > p[0] + 60 && p[1] > p[2] + 60;
  };
  struct Box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
    long count = 0;
    void add(int x, int y) {
      x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y), ++count;
    }
  };
  const Image plain = screenshot("--hide-ui --size 800x600", "make_cage_none");
  const Image made = screenshot("--hide-ui --size 800x600 --make-cage 40", "make_cage_40");
  ASSERT_GT(made.width, 0);
  Box green, mesh, plainGreen;
  for (int y = 0; y < made.height; ++y)
    for (int x = 0; x < made.width; ++x) {
      if (isPreview(made, x, y)) green.add(x, y);
      if (made.isMesh(x, y)) mesh.add(x, y);
      if (isPreview(plain, x, y)) plainGreen.add(x, y);
    }
  EXPECT_EQ(plainGreen.count, 0) << "nothing is green without the dialog";
  EXPECT_GT(green.count, 500) << "the candidate's edges";
  EXPECT_GT(mesh.count, 5000);
  EXPECT_LE(green.x0, mesh.x0);
  EXPECT_LE(green.y0, mesh.y0);
  EXPECT_GE(green.x1, mesh.x1);
  EXPECT_GE(green.y1, mesh.y1);
  const std::string log = readLog("make_cage_40");
  int faces = 0;
  const std::size_t at = log.find("make-cage: ");
  ASSERT_NE(at, std::string::npos) << log;
  ASSERT_EQ(std::sscanf(log.c_str() + at, "make-cage: %d faces", &faces), 1) << log;
  EXPECT_GE(faces, 12);
  EXPECT_LE(faces, 40);
}

// ---- per-view Show, fixed range, difference and field views (issue 12) ----
namespace {

// The "v x y z" rows of an OBJ.
std::vector<std::array<double, 3>> objVertices(const std::string& path) {
  std::vector<std::array<double, 3>> v;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::array<double, 3> p{};
    if (std::sscanf(line.c_str(), "v %lf %lf %lf", &p[0], &p[1], &p[2]) == 3) v.push_back(p);
  }
  return v;
}

}  // namespace

// The Green pane shows its distance to the Somigliana pane, the Somigliana pane shading only; the legend's top is
// the 98th percentile (view_quantity.h's robust range) of the distances of the two methods as `somicage deform`
// writes them, over the cage's diameter (2e-5: the editor stores its coordinates in float).
TEST(GuiScreenshot, DifferenceViewIsTheDistanceToTheOtherPaneInCageDiameters) {
  REQUIRE_DISPLAY();
  const TestFiles f = writeTestFiles();
  const Image img = screenshot(f.posedFiles() +
                                   " --compare somigliana,green --show shading,difference --hide-ui --hide-cage "
                                   "--size 800x400",
                               "difference");
  const auto [lo, hi] = legendRange(readLog("difference"), "difference");
  std::vector<std::vector<std::array<double, 3>>> deformed;
  for (const char* method : {"somigliana", "green"}) {
    const std::string out = (outputDir() / (std::string("difference_") + method + ".obj")).string();
    ASSERT_EQ(runSomicage("deform --cage " + quote(f.cage) + " --posed " + quote(f.posed) + " --mesh " + quote(f.mesh) +
                              " --out " + quote(out) + " --method " + method,
                          std::string("difference_") + method),
              0);
    deformed.push_back(objVertices(out));
  }
  ASSERT_EQ(deformed[0].size(), deformed[1].size());
  std::vector<double> distances;
  for (std::size_t i = 0; i < deformed[0].size(); ++i) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) d2 += std::pow(deformed[0][i][k] - deformed[1][i][k], 2);
    distances.push_back(std::sqrt(d2));
  }
  std::sort(distances.begin(), distances.end());
  const double at = 0.98 * static_cast<double>(distances.size() - 1);
  const std::size_t k = static_cast<std::size_t>(at);
  const double p98 = distances[k] + (at - static_cast<double>(k)) * (distances[k + 1] - distances[k]);
  const double diameter = 2 * std::sqrt(3.0);  // the cube [-1, 1]^3
  EXPECT_EQ(lo, 0.0);
  EXPECT_GT(p98 / diameter, 1e-3);  // the methods differ on this pose
  EXPECT_NEAR(hi, p98 / diameter, 2e-5);
  // The left pane is shaded (warm), the right one coloured by viridis (blue to yellow: not warm).
  EXPECT_GT(img.coverage(0, 400), 0.01);  // 0.015: framed clear of the legend and numbers (docs/editor.md, Framing)
  EXPECT_LT(img.coverage(400, 800), 0.5 * img.coverage(0, 400));
}

TEST(GuiScreenshot, FixedRangeIsTheTypedOneAndABadOneIsRefused) {
  REQUIRE_DISPLAY();
  const TestFiles f = writeTestFiles();
  const auto [lo, hi] =
      screenshotLegend(f.posedFiles() + " --show detj --range 0.5:2 --hide-ui --size 320x240", "fixed_range");
  EXPECT_EQ(lo, 0.5);
  EXPECT_EQ(hi, 2.0);
  EXPECT_EQ(runSomicage("--show detj --range 1.5:3 --screenshot x.png", "bad_range"), 2);
  EXPECT_NE(readLog("bad_range").find("--range"), std::string::npos) << readLog("bad_range");
}

// The field of a cage vertex: magnitudes from 0 (viridis), the mesh no longer in its shading colour; a vertex the
// cage does not have is refused with the cage's count.
TEST(GuiScreenshot, FieldViewOfACageVertex) {
  REQUIRE_DISPLAY();
  const TestFiles f = writeTestFiles();
  const Image img = screenshot(quote(f.mesh) + " " + quote(f.cage) +
                                   " --show field:3 --hide-ui --hide-cage "
                                   "--size 320x240",
                               "field");
  const auto [lo, hi] = legendRange(readLog("field"), "field");
  EXPECT_EQ(lo, 0.0);
  // Sum_i T_i = I inside (Eq. 9) and a cube corner's T_i is a fraction of it: |T_3 n_3| is well inside (0, 1.5).
  EXPECT_GT(hi, 0.01);
  EXPECT_LT(hi, 1.5);
  EXPECT_LT(img.coverage(), 0.02);
  EXPECT_EQ(runSomicage(quote(f.mesh) + " " + quote(f.cage) + " --show field:99 --screenshot x.png", "bad_field"), 2);
  EXPECT_NE(readLog("bad_field").find("the cage has 8 vertices"), std::string::npos) << readLog("bad_field");
}

// Paper Fig. 3 in 2D: the field of one polygon vertex as arrows over the inside at two nu, side by side (two
// screenshots, then two panes of one screenshot). The field changes with nu (Eq. 8a: alpha and beta), so the legends'
// tops differ.
TEST(GuiScreenshot, FieldArrowsIn2DAtTwoNu) {
  REQUIRE_DISPLAY();
  double top[2] = {0, 0};
  const char* nus[2] = {"-0.5", "0.45"};
  for (int k = 0; k < 2; ++k) {
    const std::string name = std::string("field2d_") + (k ? "b" : "a");
    const Image img = screenshot(std::string("--demo 2d --show field:2 --hide-ui --size 640x480 --nu ") + nus[k], name);
    EXPECT_GT(img.width, 0);
    top[k] = legendRange(readLog(name), "field").second;
    EXPECT_GT(top[k], 0.01) << readLog(name);
  }
  EXPECT_GT(std::abs(top[1] - top[0]), 0.05 * top[0]);
  // The same two nu as two panes of one method (--view): the shared legend spans both, so its top is the larger of
  // the single runs'; the panes differ where the same nu twice gives identical halves (rows between the labels and
  // the legend).
  auto halvesDiffer = [](const Image& img) {
    const int half = img.width / 2;
    long n = 0, total = 0;
    for (int y = 50; y < img.height - 100; ++y)
      for (int x = 0; x < half; ++x, ++total) {
        const unsigned char* a = &img.rgba[(static_cast<std::size_t>(y) * img.width + x) * 4];
        const unsigned char* b = a + static_cast<std::size_t>(half) * 4;
        bool differs = false;
        for (int c = 0; c < 3; ++c) differs |= std::abs(static_cast<int>(a[c]) - static_cast<int>(b[c])) > 24;
        n += differs;
      }
    return static_cast<double>(n) / static_cast<double>(total);
  };
  const std::string panes = "--demo 2d --show field:2 --hide-ui --size 1280x480 --view somigliana:nu=";
  const Image two = screenshot(panes + "-0.5 --view somigliana:nu=0.45", "field2d_panes");
  const Image same = screenshot(panes + "0.45 --view somigliana:nu=0.45", "field2d_same");
  ASSERT_EQ(two.width, 1280);
  EXPECT_NEAR(legendRange(readLog("field2d_panes"), "field").second, std::max(top[0], top[1]),
              1e-12 * std::max(top[0], top[1]));
  const double differ = halvesDiffer(two), control = halvesDiffer(same);
  std::printf("two-nu panes: %.4f of the pixels differ between the halves (same nu: %.4f)\n", differ, control);
  EXPECT_LT(control, 1e-4);
  EXPECT_GT(differ, 0.01);
}
