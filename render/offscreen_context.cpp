#include "offscreen_context.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdlib>
#include <exception>
#include <thread>

namespace somicage::render {

namespace {
// OffscreenGlContexts alive in this process: GLFW is initialised by the first and terminated by the last.
int liveContexts = 0;

std::string lastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}
}  // namespace

OffscreenGlContext::OffscreenGlContext(int major, int minor, int width, int height) {
  // A second context in one process can find Xvfb regenerating after the first one's disconnect (xvfb-run without
  // -noreset): that takes a moment, so a failed glfwInit is retried for up to two seconds when a display is set.
  bool initialised = liveContexts > 0 || glfwInit();
  for (int attempt = 0; !initialised && std::getenv("DISPLAY") && attempt < 20; ++attempt) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    initialised = glfwInit();
  }
  if (!initialised) {
    reason_ = "cannot initialise GLFW (" + lastGlfwError() + "); " +
              (std::getenv("DISPLAY") ? "check the display" : "no DISPLAY: run under xvfb-run -a");
    return;
  }
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, major);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, minor);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  previous_ = liveContexts > 0 ? glfwGetCurrentContext() : nullptr;
  auto giveUp = [&](std::string why) {
    reason_ = std::move(why);
    if (liveContexts == 0) glfwTerminate();
  };
  GLFWwindow* window = glfwCreateWindow(width, height, "SomiCage (offscreen)", nullptr, nullptr);
  if (!window) {
    giveUp("no OpenGL " + std::to_string(major) + "." + std::to_string(minor) + " core context (" + lastGlfwError() +
           "); update the graphics driver, or use Mesa (LIBGL_ALWAYS_SOFTWARE=1)");
    restorePrevious();
    return;
  }
  glfwMakeContextCurrent(window);
  try {
    info_ = initOpenGl(glfwGetProcAddress);
  } catch (const std::exception& e) {
    glfwDestroyWindow(window);
    giveUp(e.what());
    restorePrevious();
    return;
  }
  window_ = window;
  ++liveContexts;
}

void OffscreenGlContext::restorePrevious() {
  if (!previous_) return;
  glfwMakeContextCurrent(static_cast<GLFWwindow*>(previous_));
  try {
    initOpenGl(glfwGetProcAddress);  // glad's function pointers and version flags are those of the current context
  } catch (const std::exception&) {
  }
}

OffscreenGlContext::~OffscreenGlContext() {
  if (!window_) return;
  glfwDestroyWindow(static_cast<GLFWwindow*>(window_));
  restorePrevious();
  if (--liveContexts == 0) glfwTerminate();
}

}  // namespace somicage::render
