// What the editor deforms: a triangle mesh and its rest cage, from files or built procedurally. No GL.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "cage.h"

namespace somicage::editor {

struct Scene {
  std::string name;               // shown in the title and the status bar
  Eigen::MatrixXd meshVertices;   // #V by d, d = restCage.dim()
  Eigen::MatrixXi meshTriangles;  // #F by 3 (polygons of the file triangulated; may be empty for point sets)
  Cage restCage;
  std::string meshPath, cagePath;    // empty for the built-in demos
  std::vector<std::string> notices;  // what loadScene repaired in the cage, and warnings about it (one sentence each)

  int dim() const { return restCage.dim(); }
  bool isDemo() const { return meshPath.empty(); }
};

// The built-in demos. 3D: a capped cylinder (a bar along x) inside a box cage cut into four segments along
// the bar (20 vertices), so it bends and twists well. 2D: a dense triangulated strip inside a 10-vertex
// polygon cage.
Scene makeDemoScene(int dim);

// Loads MESH.obj and CAGE.obj through the engine facade (core/engine.h), as the command line does: the cage is
// repaired, validated and warned about in the engine's one order, and the notices say what it found. A 2D cage
// makes a 2D scene (the mesh keeps x, y).
// Throws InputError on any problem with the files, and when the repaired cage is still not valid.
Scene loadScene(const std::string& meshPath, const std::string& cagePath);

// Axis-aligned bounds of #V by 2 or 3 points as 3D corners (z = 0 for 2D).
void bounds3(const Eigen::MatrixXd& points, Eigen::Vector3d& lo, Eigen::Vector3d& hi);

}  // namespace somicage::editor
