// GLSL sources from shaders/, embedded into the binary at build time (render/embed_shaders.cmake).
// No GL here: this header only hands out text.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace somicage::render {

struct EmbeddedShader {
  const char* name;  // file name in shaders/, e.g. "mesh.vert"
  const char* text;
  std::size_t size;
};

// Every file of shaders/ (generated table).
const std::vector<EmbeddedShader>& embeddedShaders();

// The text of shaders/<name>; throws std::runtime_error naming the file when it was not embedded.
std::string shaderSource(const std::string& name);

}  // namespace somicage::render
