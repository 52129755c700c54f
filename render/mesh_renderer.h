// Draws a shaded triangle mesh whose positions change every frame. No GL types in this header.
// Create, use and destroy only while the GL context that initOpenGl() loaded is current.
#pragma once

#include <Eigen/Core>
#include <memory>

#include "mesh_normals.h"
#include "view_matrices.h"

namespace somicage::render {

struct MeshStyle {
  Eigen::Vector3f color{0.80f, 0.66f, 0.48f};
  bool wireframe = false;  // triangle edges over the shading
  bool flat = false;       // faceted shading (one normal per triangle) instead of smooth
  Eigen::Vector4f wireColor{0.15f, 0.12f, 0.10f, 0.22f};
  // The colour map of the scalars (setScalars) instead of `color`: -1 none, else a row of colorMapTable().
  int colorMap = -1;
};

// The colour maps, 256 RGB entries each (sampled from the control points of color_maps.cpp): row 0 a diverging
// blue - grey - red map (Moreland's cool-warm), row 1 viridis. Fold-overs get kFoldoverColor in every map.
enum ColorMapRow { kDivergingMap = 0, kViridisMap = 1 };
Eigen::Vector3f colorMapColor(int row, float t);  // t in [0, 1]
inline const Eigen::Vector3f kFoldoverColor{0.90f, 0.0f, 0.90f};

class MeshRenderer {
 public:
  MeshRenderer();
  ~MeshRenderer();
  MeshRenderer(const MeshRenderer&) = delete;
  MeshRenderer& operator=(const MeshRenderer&) = delete;
  MeshRenderer(MeshRenderer&&) noexcept;
  MeshRenderer& operator=(MeshRenderer&&) noexcept;

  // triangles: #F by 3 indices into the positions; uploaded once per mesh.
  void setTopology(const Eigen::MatrixXi& triangles);
  // positions: #V by 2 or 3. Uploads positions and smooth normals recomputed from them (topology untouched).
  void setPositions(const Eigen::MatrixXd& positions);
  // The same with positions and unit normals already made (#V by 3 floats each, mesh_normals.h), so a caller can
  // time or place the normals' computation itself.
  void setPositions(const RowMatrixX3f& positions, const RowMatrixX3f& normals);
  // coordinates: #V colour-map coordinates in [0, 1], -1 for a fold-over, -2 for undefined (drawn grey); empty
  // removes them. Drawn when MeshStyle::colorMap >= 0.
  void setScalars(const Eigen::VectorXf& coordinates);
  void draw(const ViewMatrices& view, const MeshStyle& style) const;

  // For render/gpu_deformer.h, which writes positions and normals with compute shaders: sizes the position and
  // normal buffers for `vertexCount` vertices (3 floats each, contents undefined until written) and returns the
  // GL names of those two and of the index buffer (#F by 3 uint). No GL types here: they are GLuint.
  struct DeviceBuffers {
    unsigned int positions = 0, normals = 0, triangles = 0;
  };
  DeviceBuffers deviceBuffers(int vertexCount);
  const Eigen::MatrixXi& triangles() const;

  int numVertices() const;
  int numTriangles() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace somicage::render
