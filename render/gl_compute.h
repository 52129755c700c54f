// RAII wrappers for the OpenGL 4.3 objects of the GPU deformer: a compute program and a query. This header
// includes glad (through gl_objects.h): only files in render/ may include it.
//
// Same rules as gl_objects.h: the constructor creates the object in the current context, the destructor deletes it,
// copies are deleted and moves take over the name. Use only in a context where GLAD_GL_VERSION_4_3 is set.
#pragma once

#include <string>

#include "gl_objects.h"

namespace somicage::render {

// A linked compute program from the embedded shaders/<file>. `defines` ("#define NAME VALUE" lines) go right
// after the file's #version line, so one file serves several compile-time specialisations. A failed compile or
// link throws std::runtime_error with the file, the stage, the defines and the driver log.
class GlComputeProgram : public GlHandle {
 public:
  GlComputeProgram(const std::string& file, const std::string& defines = "");
  void use() const;
  GLint uniform(const char* name) const;  // -1 when the driver optimised it away
  // The local size the shader declares (x * y * z invocations per work group).
  int localSizeX() const { return localSize_[0]; }

 private:
  GLint localSize_[3] = {1, 1, 1};
};

// A query object (GL_TIME_ELAPSED here).
class GlQuery : public GlHandle {
 public:
  GlQuery();
};

}  // namespace somicage::render
