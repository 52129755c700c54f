#include "shader_library.h"

#include <stdexcept>

namespace somicage::render {

std::string shaderSource(const std::string& name) {
  for (const EmbeddedShader& shader : embeddedShaders()) {
    if (name == shader.name) return std::string(shader.text, shader.size);
  }
  throw std::runtime_error("shader '" + name + "' is not embedded in this binary (is it in shaders/?)");
}

}  // namespace somicage::render
