// Loading OpenGL (glad) into the current context and whole-framebuffer operations. No GL types.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "view_matrices.h"

namespace somicage::render {

using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);  // e.g. glfwGetProcAddress

struct GlInfo {
  int major = 0, minor = 0;
  std::string vendor, renderer, version;
};

// Loads the GL functions of the current context. Throws std::runtime_error when the context is older
// than OpenGL 3.3 core, with the version found and what to do.
GlInfo initOpenGl(GlProcLoader loader);

// Clears the whole framebuffer (fbWidth x fbHeight pixels) to `background`.
void clearFramebuffer(int fbWidth, int fbHeight, const Eigen::Vector3f& background);

// Restricts drawing to `rect` (viewport + scissor) and clears its depth and, optionally, its colour.
void beginViewport(const ViewportRect& rect, const Eigen::Vector3f* background = nullptr);

// Restores the full-framebuffer viewport and switches the scissor test off.
void endViewports(int fbWidth, int fbHeight);

// Waits until every GL command issued so far has run (glFinish): timing a stage of a frame (editor's Frame timings).
void finishGl();

// Reads the current framebuffer back as RGBA8, rows top to bottom (width * height * 4 bytes).
std::vector<unsigned char> readPixelsRgba(int width, int height);

}  // namespace somicage::render
