// MEDIT .mesh reading (core/geometry/medit_io.cpp): round trip, skipped sections, and a specific error per bad file.
#include "geometry/medit_io.h"

#include <gtest/gtest.h>

#include <string>

#include "base/errors.h"

namespace somicage {
namespace {

const char* const kTwoTets =
    "MeshVersionFormatted 2\n"
    "Dimension 3\n"
    "# a comment\n"
    "Vertices\n"
    "5\n"
    "0 0 0 1\n"
    "1 0 0 1\n"
    "0 1 0 1\n"
    "0 0 1 1\n"
    "0 0 -1 1\n"
    "Triangles\n"
    "1\n"
    "1 2 3 7\n"
    "Tetrahedra\n"
    "2\n"
    "1 2 3 4 0\n"
    "1 3 2 5 0\n"
    "End\n";

TEST(MeditIo, ReadsVerticesAndTetrahedraWithTheirLines) {
  const MeditMesh m = parseMedit(kTwoTets, "two.mesh");
  ASSERT_EQ(m.mesh.numVertices(), 5);
  ASSERT_EQ(m.mesh.numSimplices(), 2);
  EXPECT_EQ(m.mesh.vertices.row(3), Eigen::RowVector3d(0, 0, 1));
  EXPECT_EQ(m.mesh.simplices.row(1), Eigen::RowVector4i(0, 2, 1, 4));  // 1-based in the file
  EXPECT_EQ(m.source.vertexLines[0], 6);
  EXPECT_EQ(m.source.simplexLines[1], 17);
}

TEST(MeditIo, WritesWhatItReadsBitForBit) {
  MeditMesh m = parseMedit(kTwoTets, "two.mesh");
  m.mesh.vertices(2, 1) = 0.1 + 0.2;  // not a short decimal
  const MeditMesh back = parseMedit(formatMedit(m.mesh), "back.mesh");
  EXPECT_EQ(back.mesh.vertices, m.mesh.vertices);
  EXPECT_EQ(back.mesh.simplices, m.mesh.simplices);
}

// Each bad file: the line and the words of its error.
TEST(MeditIo, NamesTheLineAndTheProblemOfABadFile) {
  struct Case {
    std::string text;
    long line;
    std::string words;
  };
  const std::string head = "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n";
  const Case cases[] = {
      {head + "Tetrahedra\n1\n1 2 3 5 0\nEnd\n", 11, "outside [1, 4]"},
      {head + "Tetrahedra\n1\n1 2 3 x 0\nEnd\n", 11, "not a whole number"},
      {head + "Tetrahedra\n1\n1 2 3 4 0\n", 12, "no End"},  // the line after the last
      {head + "Tetrahedra\n2\n1 2 3 4 0\n", 12, "file ends"},
      {head + "Hexagons\n1\nEnd\n", 9, "unknown keyword 'Hexagons'"},
      {head + "End\n", 9, "no Tetrahedra"},
      {"MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 nan 0 0\nEnd\n", 5, "not a finite number"},
      {"MeshVersionFormatted 2\nVertices\n1\n0 0 0 0\nEnd\n", 2, "before Dimension"},
      {"Dimension 4\n", 1, "outside [2, 3]"},
  };
  for (const Case& c : cases) {
    try {
      parseMedit(c.text, "bad.mesh");
      ADD_FAILURE() << "no error for: " << c.words;
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "bad.mesh");
      EXPECT_EQ(e.line(), c.line) << c.words << ": " << e.what();
      EXPECT_NE(e.problem().find(c.words), std::string::npos) << e.problem();
    }
  }
}

TEST(MeditIo, ReadsATriangulationIn2D) {
  const MeditMesh m = parseMedit(
      "MeshVersionFormatted 1\r\nDimension 2\r\nVertices\r\n3\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\nTriangles\r\n1\r\n1 2 3 "
      "0\r\nEnd\r\n",
      "tri.mesh");
  EXPECT_EQ(m.mesh.dim(), 2);
  EXPECT_EQ(m.mesh.numSimplices(), 1);
  EXPECT_EQ(m.source.simplexLines[0], 10);
}

}  // namespace
}  // namespace somicage
