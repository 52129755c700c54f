#include "mesh_renderer.h"

#include <algorithm>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "gl_objects.h"
#include "mesh_normals.h"

namespace somicage::render {

struct MeshRenderer::Impl {
  GlProgram program{"mesh.vert", "mesh.frag"};
  GlProgram wire{"flat.vert", "flat.frag"};
  GlVertexArray vao;
  GlBuffer positions, normals, indices, scalars;
  GlTexture colorMaps;  // 256 by 2 RGB (ColorMapRow), made once
  bool hasScalars = false;
  Eigen::MatrixXi triangles;
  int vertexCount = 0;
  GLsizei indexCount = 0;
};

MeshRenderer::MeshRenderer() : impl_(std::make_unique<Impl>()) {
  impl_->vao.setFloatAttribute(0, impl_->positions, 3);
  impl_->vao.setFloatAttribute(1, impl_->normals, 3);
  std::vector<float> table(256 * 2 * 3);
  for (int row = 0; row < 2; ++row)
    for (int i = 0; i < 256; ++i) {
      const Eigen::Vector3f c = colorMapColor(row, static_cast<float>(i) / 255.0f);
      for (int k = 0; k < 3; ++k) table[static_cast<std::size_t>((row * 256 + i) * 3 + k)] = c[k];
    }
  glBindTexture(GL_TEXTURE_2D, impl_->colorMaps.id());
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, 256, 2, 0, GL_RGB, GL_FLOAT, table.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
}
MeshRenderer::~MeshRenderer() = default;
MeshRenderer::MeshRenderer(MeshRenderer&&) noexcept = default;
MeshRenderer& MeshRenderer::operator=(MeshRenderer&&) noexcept = default;

void MeshRenderer::setTopology(const Eigen::MatrixXi& triangles) {
  if (triangles.size() > 0 && triangles.cols() != 3) throw std::invalid_argument("MeshRenderer: faces must be #F by 3");
  impl_->triangles = triangles;
  const Eigen::Matrix<unsigned int, Eigen::Dynamic, 3, Eigen::RowMajor> idx = triangles.cast<unsigned int>();
  impl_->vao.bind();
  impl_->indices.upload(GL_ELEMENT_ARRAY_BUFFER, idx.data(),
                        sizeof(unsigned int) * static_cast<std::size_t>(idx.size()), GL_STATIC_DRAW);
  glBindVertexArray(0);
  impl_->indexCount = static_cast<GLsizei>(idx.size());
}

void MeshRenderer::setPositions(const Eigen::MatrixXd& positions) {
  setPositions(toFloat3(positions), vertexNormals(positions, impl_->triangles));
}

void MeshRenderer::setPositions(const RowMatrixX3f& p, const RowMatrixX3f& n) {
  if (n.rows() != p.rows()) throw std::invalid_argument("MeshRenderer: one normal per position");
  const std::size_t bytes = sizeof(float) * static_cast<std::size_t>(p.size());
  impl_->positions.upload(GL_ARRAY_BUFFER, p.data(), bytes, GL_DYNAMIC_DRAW);
  impl_->normals.upload(GL_ARRAY_BUFFER, n.data(), bytes, GL_DYNAMIC_DRAW);
  impl_->vertexCount = static_cast<int>(p.rows());
}

void MeshRenderer::setScalars(const Eigen::VectorXf& coordinates) {
  impl_->hasScalars = coordinates.size() > 0;
  if (!impl_->hasScalars) return;
  impl_->scalars.upload(GL_ARRAY_BUFFER, coordinates.data(),
                        sizeof(float) * static_cast<std::size_t>(coordinates.size()), GL_DYNAMIC_DRAW);
  impl_->vao.setFloatAttribute(2, impl_->scalars, 1);
}

void MeshRenderer::draw(const ViewMatrices& view, const MeshStyle& style) const {
  if (impl_->indexCount == 0 || impl_->vertexCount == 0) return;
  const Impl& m = *impl_;
  m.program.use();
  glUniformMatrix4fv(m.program.uniform("uView"), 1, GL_FALSE, view.view.data());
  glUniformMatrix4fv(m.program.uniform("uProjection"), 1, GL_FALSE, view.projection.data());
  glUniform3fv(m.program.uniform("uColor"), 1, style.color.data());
  glUniform1i(m.program.uniform("uOrthographic"), view.orthographic ? 1 : 0);
  glUniform1i(m.program.uniform("uFlat"), style.flat ? 1 : 0);
  const bool mapped = style.colorMap >= 0 && m.hasScalars;
  glUniform1i(m.program.uniform("uMapped"), mapped ? 1 : 0);
  glUniform1f(m.program.uniform("uMapRow"), (static_cast<float>(std::max(style.colorMap, 0)) + 0.5f) / 2.0f);
  glUniform3fv(m.program.uniform("uFoldoverColor"), 1, kFoldoverColor.data());
  glUniform1i(m.program.uniform("uColorMaps"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, m.colorMaps.id());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  m.vao.bind();
  if (!mapped)
    glDisableVertexAttribArray(2);
  else
    glEnableVertexAttribArray(2);
  glDrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
  if (style.wireframe) {
    m.wire.use();
    glUniformMatrix4fv(m.wire.uniform("uView"), 1, GL_FALSE, view.view.data());
    glUniformMatrix4fv(m.wire.uniform("uProjection"), 1, GL_FALSE, view.projection.data());
    glUniform1f(m.wire.uniform("uDepthOffset"), 2e-5f);
    glUniform4fv(m.wire.uniform("uColor"), 1, style.wireColor.data());
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glDrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  }
  glBindVertexArray(0);
  SOMICAGE_GL_CHECK("MeshRenderer::draw");
}

MeshRenderer::DeviceBuffers MeshRenderer::deviceBuffers(int vertexCount) {
  static_assert(std::is_same<GLuint, unsigned int>::value, "DeviceBuffers holds GLuint names");
  const std::size_t bytes = sizeof(float) * 3 * static_cast<std::size_t>(vertexCount);
  for (GlBuffer* buffer : {&impl_->positions, &impl_->normals}) {
    if (buffer->size() != bytes) buffer->upload(GL_ARRAY_BUFFER, nullptr, bytes, GL_DYNAMIC_DRAW);
  }
  impl_->vertexCount = vertexCount;
  return {impl_->positions.id(), impl_->normals.id(), impl_->indices.id()};
}

const Eigen::MatrixXi& MeshRenderer::triangles() const { return impl_->triangles; }

int MeshRenderer::numVertices() const { return impl_->vertexCount; }
int MeshRenderer::numTriangles() const { return static_cast<int>(impl_->triangles.rows()); }

}  // namespace somicage::render
