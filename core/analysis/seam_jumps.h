// C0 seams (issue 25, the paper's Fig. 8): where an edge of the deformed mesh crosses a face between two simplices of
// a volume mesh of the cage (volume_mesh.h), the jump of the deformation gradient J across that face,
//   |J+ - J-|_F / (1/2 (|J+|_F + |J-|_F))          (Frobenius norms; deformation_quantities.h: gradientJump)
// with each side's J the method's exact J (jacobian.h) at the crossing point evaluated in that side's simplex
// (PrecomputeOptions::pointSimplices). Phong's J is its own quadratic per simplex, so it jumps; the smooth methods'
// rows do not depend on the simplex (one function of the point), so both sides are the same evaluation and the jump
// is 0 up to round-off. For a smooth method the volume mesh is the one Phong would use for that cage (volumeMeshFor),
// so the numbers compare.
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "deform/deformer.h"
#include "deform/jacobian.h"
#include "geometry/volume_mesh.h"

namespace somicage {

// Where the mesh's edges cross the volume mesh's interior faces, at rest.
struct SeamCrossings {
  std::vector<int> holders;               // #P: the simplex holding each mesh vertex (-1: outside the mesh)
  std::vector<std::array<int, 2>> edges;  // the mesh's edges that cross a face (vertex indices, first < second)
  Eigen::MatrixXd points;                 // #K by d: the crossing points
  std::vector<int> edge;                  // #K: the crossing's edge (index into edges)
  std::vector<std::array<int, 2>> sides;  // #K: the simplex before and the one after the face, along the edge
};

// Walks each edge of `faces` (over restPoints, #P by d; polygons give their boundary edges) from the simplex holding
// its first vertex to the one holding its second, through the faces it leaves by. An edge with a vertex in no simplex
// (outside the cage) crosses nothing; an edge that leaves the mesh on the way (a concave cage) stops there.
SeamCrossings findSeamCrossings(const VolumeMesh& mesh, const std::vector<std::vector<int>>& faces,
                                const Eigen::MatrixXd& restPoints);

// The measured seams of one pose.
struct SeamJumps {
  Eigen::VectorXd edges;     // per SeamCrossings::edges: the largest jump over the edge's crossings (NaN: no J)
  Eigen::VectorXd vertices;  // #P: the largest over the vertex's crossing edges; 0 when none; NaN outside the mesh
};

// The method's deformer at the crossing points, from each side, with its J: made once per cage, mesh and points,
// evaluated per pose. Costs a precompute and the gradients of 2 #K points (engine.h: prepareSeamJumps checks the
// memory first).
class SeamJumpEvaluator {
 public:
  // crossings: findSeamCrossings over `mesh`; options: the precompute options of the method's deformer (the volume
  // mesh becomes `mesh`, the points' simplices the crossings' sides).
  SeamJumpEvaluator(Method method, const Cage& restCage, std::shared_ptr<const VolumeMesh> mesh,
                    SeamCrossings crossings, PrecomputeOptions options, const ProgressCallback& progress = noProgress);

  const SeamCrossings& crossings() const { return crossings_; }
  const VolumeMesh& mesh() const { return *mesh_; }
  std::size_t bytes() const;
  SeamJumps evaluate(const Eigen::MatrixXd& posedVertices, const DeformParams& params) const;

 private:
  std::shared_ptr<const VolumeMesh> mesh_;
  SeamCrossings crossings_;
  std::unique_ptr<CageDeformer> deformer_;    // rows 0 .. #K - 1: side 0, #K .. 2 #K - 1: side 1
  std::unique_ptr<DeformationGradients> gradients_;  // of deformer_ (declared after it: destroyed first)
};

}  // namespace somicage
