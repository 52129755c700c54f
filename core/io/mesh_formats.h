// Mesh files by format: which formats are read and written, chosen by the file's extension.
//
// Read: .obj (parseObjDocument: every record kept), and .ply .stl .off .gltf .glb .fbx through assimp, with no
// post-processing step that welds, reorders or drops vertices, so vertex i of the file is vertex i of the mesh
// (a cage's posed and rest files match index for index). Coordinates come in metres where the format has a unit:
// FBX's unit scale (UnitScaleFactor, centimetres per unit) is applied, as are its nodes' transforms; glTF is in
// metres by its specification; OBJ, PLY, STL and OFF have no unit and read as written. assimp stores coordinates as
// 32-bit floats, so these formats read with float precision. A file with several meshes gives their vertices one after
// the other, in the file's mesh order, each moved by the transform of the first node that shows it. STL has no shared
// vertices: each triangle brings its own three, so a closed STL surface reads as a soup; ReadOptions::weld joins
// vertices at exactly equal positions (in order of first appearance), which a cage read from STL needs.
//
// Written: .obj (writeObjDocument: lossless), .ply (binary, double positions and the polygons; nothing else)
// and .glb (gltf_writer.h: triangles, UVs, materials with their colours and textures). What a format cannot carry is
// named in the returned notes, never dropped silently.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "io/mesh_document.h"

namespace somicage {

struct ReadOptions {
  bool weld = false;  // join vertices at exactly equal positions (first appearance order)
};

// Throws InputError for an unknown extension (naming the known ones) and for anything the reader rejects.
MeshDocument loadMeshDocument(const std::string& path, const ReadOptions& options = {});

// The geometry of loadMeshDocument: the one mesh loader of every command, the editor and Python, for meshes and
// cages of any supported format (an OBJ gives what loadMesh gives, obj_io.h).
PolygonMesh loadAnyMesh(const std::string& path, const ReadOptions& options = {});
// loadAnyMesh + cageFromMesh (obj_io.h): the cage as written, not repaired (engine.h's loadUsableCage repairs).
Cage loadCage(const std::string& path, const ReadOptions& options = {});
// loadAnyMesh + posedVerticesFromMesh: a posed cage file's vertices, checked against the rest cage.
Eigen::MatrixXd loadPosedVertices(const std::string& path, const Cage& restCage, const ReadOptions& options = {});

// Whether ReadOptions::weld applies to path's format: every format read through assimp (all but OBJ), whose files
// may repeat a vertex per face corner (STL always, FBX as assimp expands it, glTF at UV and normal seams).
bool weldApplies(const std::string& path);

// Writes document with the given positions (#V by 2 or 3) in the format of path's extension, atomically.
// normals: the deformed `vn` normals (writeObjDocument; empty: recomputed). Returns one sentence per kind of data the
// format could not carry (empty: nothing was lost).
std::vector<std::string> writeMeshDocument(const std::string& path, const MeshDocument& document,
                                           const Eigen::MatrixXd& positions,
                                           const Eigen::MatrixXd& normals = Eigen::MatrixXd());

// "obj, ply, ..." for help texts.
std::string readableExtensions();
std::string writableExtensions();

// Joins vertices at exactly equal positions, in order of first appearance, and renumbers faces and lines.
PolygonMesh weldVertices(const PolygonMesh& mesh);

}  // namespace somicage
