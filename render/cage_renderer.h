// Draws a cage: translucent faces (3D), edges, and round vertex handles that stay visible through the
// mesh, selected ones highlighted. No GL types in this header; use only with the GL context current.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "view_matrices.h"

namespace somicage::render {

struct CageStyle {
  Eigen::Vector4f faceColor{0.35f, 0.55f, 0.95f, 0.12f};
  Eigen::Vector4f edgeColor{0.15f, 0.30f, 0.75f, 1.0f};
  Eigen::Vector4f handleColor{0.95f, 0.95f, 0.97f, 1.0f};
  Eigen::Vector4f selectedColor{1.0f, 0.55f, 0.10f, 1.0f};
  float handleSize = 11.0f;  // pixels
  bool showFaces = true, showEdges = true, showHandles = true;
};

class CageRenderer {
 public:
  CageRenderer();
  ~CageRenderer();
  CageRenderer(const CageRenderer&) = delete;
  CageRenderer& operator=(const CageRenderer&) = delete;

  // faces: 3D: #F by 3 triangles (drawn as translucent faces and their unique edges); 2D: #F by 2 edges.
  void setTopology(const Eigen::MatrixXi& faces);
  // positions: #V by 2 or 3.
  void setPositions(const Eigen::MatrixXd& positions);
  // One flag per vertex (missing entries count as unselected).
  void setSelection(const std::vector<bool>& selected);
  void draw(const ViewMatrices& view, const CageStyle& style) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace somicage::render
