#include "cage_renderer.h"

#include <algorithm>
#include <set>
#include <utility>

#include "gl_objects.h"
#include "mesh_normals.h"

namespace somicage::render {

struct CageRenderer::Impl {
  GlProgram flat{"flat.vert", "flat.frag"};
  GlProgram handles{"handle.vert", "handle.frag"};
  GlVertexArray faceVao, edgeVao, handleVao;
  GlBuffer positions, selection, faceIndices, edgeIndices;
  GLsizei faceIndexCount = 0, edgeIndexCount = 0;
  int vertexCount = 0;
};

CageRenderer::CageRenderer() : impl_(std::make_unique<Impl>()) {
  impl_->faceVao.setFloatAttribute(0, impl_->positions, 3);
  impl_->edgeVao.setFloatAttribute(0, impl_->positions, 3);
  impl_->handleVao.setFloatAttribute(0, impl_->positions, 3);
  impl_->handleVao.setFloatAttribute(1, impl_->selection, 1);
}
CageRenderer::~CageRenderer() = default;

void CageRenderer::setTopology(const Eigen::MatrixXi& faces) {
  std::vector<unsigned int> tris, edges;
  std::set<std::pair<int, int>> seen;
  auto addEdge = [&](int a, int b) {
    if (seen.insert({std::min(a, b), std::max(a, b)}).second) {
      edges.push_back(static_cast<unsigned int>(a));
      edges.push_back(static_cast<unsigned int>(b));
    }
  };
  for (Eigen::Index f = 0; f < faces.rows(); ++f) {
    if (faces.cols() == 3) {
      for (int k = 0; k < 3; ++k) tris.push_back(static_cast<unsigned int>(faces(f, k)));
      for (int k = 0; k < 3; ++k) addEdge(faces(f, k), faces(f, (k + 1) % 3));
    } else if (faces.cols() == 2) {
      addEdge(faces(f, 0), faces(f, 1));
    }
  }
  impl_->faceVao.bind();
  impl_->faceIndices.upload(GL_ELEMENT_ARRAY_BUFFER, tris.data(), sizeof(unsigned int) * tris.size(), GL_STATIC_DRAW);
  impl_->edgeVao.bind();
  impl_->edgeIndices.upload(GL_ELEMENT_ARRAY_BUFFER, edges.data(), sizeof(unsigned int) * edges.size(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  impl_->faceIndexCount = static_cast<GLsizei>(tris.size());
  impl_->edgeIndexCount = static_cast<GLsizei>(edges.size());
}

void CageRenderer::setPositions(const Eigen::MatrixXd& positions) {
  const RowMatrixX3f p = toFloat3(positions);
  impl_->positions.upload(GL_ARRAY_BUFFER, p.data(), sizeof(float) * static_cast<std::size_t>(p.size()), GL_DYNAMIC_DRAW);
  if (impl_->vertexCount != static_cast<int>(positions.rows())) {
    impl_->vertexCount = static_cast<int>(positions.rows());
    setSelection({});
  }
}

void CageRenderer::setSelection(const std::vector<bool>& selected) {
  std::vector<float> flags(static_cast<std::size_t>(impl_->vertexCount), 0.0f);
  for (std::size_t i = 0; i < flags.size() && i < selected.size(); ++i) flags[i] = selected[i] ? 1.0f : 0.0f;
  impl_->selection.upload(GL_ARRAY_BUFFER, flags.data(), sizeof(float) * flags.size(), GL_DYNAMIC_DRAW);
}

void CageRenderer::draw(const ViewMatrices& view, const CageStyle& style) const {
  const Impl& c = *impl_;
  if (c.vertexCount == 0) return;
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDisable(GL_CULL_FACE);
  glEnable(GL_DEPTH_TEST);

  c.flat.use();
  glUniformMatrix4fv(c.flat.uniform("uView"), 1, GL_FALSE, view.view.data());
  glUniformMatrix4fv(c.flat.uniform("uProjection"), 1, GL_FALSE, view.projection.data());
  if (style.showFaces && c.faceIndexCount > 0) {
    // Translucent faces: depth-tested against the mesh but not written, so the mesh shows through.
    glDepthMask(GL_FALSE);
    glUniform1f(c.flat.uniform("uDepthOffset"), 0.0f);
    glUniform4fv(c.flat.uniform("uColor"), 1, style.faceColor.data());
    c.faceVao.bind();
    glDrawElements(GL_TRIANGLES, c.faceIndexCount, GL_UNSIGNED_INT, nullptr);
  }
  if (style.showEdges && c.edgeIndexCount > 0) {
    // Edges in front of the mesh at full colour, behind it faintly.
    glDepthMask(GL_FALSE);
    glUniform1f(c.flat.uniform("uDepthOffset"), 1e-4f);
    c.edgeVao.bind();
    Eigen::Vector4f hidden = style.edgeColor;
    hidden.w() *= 0.25f;
    glDepthFunc(GL_GREATER);
    glUniform4fv(c.flat.uniform("uColor"), 1, hidden.data());
    glDrawElements(GL_LINES, c.edgeIndexCount, GL_UNSIGNED_INT, nullptr);
    glDepthFunc(GL_LEQUAL);
    glUniform4fv(c.flat.uniform("uColor"), 1, style.edgeColor.data());
    glDrawElements(GL_LINES, c.edgeIndexCount, GL_UNSIGNED_INT, nullptr);
    glDepthFunc(GL_LESS);
  }
  if (style.showHandles) {
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_PROGRAM_POINT_SIZE);
    c.handles.use();
    glUniformMatrix4fv(c.handles.uniform("uView"), 1, GL_FALSE, view.view.data());
    glUniformMatrix4fv(c.handles.uniform("uProjection"), 1, GL_FALSE, view.projection.data());
    glUniform1f(c.handles.uniform("uPointSize"), style.handleSize);
    glUniform4fv(c.handles.uniform("uColor"), 1, style.handleColor.data());
    glUniform4fv(c.handles.uniform("uSelectedColor"), 1, style.selectedColor.data());
    c.handleVao.bind();
    glDrawArrays(GL_POINTS, 0, c.vertexCount);
    glEnable(GL_DEPTH_TEST);
  }
  glBindVertexArray(0);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  SOMICAGE_GL_CHECK("CageRenderer::draw");
}

}  // namespace somicage::render
