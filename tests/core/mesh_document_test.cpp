// Lossless OBJ export: every record but the positions and normals comes back verbatim and in order, positions
// are exact, the final newline is there, mtllib still resolves from another folder, and the recomputed normals
// match closed forms (an affine map of a flat patch: A^-T n; a cube with split normals: the face axes).
#include "io/mesh_document.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <Eigen/Geometry>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/errors.h"
#include "base/file_util.h"
#include "scratch_folder.h"

namespace somicage {
namespace {

namespace fs = std::filesystem;

using test::ScratchFolder;

// A textured quad split in two groups and two materials, with per-vertex normals and a vertex colour token.
const char* const kTexturedObj =
    "# a textured quad\n"
    "mtllib quad.mtl\n"
    "o Quad\n"
    "v 0 0 0 0.5 0.5 0.5\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n"
    "vt 0 0\n"
    "vt 1 0\n"
    "vt 1 1\n"
    "vt 0 1\n"
    "vn 0 0 1\n"
    "vn 0 0 1\n"
    "vn 0 0 1\n"
    "vn 0 0 1\n"
    "g left\n"
    "usemtl red\n"
    "s 1\n"
    "f 1/1/1 2/2/2 3/3/3\n"
    "g right\n"
    "usemtl blue\n"
    "s off\n"
    "f 1/1/1 3/3/3 4/4/4";  // no final newline

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

bool isPositionOrNormal(const std::string& line) { return line.rfind("v ", 0) == 0 || line.rfind("vn ", 0) == 0; }

TEST(MeshDocument, RestRoundTripKeepsEveryOtherRecordVerbatimAndPositionsExact) {
  ScratchFolder folder;
  const MeshDocument document = parseObjDocument(kTexturedObj, folder / "quad.obj");
  const std::string out = folder / "out.obj";
  writeObjDocument(out, document, document.geometry.vertices);
  const std::string written = readTextFile(out);
  ASSERT_FALSE(written.empty());
  EXPECT_EQ(written.back(), '\n');

  const std::vector<std::string> before = linesOf(kTexturedObj), after = linesOf(written);
  ASSERT_EQ(before.size(), after.size());
  for (size_t k = 0; k < before.size(); ++k) {
    if (!isPositionOrNormal(before[k])) {
      EXPECT_EQ(after[k], before[k]) << "line " << k + 1;
    }
  }
  EXPECT_EQ(after[3].substr(after[3].size() - 12), " 0.5 0.5 0.5") << "extra tokens of `v` are kept";
  const MeshDocument reread = parseObjDocument(written, out);
  EXPECT_LE((reread.geometry.vertices - document.geometry.vertices).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(reread.geometry.faces, document.geometry.faces);
  EXPECT_EQ(reread.faceUVs, document.faceUVs);
  EXPECT_EQ(reread.faceMaterial, (std::vector<std::string>{"red", "blue"}));
}

TEST(MeshDocument, MaterialLibraryResolvesFromAnotherFolder) {
  ScratchFolder folder;
  fs::create_directories(folder / "in");
  fs::create_directories(folder / "elsewhere/deep");
  std::ofstream(folder / "in/quad.mtl") << "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n";
  const MeshDocument document = parseObjDocument(kTexturedObj, folder / "in/quad.obj");
  const fs::path out = folder / "elsewhere/deep/out.obj";
  writeObjDocument(out.string(), document, document.geometry.vertices);
  const std::vector<std::string> lines = linesOf(readTextFile(out.string()));
  ASSERT_EQ(lines[1].rfind("mtllib ", 0), 0u);
  const fs::path named = out.parent_path() / lines[1].substr(7);
  EXPECT_TRUE(fs::equivalent(named, folder / "in/quad.mtl")) << lines[1];

  // Written next to the source, the line stays as it was.
  writeObjDocument(folder / "in/copy.obj", document, document.geometry.vertices);
  EXPECT_EQ(linesOf(readTextFile(folder / "in/copy.obj"))[1], "mtllib quad.mtl");
}

TEST(MeshDocument, NormalsOfAnAffinelyMappedFlatPatchAreTheInverseTransposeNormal) {
  const MeshDocument document = parseObjDocument(kTexturedObj, "quad.obj");
  Eigen::Matrix3d A;
  A << 1.3, 0.2, -0.4, 0.1, 0.9, 0.3, 0.5, -0.2, 1.1;
  const Eigen::MatrixXd mapped = document.geometry.vertices * A.transpose();
  const Eigen::Vector3d expected = (A.inverse().transpose() * Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::MatrixXd normals = recomputeNormals(document, mapped);
  ASSERT_EQ(normals.rows(), 4);
  for (int i = 0; i < 4; ++i) EXPECT_LE((normals.row(i).transpose() - expected).norm(), 1e-12) << i;
}

TEST(MeshDocument, SplitNormalsOfACubeStayFaceNormals) {
  std::string obj =
      "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
      "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 1 0 0\nvn 0 1 0\nvn -1 0 0\n"
      "f 1//1 4//1 3//1 2//1\nf 5//2 6//2 7//2 8//2\nf 1//3 2//3 6//3 5//3\n"
      "f 2//4 3//4 7//4 6//4\nf 3//5 4//5 8//5 7//5\nf 4//6 1//6 5//6 8//6\n";
  const MeshDocument document = parseObjDocument(obj, "cube.obj");
  // A non-uniform scale keeps the faces axis-aligned, so the normals must stay the axes.
  const Eigen::MatrixXd scaled = document.geometry.vertices * Eigen::Vector3d(2, 0.5, 3).asDiagonal();
  const Eigen::MatrixXd normals = recomputeNormals(document, scaled);
  EXPECT_LE((normals - document.normals).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(MeshDocument, BadTextureOrNormalIndexNamesTheLine) {
  try {
    parseObjDocument("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n", "bad.obj");
    FAIL() << "a `vt` index past the records must be rejected";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 5);
    EXPECT_NE(e.problem().find("texture index '2'"), std::string::npos) << e.what();
  }
}

// `vn` and `vt` numbers are read by the `v` line's parser (parseObjNumber): the whole token, finite. Before, they were
// read with from_chars alone, which stops at the first character it cannot use, so "1.5x" was 1.5.
TEST(MeshDocument, NormalAndUvNumbersAreCheckedAsPositionsAre) {
  for (const std::string bad : {"vn 1.5x 0 0", "vt 0.5 1e", "vn 0 nan 1", "vt inf 0", "vn 0 0 1e999", "vt 0.5 --1"}) {
    try {
      parseObjDocument("v 0 0 0\nv 1 0 0\nv 0 1 0\n" + bad + "\nf 1 2 3\n", "bad.obj");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), 4) << e.what();
      EXPECT_NE(e.problem().find("is not a finite decimal number"), std::string::npos) << e.what();
    }
  }
  const MeshDocument good = parseObjDocument("v 0 0 0\nvn +0.5 -0.25 1e-3\nvt 0.125 .5\n", "good.obj");
  EXPECT_EQ(good.normals.row(0), Eigen::RowVector3d(0.5, -0.25, 1e-3));
  EXPECT_EQ(good.uvs.row(0).head(2), Eigen::RowVector2d(0.125, 0.5));
}

}  // namespace
}  // namespace somicage
