// Closest points on a rest cage and the outward pseudo-normal there (Baerentzen & Aanaes 2005): a query of the
// cage's geometry that the exterior rule (exterior_points.h) and the volume meshes (volume_mesh.h) both ask.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "geometry/cage.h"

namespace somicage {

// Closest points on a rest cage (3D triangles or 2D edges) and the outward pseudo-normal there. Brute force over
// the faces: only exterior points are queried. Degenerate faces (no normal) are skipped.
class CageProximity {
 public:
  explicit CageProximity(const Cage& cage);

  struct Closest {
    enum class On { Face, Edge, Vertex };  // 2D: Face = inside an edge of the polygon, Vertex = at a corner
    Eigen::VectorXd point;                 // c (d)
    Eigen::VectorXd normal;                // unit outward pseudo-normal at c (d)
    double distance = 0;                   // |x - c|
    int face = -1;                         // a face holding c
    On on = On::Face;
    int corner = 0;  // On::Vertex: that corner of `face`; On::Edge: the edge from that corner to the next
  };
  Closest closest(const Eigen::VectorXd& x) const;

  // Moves c to the next coarser feature of its face (the inside -> the nearest edge -> that edge's nearest corner)
  // with that feature's pseudo-normal; false at a corner. A proxy stepped in from a face or an edge close to a
  // sharp edge or corner can leave the cage through the neighbouring face; from the coarser feature it cannot.
  bool coarsen(Closest& c) const;

 private:
  void setNormal(Closest& c) const;

  Cage cage_;
  std::vector<bool> skip_;         // #F: degenerate faces
  Eigen::MatrixXd faceNormals_;    // #F by d
  Eigen::MatrixXd edgeNormals_;    // 3D: #F * 3 by 3, row 3j + k for the edge from corner k to corner k + 1
  Eigen::MatrixXd vertexNormals_;  // #V by d
};

}  // namespace somicage
