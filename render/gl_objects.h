// RAII wrappers of OpenGL objects. This header includes glad: only files in render/ may include it
// (the glad include path is private to somicage_render; the public render headers use no GL types).
//
// Each constructor creates its object in the current context and the destructor deletes it; copies are
// deleted, moves take over the name and leave 0 behind. A GL context must be current for all of them.
#pragma once

#include <glad/gl.h>

#include <cstddef>
#include <string>
#include <utility>

namespace somicage::render {

// With -DSOMICAGE_GL_DEBUG=ON, throws std::runtime_error naming the call site when glGetError reports one.
void checkGlError(const char* what);
#ifdef SOMICAGE_GL_DEBUG
#define SOMICAGE_GL_CHECK(what) ::somicage::render::checkGlError(what)
#else
#define SOMICAGE_GL_CHECK(what) ((void)0)
#endif

// Owns one GL name and deletes it with `deleter` when destroyed or assigned over.
class GlHandle {
 public:
  using Deleter = void (*)(GLuint);
  GlHandle(GLuint id, Deleter deleter) : id_(id), deleter_(deleter) {}
  ~GlHandle() { reset(); }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;
  GlHandle(GlHandle&& other) noexcept : id_(std::exchange(other.id_, 0)), deleter_(other.deleter_) {}
  GlHandle& operator=(GlHandle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
      deleter_ = other.deleter_;
    }
    return *this;
  }
  GLuint id() const { return id_; }

 private:
  void reset() {
    if (id_ != 0 && deleter_ != nullptr) deleter_(id_);
    id_ = 0;
  }
  GLuint id_ = 0;
  Deleter deleter_ = nullptr;
};

class GlBuffer : public GlHandle {
 public:
  GlBuffer();
  // Replaces the contents: reallocates when the size changes, otherwise glBufferSubData.
  void upload(GLenum target, const void* data, std::size_t bytes, GLenum usage);
  std::size_t size() const { return bytes_; }

 private:
  std::size_t bytes_ = 0;
};

class GlVertexArray : public GlHandle {
 public:
  GlVertexArray();
  void bind() const;
  // Binds `buffer` as GL_ARRAY_BUFFER and describes float attribute `location` with `components` per vertex.
  void setFloatAttribute(GLuint location, const GlBuffer& buffer, int components);
};

// Compiles GLSL text as one stage; the caller deletes the shader. On failure throws std::runtime_error with the
// description (e.g. "shaders/mesh.vert (vertex stage"), the driver's GLSL version and its log.
GLuint compileShaderStage(GLenum stage, const std::string& text, const std::string& description);

// A linked program from two embedded shaders (shaders/<vertexFile>, shaders/<fragmentFile>).
// A failed compile or link throws std::runtime_error with the file, the stage and the driver log.
class GlProgram : public GlHandle {
 public:
  GlProgram(const std::string& vertexFile, const std::string& fragmentFile);
  void use() const;
  GLint uniform(const char* name) const;  // -1 when the driver optimised it away

 private:
  std::string label_;
};

class GlTexture : public GlHandle {
 public:
  GlTexture();
};

class GlFramebuffer : public GlHandle {
 public:
  GlFramebuffer();
};

}  // namespace somicage::render
