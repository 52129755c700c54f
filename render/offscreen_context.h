// A hidden window with its own OpenGL context (GLFW), for tests and benchmarks that need GL without the editor.
// No GL or GLFW types in this header.
#pragma once

#include <memory>
#include <string>

#include "gl_context.h"

namespace somicage::render {

class OffscreenGlContext {
 public:
  // Opens a hidden width x height window with an OpenGL core context of at least major.minor, makes it current
  // and loads GL (initOpenGl). On failure ok() is false and reason() says why (no display, driver too old).
  // GLFW is process-wide: the first live OffscreenGlContext initialises it and the last one terminates it, so
  // nothing else in the process may use GLFW meanwhile (the editor does). Contexts may nest: the destructor makes
  // the context that was current before this one current again (and reloads GL for it).
  explicit OffscreenGlContext(int major = 4, int minor = 3, int width = 64, int height = 64);
  ~OffscreenGlContext();
  OffscreenGlContext(const OffscreenGlContext&) = delete;
  OffscreenGlContext& operator=(const OffscreenGlContext&) = delete;

  bool ok() const { return window_ != nullptr; }
  const std::string& reason() const { return reason_; }
  const GlInfo& info() const { return info_; }

 private:
  void restorePrevious();

  void* window_ = nullptr;    // GLFWwindow
  void* previous_ = nullptr;  // the GLFWwindow whose context was current before, when another one lived
  std::string reason_;
  GlInfo info_;
};

}  // namespace somicage::render
