#include "gl_objects.h"

#include <stdexcept>
#include <vector>

#include "shader_library.h"

namespace somicage::render {

void checkGlError(const char* what) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    throw std::runtime_error(std::string("OpenGL error 0x") + std::to_string(error) + " after " + what);
  }
}

namespace {

GLuint genBuffer() {
  GLuint id = 0;
  glGenBuffers(1, &id);
  return id;
}
GLuint genVertexArray() {
  GLuint id = 0;
  glGenVertexArrays(1, &id);
  return id;
}
GLuint genTexture() {
  GLuint id = 0;
  glGenTextures(1, &id);
  return id;
}
GLuint genFramebuffer() {
  GLuint id = 0;
  glGenFramebuffers(1, &id);
  return id;
}
void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }
void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
void deleteProgram(GLuint id) { glDeleteProgram(id); }

}  // namespace

GLuint compileShaderStage(GLenum stage, const std::string& text, const std::string& description) {
  const GLuint shader = glCreateShader(stage);
  const char* source = text.c_str();
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteShader(shader);
    const char* glsl = reinterpret_cast<const char*>(glGetString(GL_SHADING_LANGUAGE_VERSION));
    throw std::runtime_error("failed to compile " + description + ", driver GLSL " + (glsl ? glsl : "?") + "):\n" +
                             log.data());
  }
  return shader;
}

namespace {

// Compiles one stage of an embedded shader; the caller deletes the shader.
GLuint compileStage(GLenum stage, const std::string& file) {
  return compileShaderStage(stage, shaderSource(file),
                            "shaders/" + file + " (" + (stage == GL_VERTEX_SHADER ? "vertex" : "fragment") + " stage");
}

}  // namespace

GlBuffer::GlBuffer() : GlHandle(genBuffer(), deleteBuffer) {}

void GlBuffer::upload(GLenum target, const void* data, std::size_t bytes, GLenum usage) {
  glBindBuffer(target, id());
  if (bytes != bytes_) {
    glBufferData(target, static_cast<GLsizeiptr>(bytes), data, usage);
    bytes_ = bytes;
  } else if (bytes > 0) {
    glBufferSubData(target, 0, static_cast<GLsizeiptr>(bytes), data);
  }
  SOMICAGE_GL_CHECK("GlBuffer::upload");
}

GlVertexArray::GlVertexArray() : GlHandle(genVertexArray(), deleteVertexArray) {}

void GlVertexArray::bind() const { glBindVertexArray(id()); }

void GlVertexArray::setFloatAttribute(GLuint location, const GlBuffer& buffer, int components) {
  glBindVertexArray(id());
  glBindBuffer(GL_ARRAY_BUFFER, buffer.id());
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, 0, nullptr);
  SOMICAGE_GL_CHECK("GlVertexArray::setFloatAttribute");
}

GlProgram::GlProgram(const std::string& vertexFile, const std::string& fragmentFile)
    : GlHandle(glCreateProgram(), deleteProgram), label_(vertexFile + " + " + fragmentFile) {
  const GLuint vs = compileStage(GL_VERTEX_SHADER, vertexFile);
  GLuint fs = 0;
  try {
    fs = compileStage(GL_FRAGMENT_SHADER, fragmentFile);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  glAttachShader(id(), vs);
  glAttachShader(id(), fs);
  glLinkProgram(id());
  glDetachShader(id(), vs);
  glDetachShader(id(), fs);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetProgramiv(id(), GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    glGetProgramInfoLog(id(), static_cast<GLsizei>(log.size()), nullptr, log.data());
    throw std::runtime_error("failed to link the program " + label_ + ":\n" + log.data());
  }
}

void GlProgram::use() const { glUseProgram(id()); }

GLint GlProgram::uniform(const char* name) const { return glGetUniformLocation(id(), name); }

GlTexture::GlTexture() : GlHandle(genTexture(), deleteTexture) {}

GlFramebuffer::GlFramebuffer() : GlHandle(genFramebuffer(), deleteFramebuffer) {}

}  // namespace somicage::render
