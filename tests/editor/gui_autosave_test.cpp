// Crash recovery with the real executable under xvfb-run: --restore-autosave restores a crashed run's session
// without asking (the same picture as opening that session with --session), says so when there is nothing to
// restore, and a --screenshot run never touches the autosave files. Skips visibly without a display.
#include <gtest/gtest.h>
#include <stb_image.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "engine/session.h"
#include "interaction/camera.h"
#include "model/autosave.h"
#include "model/scene.h"

namespace {

namespace fs = std::filesystem;

const std::string kExe = SOMICAGE_EXE;
const std::string kXvfbRun = SOMICAGE_XVFB_RUN;

std::string quote(const std::string& s) { return "'" + s + "'"; }

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A scratch folder under the test output, used as XDG_CONFIG_HOME.
class ConfigHome {
 public:
  explicit ConfigHome(const std::string& name) : root_(fs::path(SOMICAGE_TEST_TMP) / name) {
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  const fs::path& root() const { return root_; }
  somicage::editor::AutosavePaths paths() const { return somicage::editor::autosavePaths(root_.c_str(), nullptr); }

 private:
  fs::path root_;
};

// Runs somicage under xvfb-run with XDG_CONFIG_HOME = config; returns the exit code; output in `log`.
int runSomicage(const ConfigHome& config, const std::string& args, std::string& log) {
  const fs::path logPath = config.root() / "run.log";
  std::string cmd = "XDG_CONFIG_HOME=" + quote(config.root().string()) + " ";
  if (!kXvfbRun.empty()) cmd += quote(kXvfbRun) + " -a -s '-screen 0 800x600x24' ";
  cmd += quote(kExe) + " " + args + " > " + quote(logPath.string()) + " 2>&1";
  const int status = std::system(cmd.c_str());
  log = readText(logPath);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Mesh pixels (warm: red > blue, see gui_screenshot_test.cpp) of a PNG; empty when it cannot be read.
std::vector<bool> meshMask(const fs::path& png) {
  int width = 0, height = 0, channels = 0;
  unsigned char* data = stbi_load(png.c_str(), &width, &height, &channels, 4);
  std::vector<bool> mask;
  if (!data) return mask;
  for (int i = 0; i < width * height; ++i) mask.push_back(static_cast<int>(data[4 * i]) > data[4 * i + 2] + 12);
  stbi_image_free(data);
  return mask;
}

double share(const std::vector<bool>& a, const std::vector<bool>& b, bool differing) {
  long n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += differing ? a[i] != b[i] : a[i];
  return a.empty() ? 0.0 : static_cast<double>(n) / static_cast<double>(a.size());
}

// The 2D demo, bent, framed the way the editor frames it: not the default (3D) picture.
somicage::Session crashedSession() {
  using namespace somicage::editor;
  const Scene demo = makeDemoScene(2);
  somicage::Session s;
  s.demoDim = 2;
  s.pose = demo.restCage.vertices;
  s.pose.col(1) += 0.3 * s.pose.col(0);
  OrbitCamera camera;
  camera.setMode2D(true);
  Eigen::Vector3d lo, hi;
  bounds3(demo.meshVertices, lo, hi);
  camera.frame(lo - (hi - lo), hi + (hi - lo), 400.0 / 300.0);
  s.camera = camera.state();
  return s;
}

// A marker naming a process that has exited: the editor that wrote it crashed.
void writeCrashMarker(const std::string& path) {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  std::ofstream(path) << "somicage-autosave 1\npid " << child << "\n";
}

}  // namespace

TEST(GuiAutosave, RestoreAutosaveShowsTheCrashedSessionAndLeavesTheFilesAlone) {
  if (kXvfbRun.empty() && std::getenv("DISPLAY") == nullptr)
    GTEST_SKIP() << "neither xvfb-run nor a DISPLAY is available (apt-get install xvfb xauth)";
  const ConfigHome config("autosave_restore");
  const somicage::editor::AutosavePaths paths = config.paths();
  fs::create_directories(fs::path(paths.session).parent_path());
  const std::string session = somicage::sessionToJson(crashedSession());
  std::ofstream(paths.session) << session;
  std::ofstream(config.root() / "same.json") << session;
  writeCrashMarker(paths.marker);
  const std::string marker = readText(paths.marker);

  const std::string common = "--size 400x300 --hide-ui --device cpu --screenshot ";
  std::string log;
  ASSERT_EQ(runSomicage(config, "--restore-autosave " + common + quote((config.root() / "restored.png").string()), log),
            0)
      << log;
  EXPECT_EQ(log.find("no session"), std::string::npos) << log;
  ASSERT_EQ(runSomicage(config,
                        "--session " + quote((config.root() / "same.json").string()) + " " + common +
                            quote((config.root() / "opened.png").string()),
                        log),
            0)
      << log;
  const std::vector<bool> restored = meshMask(config.root() / "restored.png");
  const std::vector<bool> opened = meshMask(config.root() / "opened.png");
  ASSERT_FALSE(restored.empty());
  ASSERT_EQ(restored.size(), opened.size());
  EXPECT_GT(share(restored, restored, false), 0.01) << "the restored mesh is on screen";
  // Identical renders of the same session: any difference is the software renderer's, far below 0.5%.
  EXPECT_LT(share(restored, opened, true), 0.005);
  // A --screenshot run never writes the user's autosave files.
  EXPECT_EQ(readText(paths.session), session);
  EXPECT_EQ(readText(paths.marker), marker);
}

TEST(GuiAutosave, RestoreAutosaveWithoutACrashSaysSoAndOpensTheDemo) {
  if (kXvfbRun.empty() && std::getenv("DISPLAY") == nullptr)
    GTEST_SKIP() << "neither xvfb-run nor a DISPLAY is available (apt-get install xvfb xauth)";
  const ConfigHome config("autosave_none");
  std::string log;
  EXPECT_EQ(runSomicage(
                config,
                "--restore-autosave --size 320x240 --screenshot " + quote((config.root() / "demo.png").string()), log),
            0)
      << log;
  EXPECT_NE(log.find("--restore-autosave: no session of a crashed run to restore"), std::string::npos) << log;
  EXPECT_TRUE(fs::exists(config.root() / "demo.png"));
}
