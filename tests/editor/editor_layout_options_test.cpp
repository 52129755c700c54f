// Viewport layout (equal widths in the compare view) and the editor command line.
#include <gtest/gtest.h>

#include <cmath>

#include "base/errors.h"
#include "editor_options.h"
#include "methods/method_descriptors.h"
#include "model/view_quantity.h"
#include "ui/layout.h"

using namespace somicage;
using namespace somicage::editor;

TEST(EditorLayout, CompareViewsHaveEqualWidthsAndFillTheArea) {
  const std::vector<ViewRect> v = layoutViews(1600, 900, 340, 19, 25, 3);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_EQ(v[0].x, 340);
  EXPECT_LE(std::abs(v[0].width - v[2].width), 2.0);
  EXPECT_EQ(v[0].width, v[1].width);
  EXPECT_EQ(v[2].x + v[2].width, 1600);
  for (const ViewRect& r : v) {
    EXPECT_EQ(r.y, 19);
    EXPECT_EQ(r.height, 900 - 19 - 25);
  }
  EXPECT_EQ(viewAt(v, Eigen::Vector2d(v[1].x + 1, 100)), 1);
  EXPECT_EQ(viewAt(v, Eigen::Vector2d(10, 100)), -1);  // over the panel
}

TEST(EditorLayout, TinyWindowsStillGivePositiveSizes) {
  for (const ViewRect& r : layoutViews(10, 10, 340, 19, 25, 3)) {
    EXPECT_GE(r.width, 1);
    EXPECT_GE(r.height, 1);
  }
}

TEST(EditorOptions, FilesAndParameters) {
  const EditorOptions o =
      parseEditorArgs({"m.obj", "c.obj", "p.obj", "--method", "green", "--nu", "inf", "--gamma", "1.5", "--compare",
                       "somigliana,green,mvc", "--screenshot", "out.png", "--size", "800x600", "--hide-ui", "--local"});
  EXPECT_EQ(o.meshPath, "m.obj");
  EXPECT_EQ(o.cagePath, "c.obj");
  EXPECT_EQ(o.posedPath, "p.obj");
  EXPECT_EQ(*o.method, methods::green());
  EXPECT_TRUE(std::isinf(o.parameters.at("nu")));
  EXPECT_EQ(o.parameters.at("gamma"), 1.5);
  // --local, the spelling kept from before the parameter table: the variant local, whose blend is 1.
  DeformParams p;
  setParameter(*findParameter("variant"), p, o.parameters.at("variant"));
  EXPECT_EQ(p.blend, 1.0);
  EXPECT_EQ(variantName(p), "local");
  EXPECT_EQ(o.views.size(), 3u);
  EXPECT_EQ(o.screenshotPath, "out.png");
  EXPECT_EQ(o.width, 800);
  EXPECT_EQ(o.height, 600);
  EXPECT_TRUE(o.hideUi);
}

TEST(EditorOptions, DemoByDefault) {
  const EditorOptions o = parseEditorArgs({"--screenshot", "x.png"});
  EXPECT_TRUE(o.meshPath.empty());
  EXPECT_EQ(o.demoDim, 3);
  EXPECT_EQ(parseEditorArgs({"--demo", "2d"}).demoDim, 2);
  EXPECT_FALSE(o.demoFig8);
  EXPECT_FALSE(o.showTets);
  const EditorOptions fig8 = parseEditorArgs({"--demo", "fig8", "--show-tets"});
  EXPECT_TRUE(fig8.demoFig8);
  EXPECT_EQ(fig8.demoDim, 3);
  EXPECT_TRUE(fig8.showTets);
}

// A mesh alone opens with a generated cage (scene.h): no cage path.
TEST(EditorOptions, MeshAloneHasNoCagePath) {
  const EditorOptions o = parseEditorArgs({"m.obj"});
  EXPECT_EQ(o.meshPath, "m.obj");
  EXPECT_TRUE(o.cagePath.empty());
}

TEST(EditorOptions, BadInputNamesTheOption) {
  auto sourceOf = [](std::vector<std::string> args) {
    try {
      parseEditorArgs(args);
    } catch (const InputError& e) {
      return e.source();
    }
    return std::string("no error");
  };
  EXPECT_EQ(sourceOf({"--nu", "0.7"}), "--nu");
  EXPECT_EQ(sourceOf({"--nu", "abc"}), "--nu");
  EXPECT_EQ(sourceOf({"--gamma", "-1"}), "--gamma");
  EXPECT_EQ(sourceOf({"--gamma", "1e4"}), "--gamma");  // beyond the engine's range (deformer.h: kGammaRange)
  EXPECT_EQ(sourceOf({"--blend", "2"}), "--blend");
  EXPECT_EQ(sourceOf({"--compare", "green"}), "--compare");
  EXPECT_EQ(sourceOf({"--compare", "green,foo"}), "--compare");
  EXPECT_EQ(sourceOf({"--size", "12"}), "--size");
  EXPECT_EQ(sourceOf({"--bogus"}), "--bogus");
  EXPECT_EQ(sourceOf({"a.obj", "b.obj", "c.obj", "d.obj"}), "command line");
  EXPECT_EQ(sourceOf({"--method"}), "--method");
  EXPECT_EQ(sourceOf({"--show", "volume"}), "--show");
  EXPECT_EQ(sourceOf({"--show"}), "--show");
  EXPECT_EQ(sourceOf({"--demo", "fig9"}), "--demo");
  EXPECT_EQ(sourceOf({"--method", "phong", "--tet-level", "7"}), "--tet-level");  // levels 0 to 4
  EXPECT_EQ(sourceOf({"--tet-level"}), "--tet-level");
  EXPECT_EQ(sourceOf({"--export-dialog"}), "--export-dialog");
}

// --export-dialog FILE (the user guide's screenshot of File > Export animation, tools/figures.py guide_export).
TEST(EditorOptions, ExportDialogTakesItsFile) {
  EXPECT_EQ(parseEditorArgs({"--export-dialog", "/tmp/a.glb", "m.obj"}).exportDialog, "/tmp/a.glb");
  EXPECT_EQ(parseEditorArgs({"m.obj"}).exportDialog, std::nullopt);
}

// The single view takes the methods' own options as `somicage deform` does (--tets FILE, --tet-level N), and the
// help lists every one the registry's methods declare.
TEST(EditorOptions, MethodOptionsForTheSingleView) {
  const EditorOptions o = parseEditorArgs({"--method", "phong", "--tet-level", "2", "--tets", "cube.mesh"});
  EXPECT_EQ(o.methodOptions, (MethodOptions{{"tet-level", "2"}, {"tets", "cube.mesh"}}));
  EXPECT_TRUE(parseEditorArgs({}).methodOptions.empty());
  for (Method m : allMethods())
    for (const MethodOptionSpec& option : m->options)
      EXPECT_NE(editorUsage().find(std::string("--") + option.key + " " + option.value), std::string::npos)
          << option.key;
}

TEST(EditorOptions, ShowNamesAQuantityDescriptor) {
  const EditorOptions o = parseEditorArgs({"--show", "detj", "--hide-cage"});
  EXPECT_STREQ(quantityDescriptor(o.show.view(0).quantity).id, "detj");
  EXPECT_EQ(quantityDescriptor(o.show.view(2).quantity).source, QuantitySource::Jacobian);  // every view
  EXPECT_TRUE(o.hideCage);
  EXPECT_EQ(parseEditorArgs({}).show.view(0).quantity, 0);  // shading only
  EXPECT_EQ(quantityDescriptors()[0].values, nullptr);
}
