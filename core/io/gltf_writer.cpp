#include "io/gltf_writer.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>
#include <utility>

#include "base/errors.h"
#include "base/file_util.h"
#include "io/mesh_material.h"

namespace somicage {

namespace {

// The glTF vertices: which mesh vertex and which `vt` each is, and the triangles of each material over them.
struct GltfLayout {
  std::vector<int> meshVertex;
  std::vector<int> uv;  // empty when the mesh has no UVs
  std::vector<std::string> materials;
  std::vector<std::vector<uint32_t>> triangles;  // per material
};

GltfLayout layoutOf(const MeshDocument& document) {
  const std::vector<std::vector<int>>& faces = document.geometry.faces;
  bool withUVs = document.uvs.rows() > 0 && !faces.empty();
  for (const std::vector<int>& corners : document.faceUVs) {
    withUVs = withUVs && std::none_of(corners.begin(), corners.end(), [](int t) { return t < 0; });
  }
  GltfLayout layout;
  std::map<std::pair<int, int>, uint32_t> glVertex;
  if (!withUVs) {
    for (int i = 0; i < document.geometry.numVertices(); ++i) layout.meshVertex.push_back(i);
  }
  for (size_t f = 0; f < faces.size(); ++f) {
    const std::string material = f < document.faceMaterial.size() ? document.faceMaterial[f] : std::string();
    auto at = std::find(layout.materials.begin(), layout.materials.end(), material);
    if (at == layout.materials.end()) {
      layout.materials.push_back(material);
      layout.triangles.emplace_back();
      at = layout.materials.end() - 1;
    }
    std::vector<uint32_t>& triangles = layout.triangles[static_cast<size_t>(at - layout.materials.begin())];
    const Eigen::MatrixXi cut = triangulatePolygons(document.geometry.vertices, {faces[f]});
    for (Eigen::Index t = 0; t < cut.rows(); ++t) {
      for (int c = 0; c < 3; ++c) {
        const int vertex = cut(t, c);
        if (!withUVs) {
          triangles.push_back(static_cast<uint32_t>(vertex));
          continue;
        }
        const size_t corner =
            static_cast<size_t>(std::find(faces[f].begin(), faces[f].end(), vertex) - faces[f].begin());
        const std::pair<int, int> key{vertex, document.faceUVs[f][corner]};
        const auto [it, inserted] = glVertex.emplace(key, static_cast<uint32_t>(layout.meshVertex.size()));
        if (inserted) {
          layout.meshVertex.push_back(key.first);
          layout.uv.push_back(key.second);
        }
        triangles.push_back(it->second);
      }
    }
  }
  return layout;
}

// Appends data to the single buffer (4-byte aligned) and returns the accessor that reads it.
class BufferBuilder {
 public:
  explicit BufferBuilder(tinygltf::Model& model) : model_(model) { model_.buffers.emplace_back(); }

  // A buffer view of the bytes (images are read through one; attributes through an accessor on it).
  int addView(const void* data, size_t bytes, int target) {
    std::vector<unsigned char>& buffer = model_.buffers[0].data;
    while (buffer.size() % 4 != 0) buffer.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = bytes;
    view.target = target;
    buffer.insert(buffer.end(), static_cast<const unsigned char*>(data),
                  static_cast<const unsigned char*>(data) + bytes);
    model_.bufferViews.push_back(view);
    return static_cast<int>(model_.bufferViews.size()) - 1;
  }

  int add(const void* data, size_t bytes, int componentType, int type, size_t count, int target,
          std::vector<double> min = {}, std::vector<double> max = {}) {
    tinygltf::Accessor accessor;
    accessor.bufferView = addView(data, bytes, target);
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = count;
    accessor.minValues = std::move(min);
    accessor.maxValues = std::move(max);
    model_.accessors.push_back(accessor);
    return static_cast<int>(model_.accessors.size()) - 1;
  }

  // #n by 3 floats with their bounds (glTF requires them for POSITION and morph targets).
  int addVec3(const std::vector<float>& xyz) {
    std::vector<double> lo(3, 0.0), hi(3, 0.0);
    for (size_t i = 0; i < xyz.size(); ++i) {
      const size_t c = i % 3;
      lo[c] = i < 3 ? xyz[i] : std::min<double>(lo[c], xyz[i]);
      hi[c] = i < 3 ? xyz[i] : std::max<double>(hi[c], xyz[i]);
    }
    return add(xyz.data(), xyz.size() * sizeof(float), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
               xyz.size() / 3, TINYGLTF_TARGET_ARRAY_BUFFER, lo, hi);
  }

 private:
  tinygltf::Model& model_;
};

std::vector<float> positionsOf(const GltfLayout& layout, const Eigen::MatrixXd& positions,
                               const Eigen::MatrixXd* subtract) {
  std::vector<float> xyz;
  xyz.reserve(layout.meshVertex.size() * 3);
  for (const int i : layout.meshVertex) {
    for (Eigen::Index c = 0; c < 3; ++c) {
      const double base = subtract && c < subtract->cols() ? (*subtract)(i, c) : 0.0;
      xyz.push_back(static_cast<float>((c < positions.cols() ? positions(i, c) : 0.0) - base));
    }
  }
  return xyz;
}

const MeshMaterial& materialNamed(const DocumentMaterials& materials, const std::string& name) {
  for (const MeshMaterial& material : materials.materials) {
    if (material.name == name) return material;
  }
  static const MeshMaterial kWhite;
  return kWhite;  // documentMaterials lists every face's material: only a mesh without faces gets here
}

// The images of the materials' textures, each file (or embedded image) stored once in the buffer. A texture that
// cannot be carried is named in the notes and left out; its material keeps its colour.
class TextureBuilder {
 public:
  TextureBuilder(tinygltf::Model& model, BufferBuilder& buffer, bool haveUVs, std::vector<std::string>& notes)
      : model_(model), buffer_(buffer), haveUVs_(haveUVs), notes_(notes) {}

  // The glTF texture of a material, or -1 when it has none or it cannot be written.
  int textureOf(const MeshMaterial& material) {
    if (material.texturePath.empty() && material.textureBytes.empty()) return -1;
    const std::string key = material.textureBytes.empty() ? material.texturePath : "embedded:" + material.name;
    const auto known = textures_.find(key);
    if (known != textures_.end()) return known->second;
    const int texture = addTexture(material);
    textures_[key] = texture;
    return texture;
  }

 private:
  int addTexture(const MeshMaterial& material) {
    const std::string what =
        material.textureBytes.empty() ? "the texture " + material.texturePath : "the embedded texture";
    const std::string of = " of material '" + material.name + "'";
    if (!haveUVs_) {
      notes_.push_back(what + of + " is not written: the mesh has no UVs on every face");
      return -1;
    }
    std::string bytes = material.textureBytes;
    if (bytes.empty()) {
      std::error_code error;
      if (!std::filesystem::is_regular_file(material.texturePath, error)) {
        notes_.push_back(what + of + " was not found: the material is written without it (put the file there)");
        return -1;
      }
      bytes = readTextFile(material.texturePath);
    }
    const std::string mime = imageMimeType(bytes);
    if (mime.empty()) {
      notes_.push_back(what + of + " is neither PNG nor JPEG (the formats glTF carries): written without it");
      return -1;
    }
    tinygltf::Image image;
    image.name =
        material.textureBytes.empty() ? std::filesystem::path(material.texturePath).stem().string() : material.name;
    image.mimeType = mime;
    image.bufferView = buffer_.addView(bytes.data(), bytes.size(), 0);
    model_.images.push_back(image);
    if (model_.samplers.empty()) {
      tinygltf::Sampler sampler;  // repeat, as OBJ viewers tile UVs outside [0, 1]
      sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
      sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
      model_.samplers.push_back(sampler);
    }
    tinygltf::Texture texture;
    texture.source = static_cast<int>(model_.images.size()) - 1;
    texture.sampler = 0;
    model_.textures.push_back(texture);
    return static_cast<int>(model_.textures.size()) - 1;
  }

  tinygltf::Model& model_;
  BufferBuilder& buffer_;
  bool haveUVs_;
  std::vector<std::string>& notes_;
  std::map<std::string, int> textures_;
};

// A diffuse OBJ-style material as glTF PBR: the colour (and opacity) as the base colour, not metallic, fully rough.
tinygltf::Material gltfMaterial(const MeshMaterial& source, TextureBuilder& textures) {
  tinygltf::Material material;
  material.name = source.name.empty() ? "default" : source.name;
  material.doubleSided = true;
  tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
  pbr.baseColorFactor = {source.baseColor[0], source.baseColor[1], source.baseColor[2], source.baseColor[3]};
  pbr.metallicFactor = 0.0;
  pbr.roughnessFactor = 1.0;
  pbr.baseColorTexture.index = textures.textureOf(source);
  if (source.baseColor[3] < 1.0) material.alphaMode = "BLEND";
  return material;
}

}  // namespace

std::vector<std::string> writeGlbAnimation(const std::string& path, const MeshDocument& document,
                                           const std::vector<Eigen::MatrixXd>& frames, double fps, int firstFrame) {
  SOMICAGE_ASSERT(!frames.empty() && fps > 0, "writeGlbAnimation takes at least one frame and a positive fps");
  for (size_t k = 0; k < frames.size(); ++k) {
    if (frames[k].rows() != document.geometry.numVertices() || !frames[k].allFinite()) {
      throw InputError(path, -1, "frame " + std::to_string(k) + " does not have one finite position per vertex",
                       "nothing was written");
    }
  }
  if (document.geometry.faces.empty()) {
    throw InputError(path, -1, "the mesh has no faces: glTF carries triangle meshes here",
                     "write a point set or polylines as .obj");
  }
  const GltfLayout layout = layoutOf(document);
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "SomiCage";
  BufferBuilder buffer(model);

  const int position = buffer.addVec3(positionsOf(layout, frames[0], nullptr));
  int texcoord = -1;
  if (!layout.uv.empty()) {
    std::vector<float> uv;
    for (const int t : layout.uv) {
      uv.push_back(static_cast<float>(document.uvs(t, 0)));
      uv.push_back(static_cast<float>(1.0 - document.uvs(t, 1)));
    }
    texcoord = buffer.add(uv.data(), uv.size() * sizeof(float), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2,
                          layout.uv.size(), TINYGLTF_TARGET_ARRAY_BUFFER);
  }
  std::vector<int> targets;
  tinygltf::Value::Array targetNames;
  for (size_t k = 1; k < frames.size(); ++k) {
    targets.push_back(buffer.addVec3(positionsOf(layout, frames[k], &frames[0])));
    targetNames.emplace_back("frame_" + std::to_string(firstFrame + static_cast<int>(k)));
  }

  std::vector<std::string> notes;
  const DocumentMaterials materials = documentMaterials(document);
  notes.insert(notes.end(), materials.notes.begin(), materials.notes.end());
  TextureBuilder textures(model, buffer, texcoord >= 0, notes);
  tinygltf::Mesh mesh;
  mesh.name = document.sourcePath.empty() ? "mesh" : std::filesystem::path(document.sourcePath).stem().string();
  for (size_t m = 0; m < layout.materials.size(); ++m) {
    model.materials.push_back(gltfMaterial(materialNamed(materials, layout.materials[m]), textures));
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.material = static_cast<int>(m);
    primitive.attributes["POSITION"] = position;
    if (texcoord >= 0) primitive.attributes["TEXCOORD_0"] = texcoord;
    const std::vector<uint32_t>& triangles = layout.triangles[m];
    primitive.indices =
        buffer.add(triangles.data(), triangles.size() * sizeof(uint32_t), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                   TINYGLTF_TYPE_SCALAR, triangles.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    for (const int target : targets) primitive.targets.push_back({{"POSITION", target}});
    mesh.primitives.push_back(primitive);
  }
  if (!targets.empty()) {
    mesh.weights.assign(targets.size(), 0.0);
    tinygltf::Value::Object extras;
    extras["targetNames"] = tinygltf::Value(targetNames);
    mesh.extras = tinygltf::Value(extras);
  }
  model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  node.name = mesh.name;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  if (!targets.empty()) {
    std::vector<float> times, weights;
    for (size_t k = 0; k < frames.size(); ++k) {
      times.push_back(static_cast<float>(static_cast<double>(k) / fps));
      for (size_t t = 0; t < targets.size(); ++t) weights.push_back(t + 1 == k ? 1.0f : 0.0f);
    }
    tinygltf::AnimationSampler sampler;
    sampler.input = buffer.add(times.data(), times.size() * sizeof(float), TINYGLTF_COMPONENT_TYPE_FLOAT,
                               TINYGLTF_TYPE_SCALAR, times.size(), 0, {times.front()}, {times.back()});
    sampler.output = buffer.add(weights.data(), weights.size() * sizeof(float), TINYGLTF_COMPONENT_TYPE_FLOAT,
                                TINYGLTF_TYPE_SCALAR, weights.size(), 0);
    sampler.interpolation = "LINEAR";
    tinygltf::AnimationChannel channel;
    channel.sampler = 0;
    channel.target_node = 0;
    channel.target_path = "weights";
    tinygltf::Animation animation;
    animation.name = "SomiCage";
    animation.samplers.push_back(sampler);
    animation.channels.push_back(channel);
    model.animations.push_back(animation);
  }
  model.buffers[0].data.resize((model.buffers[0].data.size() + 3) / 4 * 4, 0);

  std::ostringstream bytes;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, bytes, false, true)) {
    throw InputError(path, -1, "tinygltf could not encode the scene", "nothing was written; please report this");
  }
  writeFileAtomic(path, bytes.str());
  if (!document.geometry.lines.empty()) notes.push_back("GLB is written without the `l` polylines (write .obj)");
  if (document.uvs.rows() > 0 && layout.uv.empty())
    notes.push_back("GLB is written without UVs: some faces have none (write .obj to keep them)");
  return notes;
}

}  // namespace somicage
