// .mtl parsing: colours, opacity from `d` (which wins over `Tr`) or 1 - `Tr`, map_Kd's file after its options
// (a name with blanks and Windows separators included) resolved next to the .mtl, and errors that name the line.
#include "io/mesh_material.h"

#include <gtest/gtest.h>

#include "base/errors.h"

namespace somicage {
namespace {

TEST(ParseMtl, ColoursOpacityAndTextureFiles) {
  const std::vector<MeshMaterial> materials = parseMtl(
      "# comment\r\nnewmtl a\r\nKd 0.1 0.2 0.3\r\nTr 0.4\r\n"
      "newmtl b\nd -halo 0.6\nTr 0.9\nmap_Kd -blendu on -s 2 2 -o 0.5 tex\\my skin.png\n"
      "newmtl c\nmap_Kd /abs/c.jpg\nNs 10\n",
      "/models/m.mtl");
  ASSERT_EQ(materials.size(), 3u);
  EXPECT_EQ(materials[0].name, "a");
  EXPECT_TRUE(materials[0].baseColor.isApprox(Eigen::Vector4d(0.1, 0.2, 0.3, 0.6), 1e-15));
  EXPECT_TRUE(materials[0].texturePath.empty());
  EXPECT_EQ(materials[1].baseColor, Eigen::Vector4d(1, 1, 1, 0.6)) << "d wins over a later Tr";
  EXPECT_EQ(materials[1].texturePath, "/models/tex/my skin.png");
  EXPECT_EQ(materials[2].texturePath, "/abs/c.jpg");
  EXPECT_EQ(materials[2].baseColor, Eigen::Vector4d(1, 1, 1, 1)) << "white and opaque unless said";
}

TEST(ParseMtl, BadValuesNameTheLine) {
  const auto expectError = [](const std::string& text, long line, const std::string& what) {
    try {
      parseMtl(text, "m.mtl");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_NE(e.problem().find(what), std::string::npos) << e.what();
    }
  };
  expectError("newmtl a\nKd 0.5 0.5\n", 2, "needs 3 numbers");
  expectError("newmtl a\n\nKd 0.5 1.5 0.5\n", 3, "'1.5' is not a colour component in [0, 1]");
  expectError("Kd 1 1 1\n", 1, "before any `newmtl`");
  expectError("newmtl a\nmap_Kd -s 1 1 1\n", 2, "names no file");
  expectError("newmtl a\nd nan\n", 2, "opacity");
}

// Classic Mac OS line ends (a lone CR), as the OBJ parser takes them: before, std::getline saw one line, so the
// materials after the first were lost and a colour read "0.1 0.2 0.3\rKd" as its numbers.
TEST(ParseMtl, CarriageReturnOnlyFilesHaveLines) {
  const std::vector<MeshMaterial> materials = parseMtl("newmtl a\rKd 0.1 0.2 0.3\rnewmtl b\rd 0.25\r", "m.mtl");
  ASSERT_EQ(materials.size(), 2u);
  EXPECT_EQ(materials[0].baseColor, Eigen::Vector4d(0.1, 0.2, 0.3, 1));
  EXPECT_EQ(materials[1].baseColor, Eigen::Vector4d(1, 1, 1, 0.25));
  try {
    parseMtl("newmtl a\r\rKd 0.5 2 0.5\r", "m.mtl");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3) << e.what();
  }
}

}  // namespace
}  // namespace somicage
