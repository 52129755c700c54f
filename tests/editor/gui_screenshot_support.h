// What the screenshot tests share: running the real somicage executable under xvfb-run (Mesa llvmpipe), reading
// its PNG back, telling mesh pixels apart, and a small posed scene written on the fly.
//
// "Mesh pixels" are told apart by colour: the mesh is shaded in a warm tone (red > blue), while the
// background, the translucent cage and its handles are grey or blue (blue >= red).
#pragma once

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace gui_test {

namespace fs = std::filesystem;

inline const std::string kExe = SOMICAGE_EXE;
inline const std::string kXvfbRun = SOMICAGE_XVFB_RUN;
inline const std::string kModels = SOMICAGE_MODELS_DIR;

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;
  bool isMesh(int x, int y) const {
    const unsigned char* p =
        &rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4];
    return static_cast<int>(p[0]) > static_cast<int>(p[2]) + 12;
  }
  // Fraction of mesh pixels in the columns [x0, x1).
  double coverage(int x0, int x1) const {
    long n = 0;
    for (int y = 0; y < height; ++y)
      for (int x = x0; x < x1; ++x) n += isMesh(x, y);
    return static_cast<double>(n) / (static_cast<double>(x1 - x0) * height);
  }
  double coverage() const { return coverage(0, width); }
};

// Fraction of pixels where one image shows the mesh and the other does not (same-size column ranges).
inline double maskDifference(const Image& a, int ax0, const Image& b, int bx0, int columns) {
  long n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < columns; ++x) n += a.isMesh(ax0 + x, y) != b.isMesh(bx0 + x, y);
  return static_cast<double>(n) / (static_cast<double>(columns) * a.height);
}

// Fraction of pixels whose colour differs by more than `threshold` in some channel (same-size images).
inline double colourDifference(const Image& a, const Image& b, int threshold) {
  long n = 0;
  for (std::size_t i = 0; i + 3 < a.rgba.size(); i += 4) {
    bool differs = false;
    for (int c = 0; c < 3; ++c)
      differs |= std::abs(static_cast<int>(a.rgba[i + c]) - static_cast<int>(b.rgba[i + c])) > threshold;
    n += differs;
  }
  return static_cast<double>(n) / (static_cast<double>(a.width) * a.height);
}

inline fs::path outputDir() {
  const fs::path dir = SOMICAGE_TEST_TMP;
  fs::create_directories(dir);
  return dir;
}

inline std::string quote(const std::string& s) { return "'" + s + "'"; }

// Skips the test when no display can be had.
#define REQUIRE_DISPLAY()                                                                         \
  do {                                                                                            \
    if (kXvfbRun.empty() && std::getenv("DISPLAY") == nullptr)                                    \
      GTEST_SKIP() << "neither xvfb-run nor a DISPLAY is available (apt-get install xvfb xauth)"; \
  } while (0)

// Runs somicage with the arguments; returns its exit code, the output goes to log.
inline int runSomicage(const std::string& args, const std::string& name) {
  const std::string log = (outputDir() / (name + ".log")).string();
  std::string cmd;
  if (!kXvfbRun.empty()) cmd = quote(kXvfbRun) + " -a -s '-screen 0 1600x900x24' ";
  cmd += quote(kExe) + " " + args + " > " + quote(log) + " 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline std::string readLog(const std::string& name) {
  std::ifstream in(outputDir() / (name + ".log"));
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline Image screenshot(const std::string& args, const std::string& name) {
  const std::string png = (outputDir() / (name + ".png")).string();
  fs::remove(png);
  const int rc = runSomicage(args + " --screenshot " + quote(png), name);
  EXPECT_EQ(rc, 0) << readLog(name);
  Image img;
  int channels = 0;
  unsigned char* data = stbi_load(png.c_str(), &img.width, &img.height, &channels, 4);
  if (!data) {
    ADD_FAILURE() << "could not read " << png << "\n" << readLog(name);
    return img;
  }
  img.rgba.assign(data, data + static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height) * 4);
  stbi_image_free(data);
  return img;
}

// The range a --screenshot run printed for a quantity's legend ("legend detj: LO HI"); NaN when absent.
inline std::pair<double, double> legendRange(const std::string& log, const std::string& id = "detj") {
  const std::string key = "legend " + id + ": ";
  const std::size_t at = log.find(key);
  if (at == std::string::npos) return {NAN, NAN};
  char* end = nullptr;
  const double lo = std::strtod(log.c_str() + at + key.size(), &end);
  return {lo, std::strtod(end, nullptr)};
}

// Takes the screenshot and returns the legend range it printed for quantity `id`.
inline std::pair<double, double> screenshotLegend(const std::string& args, const std::string& name,
                                                  const std::string& id = "detj") {
  screenshot(args, name);
  return legendRange(readLog(name), id);
}

// A sphere mesh inside the cube cage [-1, 1]^3, and a pose that twists and shifts the top of the cage.
struct TestFiles {
  std::string mesh, cage, posed;
  // The editor's file arguments: MESH CAGE POSED-CAGE (quoted).
  std::string files(const std::string& posedCage) const {
    return quote(mesh) + " " + quote(cage) + " " + quote(posedCage);
  }
  std::string posedFiles() const { return files(posed); }
};

// `cage` (an OBJ) scaled by s about the origin, written to `path`: a uniform scale, det J = s^3 at every point.
inline std::string writeScaledCage(const std::string& cage, double s, const fs::path& path) {
  fs::create_directories(path.parent_path());
  std::ifstream in(cage);
  std::ofstream out(path);
  out.precision(17);
  for (std::string line; std::getline(in, line);) {
    double x, y, z;
    if (std::sscanf(line.c_str(), "v %lf %lf %lf", &x, &y, &z) == 3)
      out << "v " << s * x << " " << s * y << " " << s * z << "\n";
    else
      out << line << "\n";
  }
  return path.string();
}

inline TestFiles writeTestFiles() {
  const fs::path dir = outputDir();
  TestFiles f{(dir / "sphere.obj").string(), (dir / "cube_cage.obj").string(), (dir / "cube_cage_posed.obj").string()};
  {
    std::ofstream out(f.mesh);
    const int rings = 24, segments = 48;
    const double r = 0.6, pi = 3.14159265358979323846;
    out << "v 0 " << r << " 0\n";
    for (int i = 1; i < rings; ++i) {
      const double phi = pi * i / rings;
      for (int j = 0; j < segments; ++j) {
        const double theta = 2 * pi * j / segments;
        out << "v " << r * std::sin(phi) * std::cos(theta) << " " << r * std::cos(phi) << " "
            << r * std::sin(phi) * std::sin(theta) << "\n";
      }
    }
    out << "v 0 " << -r << " 0\n";
    auto idx = [&](int ring, int j) { return 2 + (ring - 1) * segments + (j % segments); };  // 1-based
    const int bottom = 2 + (rings - 1) * segments;
    for (int j = 0; j < segments; ++j) out << "f 1 " << idx(1, j + 1) << " " << idx(1, j) << "\n";
    for (int i = 1; i + 1 < rings; ++i) {
      for (int j = 0; j < segments; ++j) {
        out << "f " << idx(i, j) << " " << idx(i, j + 1) << " " << idx(i + 1, j + 1) << "\n";
        out << "f " << idx(i, j) << " " << idx(i + 1, j + 1) << " " << idx(i + 1, j) << "\n";
      }
    }
    for (int j = 0; j < segments; ++j)
      out << "f " << bottom << " " << idx(rings - 1, j) << " " << idx(rings - 1, j + 1) << "\n";
  }
  const double v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                          {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  const char* faces =
      "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n";
  {
    std::ofstream out(f.cage);
    for (const auto& p : v) out << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
    out << faces;
  }
  {
    std::ofstream out(f.posed);
    const double a = 1.0;  // radians of twist of the top face about y
    for (const auto& p : v) {
      double x = p[0], y = p[1], z = p[2];
      if (y > 0) {
        const double xr = std::cos(a) * x + std::sin(a) * z, zr = -std::sin(a) * x + std::cos(a) * z;
        x = xr + 0.6;
        z = zr;
        y += 0.3;
      }
      out << "v " << x << " " << y << " " << z << "\n";
    }
    out << faces;
  }
  return f;
}

}  // namespace gui_test
