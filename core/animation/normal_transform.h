// Normals of a deformed mesh carried by the deformation's gradient instead of recomputed from the new faces:
// a normal n at a point where the map has gradient J becomes n' = normalize(cof(J) n), cof(J) = det(J) J^-T, the
// way a surface's normal (a covector) transforms under f. For det J > 0 this is normalize(J^-T n); cof keeps the
// normal on the same side of its faces where the map folds over (det J < 0). An affine map A gives A^-T n exactly.
//
// An OBJ `vn` is named per face corner: it takes the J of the corner's vertex; a `vn` named by corners at several
// vertices gets the normalised sum of their transformed normals. A `vn` some of whose corners have no usable J
// (the vertex follows the exterior rule, so J is undefined, or cof(J) n vanishes) is recomputed from the deformed
// faces instead (recomputeNormals), as is the whole mesh when no J is available at all.
#pragma once

#include <Eigen/Core>

#include "deform/jacobian.h"
#include "io/mesh_document.h"

namespace somicage {

struct TransformedNormals {
  Eigen::MatrixXd normals;  // document.normalCount by 3, one per `vn` record
  int recomputed = 0;       // `vn` records that fell back to recomputeNormals
};

// positions: the deformed mesh (#V by 2 or 3); jacobians: #V by d*d, row-major per vertex (column a*d + b holds
// df_a/dx_b, DeformationGradients::evaluate), NaN rows where J is undefined. A 2D map (d = 2) moves x, y and keeps
// z: its J is extended by J_zz = 1. A `vn` no face names keeps its value.
TransformedNormals transformNormals(const MeshDocument& document, const Eigen::MatrixXd& positions,
                                    const Eigen::MatrixXd& jacobians);

// The same for a pose: J evaluated from gradients (made for the document's vertices) at the posed cage.
TransformedNormals transformNormals(const MeshDocument& document, const Eigen::MatrixXd& positions,
                                    const DeformationGradients& gradients, const Eigen::MatrixXd& posedVertices,
                                    const DeformParams& params);

}  // namespace somicage
