// What the editor deforms: a triangle mesh and its rest cage, from files or built procedurally. No GL.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "engine/engine.h"
#include "geometry/cage.h"
#include "io/mesh_document.h"

namespace somicage::editor {

struct Scene {
  std::string name;               // shown in the title and the status bar
  Eigen::MatrixXd meshVertices;   // #V by d, d = restCage.dim()
  Eigen::MatrixXi meshTriangles;  // #F by 3 (polygons of the file triangulated; may be empty for point sets)
  Cage restCage;
  std::string meshPath, cagePath;                // empty for the built-in demos
  std::shared_ptr<const MeshDocument> document;  // the mesh file as read, for lossless export (null for demos)
  std::vector<std::string> notices;  // what loadScene repaired in the cage, and warnings about it (one sentence each)

  int dim() const { return restCage.dim(); }
  bool isDemo() const { return meshPath.empty(); }
};

// The built-in demos. 3D: a capped cylinder (a bar along x) inside a box cage cut into four segments along
// the bar (20 vertices), so it bends and twists well. 2D: a dense triangulated strip inside a 10-vertex
// polygon cage.
Scene makeDemoScene(int dim);

// Loads MESH and CAGE in any format of core/io/mesh_formats.h through the engine facade (core/engine/engine.h), as the
// command line does: the cage is repaired, validated and warned about in the engine's one order, which the notices say.
// A 2D cage makes a 2D scene (the mesh keeps x, y). An empty cagePath makes a cage for the mesh
// (core/generation/cage_generation.h, 200 faces), which the notices say too. Throws InputError on any problem with the
// files, and when the repaired cage is still not valid.
Scene loadScene(const std::string& meshPath, const std::string& cagePath);
// MESH (as loadScene) around a cage given in memory, already prepared (a session's inline cage, session.h): cagePath
// stays empty and cageSource names the cage in the placement warning. An empty meshPath: the built-in demo of the
// cage's dimension, with this cage.
Scene loadSceneWithCage(const std::string& meshPath, const Cage& cage, const std::string& cageSource);

// A line of Scene::notices: "cage repaired: TEXT", "cage warning: TEXT", or "mesh warning: TEXT" for a notice without
// a source (the placement warning, which names both files itself).
std::string sceneNotice(const Notice& notice);

// Axis-aligned bounds of #V by 2 or 3 points as 3D corners (z = 0 for 2D).
void bounds3(const Eigen::MatrixXd& points, Eigen::Vector3d& lo, Eigen::Vector3d& hi);

}  // namespace somicage::editor
