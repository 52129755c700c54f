// The Fig. 8 demo (app/editor/model/fig8_demo.h) as the editor draws it under xvfb-run (Mesa llvmpipe): the Phong panes
// crease where the mesh crosses tetrahedra and the Somigliana pane does not, measured on the picture (not compared
// with a stored one); View > Show tetrahedra draws the posed tetrahedra on the Phong panes only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "gui_screenshot_support.h"

using namespace gui_test;

namespace {

// --demo fig8 has three panes side by side: Phong on the cage's star, Phong on CGAL's level 2, Somigliana local nu 0.
constexpr int kPanes = 3;
const std::string kFig8 = "--demo fig8 --hide-ui --size 1500x500";

const unsigned char* pixel(const Image& img, int x, int y) {
  return &img.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x)) *
                   4];
}

double luminance(const Image& img, int x, int y) {
  const unsigned char* p = pixel(img, x, y);
  return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
}

// Shading creases along the rows of a pane: the second difference of the luminance (8-bit levels) with step h = 2
// pixels, L(x - 2) - 2 L(x) + L(x + 2), at every pixel of the middle 40 % of the pane's columns (away from the bar's
// end caps, whose edges are creases of the mesh itself) that lies 6 pixels or more inside the mesh along its row
// (away from the silhouette). Smooth shading changes slowly (a few levels over tens of pixels: |d2| ~ 1); a C0 seam
// turns the normal within a triangle or two, a step of tens of levels over a few pixels.
struct Creases {
  long samples = 0;
  double fraction = 0.0;  // of the samples with |d2| > kCreaseLevels
};
constexpr int kStep = 2, kInside = 4;
constexpr double kCreaseLevels = 8.0;

Creases creases(const Image& img, int pane) {
  const int width = img.width / kPanes, x0 = pane * width;
  Creases c;
  long creased = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = x0 + width * 3 / 10; x < x0 + width * 7 / 10; ++x) {
      bool inside = true;
      for (int k = -kStep - kInside; k <= kStep + kInside && inside; ++k) inside = img.isMesh(x + k, y);
      if (!inside) continue;
      ++c.samples;
      const double d2 = luminance(img, x - kStep, y) - 2 * luminance(img, x, y) + luminance(img, x + kStep, y);
      creased += std::abs(d2) > kCreaseLevels;
    }
  c.fraction = c.samples ? static_cast<double>(creased) / static_cast<double>(c.samples) : 0.0;
  return c;
}

// Pixels of a colour class in a pane, and their bounding box.
struct Found {
  long count = 0;
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};
template <typename Test>
Found find(const Image& img, int pane, Test test) {
  const int width = img.width / kPanes;
  Found f;
  for (int y = 0; y < img.height; ++y)
    for (int x = pane * width; x < (pane + 1) * width; ++x) {
      const unsigned char* p = pixel(img, x, y);
      if (!test(static_cast<int>(p[0]), static_cast<int>(p[1]), static_cast<int>(p[2]))) continue;
      ++f.count;
      f.x0 = std::min(f.x0, x), f.y0 = std::min(f.y0, y), f.x1 = std::max(f.x1, x), f.y1 = std::max(f.y1, y);
    }
  return f;
}
// The tetrahedra's orange edges (editor_renderer.cpp: 0.95, 0.55, 0.15) in front of the mesh; the mesh's warm tone
// has r - b <= 80 in these pictures.
bool orange(int r, int, int b) { return r - b > 140; }
// The cage's blue edges in front of the mesh (cage_renderer.h: 0.15, 0.30, 0.75); its translucent faces have
// b - r ~ 30.
bool cageBlue(int r, int, int b) { return b - r > 80; }

}  // namespace

TEST(GuiFig8, ThePhongPanesCreaseAndTheSomiglianaPaneDoesNot) {
  REQUIRE_DISPLAY();
  const Image img = screenshot(kFig8 + " --hide-cage", "fig8");
  ASSERT_EQ(img.width, 1500);
  // Measured (llvmpipe, 2026-12-04): Phong star 9.2 %, Phong level 2 7.8 %, Somigliana 0.01 % (one pixel of 13,659,
  // |d2| at most 10 levels there); the bounds leave a factor 4 and 50.
  for (int pane = 0; pane < kPanes; ++pane) {
    const Creases c = creases(img, pane);
    SCOPED_TRACE("pane " + std::to_string(pane));
    std::printf("pane %d: %.4f of %ld pixels crease (|d2| > %g levels)\n", pane, c.fraction, c.samples, kCreaseLevels);
    ASSERT_GT(c.samples, 5000) << "the bar should fill the middle of the pane";
    if (pane < 2)
      EXPECT_GT(c.fraction, 0.02) << "Phong is C0 across tetrahedra: its shading should crease";
    else
      EXPECT_LT(c.fraction, 0.002) << "Somigliana's deformation is smooth: no creases";
  }
}

TEST(GuiFig8, ShowTetsDrawsThePosedTetrahedraOnThePhongPanesOnly) {
  REQUIRE_DISPLAY();
  const Image tets = screenshot(kFig8 + " --hide-cage --show-tets", "fig8_tets");
  const Image cage = screenshot(kFig8, "fig8_cage");
  ASSERT_EQ(tets.width, 1500);
  ASSERT_EQ(cage.width, 1500);
  const Found coarse = find(tets, 0, orange), fine = find(tets, 1, orange), smooth = find(tets, 2, orange);
  // Measured: 2.1 % and 8.9 % of the panes' pixels.
  EXPECT_GT(coarse.count, 2000) << "the star's edges";
  EXPECT_GT(fine.count, 2 * coarse.count) << "level 2 has many more edges than the star";
  EXPECT_EQ(smooth.count, 0) << "Somigliana has no tetrahedra";
  EXPECT_EQ(find(cage, 0, orange).count, 0) << "off by default";
  // The mesh's boundary is the posed cage: the wireframe's extent is the drawn cage's, to 8 pixels (the handles
  // cover the edges' ends). The rest cage is 0.6 lower in the middle (the arch, fig8_demo.h), 40 % of its height.
  for (int pane = 0; pane < 2; ++pane) {
    SCOPED_TRACE("pane " + std::to_string(pane));
    const Found wire = find(tets, pane, orange), outline = find(cage, pane, cageBlue);
    ASSERT_GT(outline.count, 500);
    EXPECT_NEAR(wire.x0, outline.x0, 8);
    EXPECT_NEAR(wire.x1, outline.x1, 8);
    EXPECT_NEAR(wire.y0, outline.y0, 8);
    EXPECT_NEAR(wire.y1, outline.y1, 8);
  }
}
