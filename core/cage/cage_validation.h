// Checks that a cage is usable by the coordinates (docs/method.md, "Conventions"):
//   3D: a closed, edge-manifold triangle mesh, consistently oriented, with outward normals (signed volume > 0);
//   2D: a simple polygon (no two edges cross or touch), counter-clockwise (signed area > 0).
// Both: no degenerate faces (near-zero area or length) and no two vertices at the same position.
// Also lists 3D self-intersections (a warning: describeCageWarnings).
// Cost: O(F log F + V log V), plus the face pairs whose bounding boxes overlap in 3D. Indices are 0-based.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "geometry/cage.h"

namespace somicage {

struct CageReport {
  int dim = 3;
  int numVertices = 0;
  int numFaces = 0;

  // Faces with an index outside [0, #V): nothing else is checked when there are any.
  std::vector<int> invalidFaces;

  // A ridge is what two faces share: an edge (a, b) in 3D, a vertex (a, -1) in 2D.
  struct Ridge {
    int a = -1, b = -1;
    std::vector<int> faces;  // the faces that contain it
  };
  std::vector<Ridge> boundaryRidges;     // in one face only: the cage has a hole (2D: an open polyline end)
  std::vector<Ridge> nonManifoldRidges;  // in three or more faces
  std::vector<Ridge> misorientedRidges;  // in two faces that traverse it the same way

  // Faces whose area (3D) or length (2D) is below kDegenerateTolerance times diameter^2 (3D) or diameter (2D),
  // or that repeat a vertex.
  std::vector<int> degenerateFaces;
  // Pairs (i, j), i < j, of vertices closer than kDuplicateTolerance times the cage diameter.
  std::vector<std::array<int, 2>> duplicateVertices;
  // Vertices that no face uses: they get zero coordinates and never move anything.
  std::vector<int> unreferencedVertices;
  // Pairs (i, j), i < j, of faces that meet other than at the vertices they share.
  // 2D (a problem): non-adjacent edges that cross or touch, or adjacent edges that fold back onto each other. The
  //   sweep stops at the first such pair, so at most one is listed.
  // 3D (a warning only, see describeCageWarnings): every pair of non-degenerate triangles that cross or touch, or
  //   that share an edge and are folded onto each other (opening angle <= kFoldTolerance). The coordinates stay
  //   defined, but a point in the overlap is inside twice (winding number 2) and deforms poorly.
  std::vector<std::array<int, 2>> intersectingFaces;

  int components = 0;         // connected components of the face graph
  double signedVolume = 0.0;  // 3D: enclosed volume, 2D: enclosed area; positive when the normals point out
  double diameter = 0.0;      // bounding-box diagonal

  static constexpr double kDegenerateTolerance = 1e-10;
  static constexpr double kDuplicateTolerance = 1e-10;
  static constexpr double kFoldTolerance = 1e-9;  // radians

  bool indicesValid() const { return invalidFaces.empty(); }
  bool closed() const { return indicesValid() && boundaryRidges.empty(); }
  bool manifold() const { return indicesValid() && nonManifoldRidges.empty(); }
  bool consistentlyOriented() const { return indicesValid() && misorientedRidges.empty(); }
  // Outward normals (2D: counter-clockwise) only make sense on a closed, manifold, consistently oriented cage.
  // A volume (area) below kDegenerateTolerance times diameter^3 (diameter^2) is a flat cage: its faces fold onto each
  // other and the rest-pose weights of Eqs. 10-14 lose every digit.
  bool outward() const {
    return closed() && manifold() && consistentlyOriented() && signedVolume > minimumEnclosedMeasure();
  }
  double minimumEnclosedMeasure() const { return kDegenerateTolerance * std::pow(diameter, dim); }
  bool simple() const { return dim == 3 || (closed() && manifold() && components == 1 && intersectingFaces.empty()); }
  // True when the coordinates of this cage are well defined (every check passes).
  bool valid() const;
};

CageReport validateCage(const Cage& cage);

// One entry per kind of problem, in order of severity: what is wrong, naming (the first few) elements, and what to
// do about it. Empty exactly when report.valid().
std::vector<std::string> describeCageProblems(const CageReport& report);

// Throws InputError(source, ...) with the first problem (and how many more there are) unless report.valid(); the
// hint points to 'somicage check', which lists them all.
void requireValidCage(const CageReport& report, const std::string& source);

// What makes a valid cage deform poorly without making it unusable (3D self-intersections), in the same form:
// what is wrong, naming (the first few) elements, and what to do about it. Empty when there is nothing to say.
std::vector<std::string> describeCageWarnings(const CageReport& report);

}  // namespace somicage
