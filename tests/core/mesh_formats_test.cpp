// Mesh formats: one small mesh written by the test in each format gives the same vertices, in the same order,
// and the same faces as the OBJ of that mesh (coordinates are multiples of 1/4, exact in the 32-bit floats that
// assimp reads with); STL and FBX bring one vertex per face corner, which --weld joins back; the PLY and GLB
// writers read back (through assimp) as written.
#include "io/mesh_formats.h"

#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "base/errors.h"
#include "scratch_folder.h"

namespace somicage {
namespace {

namespace fs = std::filesystem;

using test::ScratchFolder;

// A square pyramid (a quad base, four triangles) and one vertex no face uses.
const std::vector<std::array<double, 3>> kVertices = {{0, 0, 0}, {1, 0, 0},        {1, 1, 0},
                                                      {0, 1, 0}, {0.5, 0.5, 0.75}, {2.25, -1.5, 0.25}};
const std::vector<std::vector<int>> kFaces = {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};

std::string objText() {
  std::string text;
  for (const auto& v : kVertices)
    text += "v " + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
  for (const auto& f : kFaces) {
    text += "f";
    for (const int i : f) text += " " + std::to_string(i + 1);
    text += "\n";
  }
  return text;
}

// The vertices, one line each, then the faces as "count i j k ..." (0-based): the body of PLY and OFF files.
std::string countedText() {
  std::string text;
  for (const auto& v : kVertices)
    text += std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
  for (const auto& f : kFaces) {
    text += std::to_string(f.size());
    for (const int i : f) text += " " + std::to_string(i);
    text += "\n";
  }
  return text;
}

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

void expectSameAsObj(const PolygonMesh& mesh, const PolygonMesh& obj) {
  ASSERT_EQ(mesh.numVertices(), obj.numVertices());
  EXPECT_EQ((mesh.vertices - obj.vertices).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(mesh.faces, obj.faces);
}

class MeshFormats : public ::testing::Test {
 protected:
  void SetUp() override {
    write(folder / "mesh.obj", objText());
    obj = loadAnyMesh(folder / "mesh.obj");
  }
  ScratchFolder folder;
  PolygonMesh obj;
};

TEST_F(MeshFormats, PlyGivesTheObjVerticesInOrder) {
  std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 5\nproperty list uchar int vertex_indices\nend_header\n";
  write(folder / "mesh.ply", ply + countedText());
  expectSameAsObj(loadAnyMesh(folder / "mesh.ply"), obj);
}

TEST_F(MeshFormats, OffGivesTheObjVerticesInOrder) {
  write(folder / "mesh.off", "OFF\n6 5 0\n" + countedText());
  expectSameAsObj(loadAnyMesh(folder / "mesh.off"), obj);
}

std::string base64(const std::string& bytes) {
  static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned a = static_cast<unsigned char>(bytes[i]);
    const unsigned b = i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) : 0;
    const unsigned c = i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0;
    const unsigned triple = a << 16 | b << 8 | c;
    out += kAlphabet[triple >> 18 & 63];
    out += kAlphabet[triple >> 12 & 63];
    out += i + 1 < bytes.size() ? kAlphabet[triple >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[triple & 63] : '=';
  }
  return out;
}

TEST_F(MeshFormats, GltfGivesTheObjVerticesInOrder) {
  // glTF has triangles only: the base quad as two triangles, in the OBJ's winding.
  const std::vector<uint32_t> indices = {0, 3, 2, 0, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  std::string bytes;
  for (const auto& v : kVertices) {
    for (const double x : v) {
      const float f = static_cast<float>(x);
      bytes.append(reinterpret_cast<const char*>(&f), sizeof f);
    }
  }
  const size_t positionBytes = bytes.size();
  for (const uint32_t i : indices) bytes.append(reinterpret_cast<const char*>(&i), sizeof i);
  const std::string gltf =
      R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "buffers": [{"byteLength": )" +
      std::to_string(bytes.size()) + R"(, "uri": "data:application/octet-stream;base64,)" + base64(bytes) + R"("}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" +
      std::to_string(positionBytes) + R"(}, {"buffer": 0, "byteOffset": )" + std::to_string(positionBytes) +
      R"(, "byteLength": )" + std::to_string(indices.size() * 4) + R"(}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 6, "type": "VEC3",
                   "min": [0, -1.5, 0], "max": [2.25, 1, 0.75]},
                  {"bufferView": 1, "componentType": 5125, "count": 18, "type": "SCALAR"}]})";
  write(folder / "mesh.gltf", gltf);
  const PolygonMesh mesh = loadAnyMesh(folder / "mesh.gltf");
  ASSERT_EQ(mesh.numVertices(), obj.numVertices());
  EXPECT_EQ((mesh.vertices - obj.vertices).cwiseAbs().maxCoeff(), 0.0);
  ASSERT_EQ(mesh.faces.size(), 6u);
  for (size_t f = 0; f < 6; ++f) {
    EXPECT_EQ(mesh.faces[f], (std::vector<int>{static_cast<int>(indices[3 * f]), static_cast<int>(indices[3 * f + 1]),
                                               static_cast<int>(indices[3 * f + 2])}));
  }
}

// The mesh welded from per-corner vertices: vertex j is the OBJ vertex that appears j-th in the faces, and each
// face is the OBJ face renumbered so.
void expectWeldedObj(const PolygonMesh& welded, const PolygonMesh& obj, const std::vector<std::vector<int>>& objFaces) {
  std::vector<int> order, renumber(static_cast<size_t>(obj.numVertices()), -1);
  for (const auto& face : objFaces) {
    for (const int i : face) {
      if (renumber[static_cast<size_t>(i)] < 0)
        renumber[static_cast<size_t>(i)] = static_cast<int>(order.size()), order.push_back(i);
    }
  }
  ASSERT_EQ(welded.numVertices(), static_cast<int>(order.size()));
  for (size_t j = 0; j < order.size(); ++j)
    EXPECT_EQ(welded.vertices.row(static_cast<Eigen::Index>(j)), obj.vertices.row(order[j])) << j;
  ASSERT_EQ(welded.faces.size(), objFaces.size());
  for (size_t f = 0; f < objFaces.size(); ++f) {
    std::vector<int> expected;
    for (const int i : objFaces[f]) expected.push_back(renumber[static_cast<size_t>(i)]);
    EXPECT_EQ(welded.faces[f], expected) << "face " << f;
  }
}

// STL and assimp's FBX bring one vertex per face corner; weld joins them in order of first appearance.
TEST_F(MeshFormats, StlHasOneVertexPerCornerAndWeldJoinsThem) {
  std::string stl = "solid pyramid\n";
  std::vector<std::vector<int>> triangles = {{0, 3, 2}, {0, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  for (const auto& t : triangles) {
    stl += " facet normal 0 0 0\n  outer loop\n";
    for (const int i : t)
      stl += "   vertex " + std::to_string(kVertices[i][0]) + " " + std::to_string(kVertices[i][1]) + " " +
             std::to_string(kVertices[i][2]) + "\n";
    stl += "  endloop\n endfacet\n";
  }
  stl += "endsolid pyramid\n";
  write(folder / "mesh.stl", stl);
  const PolygonMesh soup = loadAnyMesh(folder / "mesh.stl");
  ASSERT_EQ(soup.numVertices(), 18);
  for (int c = 0; c < 18; ++c) {
    const auto& expected = kVertices[static_cast<size_t>(triangles[c / 3][c % 3])];
    EXPECT_EQ(soup.vertices.row(c), Eigen::RowVector3d(expected[0], expected[1], expected[2])) << c;
  }
  expectWeldedObj(loadAnyMesh(folder / "mesh.stl", ReadOptions{true}), obj, triangles);
}

TEST_F(MeshFormats, FbxWrittenByAssimpWeldsBackToTheObj) {
  // The scene assimp reads from our OBJ, written as ASCII FBX by assimp's exporter, its unit set to metres
  // (UnitScaleFactor 100 cm; assimp writes 1, centimetres, which would read as 1/100 of the OBJ: tests/app's
  // mesh_units_test.cpp).
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(folder / "mesh.obj", 0);
  ASSERT_NE(scene, nullptr);
  Assimp::Exporter exporter;
  ASSERT_EQ(exporter.Export(scene, "fbxa", folder / "mesh.fbx"), AI_SUCCESS) << exporter.GetErrorString();
  std::ifstream in(folder / "mesh.fbx", std::ios::binary);
  std::string fbx((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string unit = "\"UnitScaleFactor\", \"double\", \"Number\", \"\", 1\n";
  ASSERT_NE(fbx.find(unit), std::string::npos);
  fbx.replace(fbx.find(unit), unit.size(), "\"UnitScaleFactor\", \"double\", \"Number\", \"\", 100\n");
  write(folder / "mesh.fbx", fbx);
  expectWeldedObj(loadAnyMesh(folder / "mesh.fbx", ReadOptions{true}), obj, kFaces);
}

TEST_F(MeshFormats, PlyAndGlbWritersReadBackAsWritten) {
  const MeshDocument document = loadMeshDocument(folder / "mesh.obj");
  Eigen::MatrixXd moved = document.geometry.vertices;
  moved.col(2).array() += 0.5;
  EXPECT_TRUE(writeMeshDocument(folder / "out.ply", document, moved).empty());
  const PolygonMesh ply = loadAnyMesh(folder / "out.ply");
  EXPECT_EQ(ply.vertices, moved);
  EXPECT_EQ(ply.faces, obj.faces);

  EXPECT_TRUE(writeMeshDocument(folder / "out.glb", document, moved).empty());
  const PolygonMesh glb = loadAnyMesh(folder / "out.glb");
  EXPECT_EQ(glb.vertices, moved);  // no UVs: glTF vertex i is mesh vertex i
  EXPECT_EQ(glb.faces.size(), 6u);
}

TEST_F(MeshFormats, UnknownFormatsAndWhatAFormatCannotCarryAreNamed) {
  write(folder / "mesh.xyz", "1 2 3\n");
  try {
    loadAnyMesh(folder / "mesh.xyz");
    FAIL() << "an unknown extension must be rejected";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(".obj, .ply, .stl, .off, .gltf, .glb, .fbx"), std::string::npos) << e.what();
  }
  const MeshDocument document = loadMeshDocument(folder / "mesh.obj");
  EXPECT_THROW(writeMeshDocument(folder / "out.stl", document, document.geometry.vertices), InputError);
  EXPECT_FALSE(fs::exists(folder / "out.stl"));

  write(folder / "textured.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl red\nf 1/1 2/1 3/1\n");
  const MeshDocument textured = loadMeshDocument(folder / "textured.obj");
  const std::vector<std::string> notes =
      writeMeshDocument(folder / "textured.ply", textured, textured.geometry.vertices);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_NE(notes[0].find("UVs"), std::string::npos);
  EXPECT_NE(notes[1].find("materials"), std::string::npos);
}

}  // namespace
}  // namespace somicage
