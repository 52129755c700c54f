#include "gltf_writer.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>
#include <utility>

#include "errors.h"
#include "file_util.h"

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

  int add(const void* data, size_t bytes, int componentType, int type, size_t count, int target,
          std::vector<double> min = {}, std::vector<double> max = {}) {
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
    tinygltf::Accessor accessor;
    accessor.bufferView = static_cast<int>(model_.bufferViews.size()) - 1;
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

}  // namespace

std::vector<std::string> writeGlbAnimation(const std::string& path, const MeshDocument& document,
                                           const std::vector<Eigen::MatrixXd>& frames, double fps) {
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
    targetNames.emplace_back("frame_" + std::to_string(k));
  }

  tinygltf::Mesh mesh;
  mesh.name = document.sourcePath.empty() ? "mesh" : std::filesystem::path(document.sourcePath).stem().string();
  for (size_t m = 0; m < layout.materials.size(); ++m) {
    tinygltf::Material material;
    material.name = layout.materials[m].empty() ? "default" : layout.materials[m];
    material.doubleSided = true;
    model.materials.push_back(material);
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
  std::vector<std::string> notes;
  if (!document.geometry.lines.empty()) notes.push_back("GLB is written without the `l` polylines (write .obj)");
  if (document.uvs.rows() > 0 && layout.uv.empty())
    notes.push_back("GLB is written without UVs: some faces have none (write .obj to keep them)");
  return notes;
}

}  // namespace somicage
