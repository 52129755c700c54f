#include "gl_context.h"

#include <stdexcept>

#include "gl_objects.h"

namespace somicage::render {

namespace {
std::string glString(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}
}  // namespace

GlInfo initOpenGl(GlProcLoader loader) {
  const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(loader));
  if (version == 0) {
    throw std::runtime_error(
        "could not load OpenGL functions; an OpenGL 3.3 core context is needed (check the graphics driver, "
        "or run under xvfb-run with Mesa's llvmpipe)");
  }
  GlInfo info;
  info.major = GLAD_VERSION_MAJOR(version);
  info.minor = GLAD_VERSION_MINOR(version);
  info.vendor = glString(GL_VENDOR);
  info.renderer = glString(GL_RENDERER);
  info.version = glString(GL_VERSION);
  if (info.major < 3 || (info.major == 3 && info.minor < 3)) {
    throw std::runtime_error("OpenGL " + info.version + " found; SomiCage needs OpenGL 3.3 core or newer");
  }
  return info;
}

void clearFramebuffer(int fbWidth, int fbHeight, const Eigen::Vector3f& background) {
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, fbWidth, fbHeight);
  glClearColor(background.x(), background.y(), background.z(), 1.0f);
  glClearDepth(1.0);
  glDepthMask(GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  SOMICAGE_GL_CHECK("clearFramebuffer");
}

void beginViewport(const ViewportRect& rect, const Eigen::Vector3f* background) {
  glViewport(rect.x, rect.y, rect.width, rect.height);
  glEnable(GL_SCISSOR_TEST);
  glScissor(rect.x, rect.y, rect.width, rect.height);
  glDepthMask(GL_TRUE);
  GLbitfield mask = GL_DEPTH_BUFFER_BIT;
  if (background) {
    glClearColor(background->x(), background->y(), background->z(), 1.0f);
    mask |= GL_COLOR_BUFFER_BIT;
  }
  glClear(mask);
  SOMICAGE_GL_CHECK("beginViewport");
}

void endViewports(int fbWidth, int fbHeight) {
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, fbWidth, fbHeight);
}

void finishGl() { glFinish(); }

std::vector<unsigned char> readPixelsRgba(int width, int height) {
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  std::vector<unsigned char> bottomUp(row * static_cast<std::size_t>(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
  SOMICAGE_GL_CHECK("readPixelsRgba");
  std::vector<unsigned char> topDown(bottomUp.size());
  for (int y = 0; y < height; ++y) {
    std::copy(bottomUp.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(height - 1 - y)),
              bottomUp.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(height - y)),
              topDown.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)));
  }
  for (std::size_t i = 3; i < topDown.size(); i += 4) topDown[i] = 255;  // opaque PNGs
  return topDown;
}

}  // namespace somicage::render
