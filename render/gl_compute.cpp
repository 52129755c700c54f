#include "gl_compute.h"

#include <stdexcept>
#include <vector>

#include "shader_library.h"

namespace somicage::render {

namespace {

void deleteProgram(GLuint id) { glDeleteProgram(id); }
void deleteQuery(GLuint id) { glDeleteQueries(1, &id); }
GLuint genQuery() {
  GLuint id = 0;
  glGenQueries(1, &id);
  return id;
}

// The embedded text with `defines` inserted after the #version line (which must come first in GLSL).
std::string specialise(const std::string& file, const std::string& defines) {
  std::string text = shaderSource(file);
  const std::size_t version = text.find("#version");
  const std::size_t lineEnd = version == std::string::npos ? std::string::npos : text.find('\n', version);
  if (lineEnd == std::string::npos) throw std::runtime_error("shaders/" + file + " has no #version line");
  text.insert(lineEnd + 1, defines + (defines.empty() || defines.back() == '\n' ? "" : "\n") + "#line 2\n");
  return text;
}

std::string programLog(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
  return log.data();
}

}  // namespace

GlComputeProgram::GlComputeProgram(const std::string& file, const std::string& defines)
    : GlHandle(glCreateProgram(), deleteProgram) {
  const std::string text = specialise(file, defines);
  const GLuint shader =
      compileShaderStage(GL_COMPUTE_SHADER, text, "shaders/" + file + " (compute stage, with\n" + defines + "\n");
  glAttachShader(id(), shader);
  glLinkProgram(id());
  glDetachShader(id(), shader);
  glDeleteShader(shader);
  GLint ok = GL_FALSE;
  glGetProgramiv(id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE)
    throw std::runtime_error("failed to link the compute program shaders/" + file + ":\n" + programLog(id()));
  glGetProgramiv(id(), GL_COMPUTE_WORK_GROUP_SIZE, localSize_);
  SOMICAGE_GL_CHECK("GlComputeProgram");
}

void GlComputeProgram::use() const { glUseProgram(id()); }

GLint GlComputeProgram::uniform(const char* name) const { return glGetUniformLocation(id(), name); }

GlQuery::GlQuery() : GlHandle(genQuery(), deleteQuery) {}

}  // namespace somicage::render
