// MEDIT ASCII meshes (.mesh, the format of Mesh_3, TetGen's -g and Gmsh): the volume mesh of a cage for the Phong
// deformer (volume_mesh.h). Read:
//   MeshVersionFormatted 1 | 2
//   Dimension 3 | 2
//   Vertices  N   then N lines "x y [z] ref"
//   Tetrahedra M  then M lines "a b c d ref" (1-based; in 2D: Triangles, "a b c ref")
//   End
// Other sections (Triangles in 3D, Edges, Corners, Ridges, Required*) are skipped; `#` starts a comment. Every
// problem throws InputError naming the file, the line, what is wrong and what to do.
#pragma once

#include <string>

#include "geometry/volume_mesh.h"

namespace somicage {

struct MeditMesh {
  VolumeMesh mesh;
  VolumeMeshSource source;  // the file and each vertex's and element's line, for checkVolumeMesh
};

// Parses MEDIT text; source names it in errors (normally the path).
MeditMesh parseMedit(const std::string& text, const std::string& source);
MeditMesh readMedit(const std::string& path);

// The mesh as MEDIT text (references 0, 17 significant digits: reads back bit for bit).
std::string formatMedit(const VolumeMesh& mesh);

}  // namespace somicage
