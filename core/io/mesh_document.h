// A mesh with everything its file carries besides positions, so that a deformed mesh can be written back
// without losing UVs, groups, objects, materials or smoothing groups.
//
// The geometry (positions, faces, polylines) is what the engine deforms; it comes from the format's reader
// (OBJ: parseObj, the one OBJ parser; other formats: mesh_formats.h). An OBJ document also keeps every record of
// the file in order, collected in parseObj's one pass (ObjLineVisitor): `vt`, `g`, `o`, `usemtl`, `mtllib`, `s`, `f`
// and `l` lines (face index triples included) and comments are written back verbatim; `v` lines get the new positions
// (any extra tokens, e.g. vertex colours, kept); `vn` lines get the deformed normals: transformed by the deformation's
// gradient (normal_transform.h) or recomputed for the new positions (recomputeNormals).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "io/mesh_material.h"
#include "io/obj_io.h"

namespace somicage {

// One record of an OBJ file, in file order.
struct ObjRecord {
  enum class Kind { Text, Position, Normal };
  Kind kind = Kind::Text;
  int index = -1;    // Position: the vertex (0-based); Normal: the normal (0-based)
  std::string text;  // Text: the line as written; Position: the tokens after x y z (may be empty)
};

struct MeshDocument {
  std::string sourcePath;  // the file it was read from (relative `mtllib` names resolve next to it)
  PolygonMesh geometry;
  std::vector<ObjRecord> records;  // empty: the document was not read from OBJ (write geometry only)
  int normalCount = 0;             // `vn` records
  Eigen::MatrixXd normals;         // normalCount by 3, as read
  // Per face (geometry.faces order), per corner: the 0-based `vn` index, or -1 when the corner has none.
  std::vector<std::vector<int>> faceNormals;
  // Per face, per corner: the 0-based `vt` index, or -1 (used by the GLB writer, which carries UVs per vertex).
  std::vector<std::vector<int>> faceUVs;
  Eigen::MatrixXd uvs;                    // #vt by 2
  std::vector<std::string> faceMaterial;  // per face: the `usemtl` name in effect ("" = none)
  // Materials the file itself defines (assimp formats); OBJ's come from its .mtl libraries (documentMaterials).
  std::vector<MeshMaterial> materials;
};

// Parses OBJ text into a document (geometry through parseObj). source names it in errors and resolves mtllib.
MeshDocument parseObjDocument(const std::string& text, const std::string& source);

// Normals for the given positions (#V by 3), one per `vn` record of the document: the corner-angle-weighted sum
// of the unit normals of the faces whose corners use that `vn` index (polygons: Newell normal), so a file with
// one normal per vertex gets smooth normals and a file with split normals keeps its creases. A `vn` no face
// uses keeps its value. Zero-area faces add nothing; a normal with nothing added keeps its value.
Eigen::MatrixXd recomputeNormals(const MeshDocument& document, const Eigen::MatrixXd& positions);

// Writes the document as OBJ with the given positions (#V by 2 or 3; 2 columns: z = 0), %.17g, a final newline,
// atomically. `mtllib` lines whose file lies next to the source are rewritten as a path relative to the output's
// folder when the output goes elsewhere, so the materials (and the textures they name) still resolve.
// normals: one per `vn` record (normalCount by 3, e.g. transformNormals); empty: recomputeNormals of positions.
// A document without records is written as saveObj does.
void writeObjDocument(const std::string& path, const MeshDocument& document, const Eigen::MatrixXd& positions,
                      const Eigen::MatrixXd& normals = Eigen::MatrixXd());

// The materials a document's faces name, in order of first use (faceMaterial), each found in the file's own
// materials or in its .mtl libraries; a material found nowhere is white. notes: one sentence per library that
// could not be read and per material that is not defined.
struct DocumentMaterials {
  std::vector<MeshMaterial> materials;
  std::vector<std::string> notes;
};
DocumentMaterials documentMaterials(const MeshDocument& document);

}  // namespace somicage
