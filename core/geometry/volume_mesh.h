// A volume mesh of a cage's interior: tetrahedra in 3D, triangles in 2D, whose first #V vertices are the cage's
// vertices in order (the Phong deformer of phong_method.cpp interpolates over it; docs/engine.md, "Phong").
// Further (Steiner) vertices lie inside the cage or on its faces. Made by the cage generation library
// (cage_tetrahedralization.h: CGAL Mesh_3), read from a MEDIT file (medit_io.h), or, for a cage that is
// star-shaped from its centroid, the star of its faces around that point (starVolumeMesh).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "base/progress.h"
#include "geometry/cage.h"

namespace somicage {

struct VolumeMesh {
  Eigen::MatrixXd vertices;   // #N by d; rows 0 .. #V - 1 are the cage's
  Eigen::MatrixXi simplices;  // #S by d + 1, 0-based; positively oriented after checkVolumeMesh
  // A generated mesh that is not the one asked for: why, in one sentence for the user (cage_tetrahedralization.h:
  // Mesh_3 fell back to TetGen); prepareVolumeMesh (engine.h) turns it into a Warning notice. Empty otherwise.
  std::string fallback;

  int dim() const { return static_cast<int>(vertices.cols()); }
  int numVertices() const { return static_cast<int>(vertices.rows()); }
  int numSimplices() const { return static_cast<int>(simplices.rows()); }
};

// The signed volume (3D) or area (2D) of simplex s: positive when positively oriented.
double signedSimplexMeasure(const VolumeMesh& mesh, int s);

// The barycentric coordinates' gradients in every simplex (d + 1 by d each, row k for its vertex k): the rows
// of D_m^-1 (D_m = [v1 - v0, ..., vd - v0]) and minus their sum. Constant in a simplex.
std::vector<Eigen::MatrixXd> barycentricGradients(const VolumeMesh& mesh);

// The mesh's edges, each once (#E by 2, the smaller index first, sorted): what a wireframe of it draws.
Eigen::MatrixXi volumeMeshEdges(const VolumeMesh& mesh);

// A face on the mesh's boundary (used by one simplex): that simplex, and its vertex opposite the face.
struct BoundaryFace {
  int simplex;
  int opposite;
};
// The boundary faces, by ascending sorted vertex indices. *overShared: a simplex with a face that three or more
// simplices use (-1 if none).
std::vector<BoundaryFace> boundaryFaces(const VolumeMesh& mesh, int* overShared = nullptr);

// Where a mesh came from, for the errors and notices of checkVolumeMesh: the file, and each vertex's and each
// simplex's line in it (empty for a generated mesh).
struct VolumeMeshSource {
  std::string name;
  std::vector<long> vertexLines, simplexLines;
};

// Checks that `mesh` is a volume mesh of `cage`, in this order, throwing InputError(source, line, ...) with the
// vertex or simplex concerned: the dimension; the first #V vertices are the cage's (to 1e-9 cage diameters;
// the error names the vertex and the distance); every index is in range; no simplex is degenerate; every face on
// the mesh's boundary lies on a cage face (1e-9 diameters) and faces the same way; the boundary covers the cage
// (equal areas, 1e-9 relative), so no simplex lies outside the cage and none is missing. Negatively oriented
// simplices are reoriented first; returns how many were (the caller gives a notice).
int checkVolumeMesh(VolumeMesh& mesh, const Cage& cage, const VolumeMeshSource& source);

// The faces of `cage` joined to its volume (2D: area) centroid c: a volume mesh with one Steiner vertex (row #V),
// when the cage is star-shaped from c (no simplex a sliver: measure > 1e-6 of its longest edge to the d); null
// otherwise. What a volume method uses when a front end gives it neither a mesh nor a mesher.
std::unique_ptr<VolumeMesh> starVolumeMesh(const Cage& cage);

// A method's own precompute options (MethodDescriptor::options), as text by key: e.g. "tets" (a MEDIT file) and
// "tet-level" for Phong. Front ends fill it from their options (the CLI's --tets, Python's tets=).
using MethodOptions = std::map<std::string, std::string>;

// Detail levels of the generated tetrahedra (cage_tetrahedralization.h): 0 keeps about the cage's vertices, each
// level halves the element size.
constexpr int kTetLevels = 5;  // 0 .. 4
constexpr int kDefaultTetLevel = 1;
// The method option "tet-level": a whole number 0 .. 4 (kDefaultTetLevel when absent). Throws InputError naming
// --tet-level otherwise, with the range: the mesher reads it, and the front ends check it when they read it.
int parseTetLevel(const MethodOptions& options);

// Makes a volume mesh of a cage from the method options: the CGAL tetrahedralization (cage_tetrahedralization.h),
// injected by the front ends that link the cage generation library. The result is checked by checkVolumeMesh.
// progress as in progress.h: it may stop the mesher (Cancelled).
using VolumeMesher =
    std::function<VolumeMesh(const Cage& restCage, const MethodOptions& options, const ProgressCallback& progress)>;

}  // namespace somicage
