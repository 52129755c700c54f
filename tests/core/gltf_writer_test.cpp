// GLB materials: a textured OBJ with a .mtl and a PNG made here is written as GLB and parsed back with tinygltf's
// reader (not the writer's code): each material's colour and opacity, the texture's bytes (identical to the PNG
// file) and decoded pixels, every corner's UV against the OBJ's `vt` (v flipped), and which material each face's
// triangles belong to, in face order. A missing texture is named and left out; a GLB read back through assimp keeps
// its materials and embedded image when it is written again.
#include "io/gltf_writer.h"

#include <gtest/gtest.h>
#include <stb_image_write.h>
#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "base/errors.h"
#include "base/file_util.h"
#include "io/mesh_formats.h"
#include "scratch_folder.h"

namespace somicage {
namespace {

namespace fs = std::filesystem;

using test::ScratchFolder;

void write(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// A 2 by 2 RGBA PNG: red, green / blue, white.
const unsigned char kPixels[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};

// Three triangles over four vertices with their own UVs: faces 1 and 3 use the textured `skin`, face 2 `glass`.
const char* const kObj =
    "mtllib tri.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0.5\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.25 0.75\n"
    "usemtl skin\nf 1/1 2/2 3/3\n"
    "usemtl glass\nf 1/5 3/3 4/4\n"
    "usemtl skin\nf 2/2 4/4 3/3\n";

struct Parsed {
  tinygltf::Model model;
  std::string warnings;
};

Parsed parseGlb(const fs::path& path) {
  Parsed parsed;
  std::string error;
  tinygltf::TinyGLTF reader;
  EXPECT_TRUE(reader.LoadBinaryFromFile(&parsed.model, &error, &parsed.warnings, path.string())) << error;
  return parsed;
}

template <typename T>
std::vector<T> accessorValues(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& accessor = model.accessors.at(static_cast<size_t>(index));
  const tinygltf::BufferView& view = model.bufferViews.at(static_cast<size_t>(accessor.bufferView));
  const size_t width = accessor.type == TINYGLTF_TYPE_VEC2 ? 2 : accessor.type == TINYGLTF_TYPE_VEC3 ? 3 : 1;
  std::vector<T> values(accessor.count * width);
  std::memcpy(values.data(), model.buffers[0].data.data() + view.byteOffset + accessor.byteOffset,
              values.size() * sizeof(T));
  return values;
}

class GlbMaterials : public ::testing::Test {
 protected:
  void SetUp() override {
    fs::create_directories(folder / "maps");
    ASSERT_NE(stbi_write_png((folder / "maps/skin.png").c_str(), 2, 2, 4, kPixels, 8), 0);
    write(folder / "tri.obj", kObj);
  }

  // Writes the OBJ as GLB with the given .mtl and parses it back.
  Parsed writeAndParse(const std::string& mtl, std::vector<std::string>* notes = nullptr) {
    write(folder / "tri.mtl", mtl);
    const MeshDocument document = loadMeshDocument(folder / "tri.obj");
    const std::vector<std::string> written =
        writeMeshDocument(folder / "out.glb", document, document.geometry.vertices);
    if (notes) *notes = written;
    return parseGlb(folder / "out.glb");
  }

  ScratchFolder folder;
};

const char* const kMtl =
    "# two materials\n"
    "newmtl skin\nKd 0.9 0.8 0.7\nmap_Kd -s 1 1 1 maps/skin.png\n"
    "newmtl glass\nKd 0.2 0.4 0.6\nTr 0.75\n";

TEST_F(GlbMaterials, ColoursOpacityAndTheEmbeddedTextureReadBack) {
  std::vector<std::string> notes;
  const Parsed parsed = writeAndParse(kMtl, &notes);
  EXPECT_TRUE(notes.empty()) << notes.front();
  const tinygltf::Model& model = parsed.model;
  ASSERT_EQ(model.materials.size(), 2u);
  const tinygltf::Material& skin = model.materials[0];
  const tinygltf::Material& glass = model.materials[1];
  EXPECT_EQ(skin.name, "skin") << "materials in order of first use";
  EXPECT_EQ(glass.name, "glass");
  const std::vector<double> skinColour{0.9, 0.8, 0.7, 1.0}, glassColour{0.2, 0.4, 0.6, 0.25};
  for (size_t c = 0; c < 4; ++c) {
    EXPECT_NEAR(skin.pbrMetallicRoughness.baseColorFactor[c], skinColour[c], 1e-12);
    EXPECT_NEAR(glass.pbrMetallicRoughness.baseColorFactor[c], glassColour[c], 1e-12) << "opacity = 1 - Tr";
  }
  EXPECT_EQ(glass.alphaMode, "BLEND");
  EXPECT_EQ(skin.alphaMode, "OPAQUE");
  EXPECT_EQ(skin.pbrMetallicRoughness.metallicFactor, 0.0) << "OBJ diffuse materials are not metals";
  EXPECT_EQ(glass.pbrMetallicRoughness.baseColorTexture.index, -1);

  const int texture = skin.pbrMetallicRoughness.baseColorTexture.index;
  ASSERT_GE(texture, 0);
  EXPECT_EQ(skin.pbrMetallicRoughness.baseColorTexture.texCoord, 0);
  const tinygltf::Image& image = model.images.at(static_cast<size_t>(model.textures.at(texture).source));
  EXPECT_EQ(image.mimeType, "image/png");
  ASSERT_GE(image.bufferView, 0) << "embedded in the GLB's buffer, not a file next to it";
  const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(image.bufferView)];
  const std::string embedded(reinterpret_cast<const char*>(model.buffers[0].data.data()) + view.byteOffset,
                             view.byteLength);
  EXPECT_EQ(embedded, readTextFile(folder / "maps/skin.png")) << "the PNG's bytes, unchanged";
  ASSERT_EQ(image.width, 2);
  ASSERT_EQ(image.height, 2);
  ASSERT_EQ(image.image.size(), 16u);
  EXPECT_EQ(std::memcmp(image.image.data(), kPixels, 16), 0) << "tinygltf decodes the pixels written";
}

TEST_F(GlbMaterials, EveryCornerKeepsItsUvAndEveryFaceItsMaterialInFaceOrder) {
  const Parsed parsed = writeAndParse(kMtl);
  const MeshDocument obj = loadMeshDocument(folder / "tri.obj");
  const tinygltf::Mesh& mesh = parsed.model.meshes.at(0);
  ASSERT_EQ(mesh.primitives.size(), 2u);
  // The OBJ's faces per material, in face order: skin = faces 0 and 2, glass = face 1.
  const std::vector<std::vector<size_t>> facesOf{{0, 2}, {1}};
  for (size_t m = 0; m < 2; ++m) {
    SCOPED_TRACE("primitive " + std::to_string(m));
    const tinygltf::Primitive& primitive = mesh.primitives[m];
    EXPECT_EQ(primitive.material, static_cast<int>(m));
    const std::vector<float> xyz = accessorValues<float>(parsed.model, primitive.attributes.at("POSITION"));
    const std::vector<float> uv = accessorValues<float>(parsed.model, primitive.attributes.at("TEXCOORD_0"));
    const std::vector<uint32_t> indices = accessorValues<uint32_t>(parsed.model, primitive.indices);
    ASSERT_EQ(indices.size(), 3 * facesOf[m].size());
    for (size_t t = 0; t < facesOf[m].size(); ++t) {
      const size_t f = facesOf[m][t];
      for (size_t c = 0; c < 3; ++c) {
        const uint32_t g = indices[3 * t + c];
        // The triangle's corners are the face's corners (triangles keep the face's order and winding).
        const int vertex = obj.geometry.faces[f][c];
        for (int a = 0; a < 3; ++a) EXPECT_EQ(xyz[3 * g + a], obj.geometry.vertices(vertex, a)) << "face " << f;
        const int vt = obj.faceUVs[f][c];
        EXPECT_EQ(uv[2 * g], obj.uvs(vt, 0)) << "face " << f << " corner " << c;
        EXPECT_EQ(uv[2 * g + 1], 1.0 - obj.uvs(vt, 1)) << "glTF's v runs down";
      }
    }
  }
}

TEST_F(GlbMaterials, AMissingTextureIsNamedAndLeftOut) {
  std::vector<std::string> notes;
  const Parsed parsed = writeAndParse("newmtl skin\nKd 0.5 0.5 0.5\nmap_Kd gone.png\nnewmtl glass\n", &notes);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find(folder / "gone.png"), std::string::npos) << notes[0];
  EXPECT_NE(notes[0].find("not found"), std::string::npos) << notes[0];
  EXPECT_NE(notes[0].find("'skin'"), std::string::npos) << notes[0];
  ASSERT_EQ(parsed.model.materials.size(), 2u);
  EXPECT_EQ(parsed.model.materials[0].pbrMetallicRoughness.baseColorTexture.index, -1);
  EXPECT_NEAR(parsed.model.materials[0].pbrMetallicRoughness.baseColorFactor[0], 0.5, 1e-12) << "colour kept";
  EXPECT_TRUE(parsed.model.images.empty());
}

TEST_F(GlbMaterials, AMissingLibraryOrMaterialIsNamedAndWrittenWhite) {
  write(folder / "tri.mtl", "newmtl skin\nKd 0.5 0.5 0.5\n");
  fs::remove(folder / "tri.mtl");
  const MeshDocument document = loadMeshDocument(folder / "tri.obj");
  std::vector<std::string> notes = writeMeshDocument(folder / "out.glb", document, document.geometry.vertices);
  ASSERT_EQ(notes.size(), 3u) << "the library, then each undefined material";
  EXPECT_NE(notes[0].find("tri.mtl was not found"), std::string::npos) << notes[0];
  EXPECT_NE(notes[1].find("'skin'"), std::string::npos) << notes[1];
  EXPECT_NE(notes[2].find("'glass'"), std::string::npos) << notes[2];
  const Parsed parsed = parseGlb(folder / "out.glb");
  EXPECT_EQ(parsed.model.materials.at(1).pbrMetallicRoughness.baseColorFactor, (std::vector<double>{1, 1, 1, 1}));
}

TEST_F(GlbMaterials, ABadLibraryNamesItsFileAndLine) {
  write(folder / "tri.mtl", "newmtl skin\nKd 0.5 x 0.5\n");
  const MeshDocument document = loadMeshDocument(folder / "tri.obj");
  try {
    writeMeshDocument(folder / "out.glb", document, document.geometry.vertices);
    FAIL() << "a colour that is not a number must be refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), folder / "tri.mtl");
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(e.problem().find("'x'"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(folder / "out.glb")) << "nothing written";
}

TEST_F(GlbMaterials, AGlbReadThroughAssimpKeepsItsMaterialsAndImage) {
  writeAndParse(kMtl);
  const MeshDocument document = loadMeshDocument(folder / "out.glb");
  ASSERT_EQ(document.materials.size(), 2u);
  const std::vector<std::string> notes = writeMeshDocument(folder / "again.glb", document, document.geometry.vertices);
  EXPECT_TRUE(notes.empty()) << notes.front();
  const Parsed again = parseGlb(folder / "again.glb");
  ASSERT_EQ(again.model.materials.size(), 2u);
  EXPECT_EQ(again.model.materials[0].name, "skin");
  for (size_t c = 0; c < 4; ++c) {
    EXPECT_NEAR(again.model.materials[1].pbrMetallicRoughness.baseColorFactor[c],
                (std::vector<double>{0.2, 0.4, 0.6, 0.25}[c]), 1e-6)
        << "float precision through assimp";
  }
  ASSERT_EQ(again.model.images.size(), 1u);
  EXPECT_EQ(std::memcmp(again.model.images[0].image.data(), kPixels, 16), 0);
}

}  // namespace
}  // namespace somicage
