#include "io/mesh_formats.h"

#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cctype>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <map>

#include "base/errors.h"
#include "base/file_util.h"
#include "io/gltf_writer.h"

namespace somicage {

namespace {

std::string extensionOf(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  if (!extension.empty()) extension.erase(0, 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// ---- Reading ----

MeshDocument readObj(const std::string& path, const ReadOptions&) { return parseObjDocument(readTextFile(path), path); }

// The transform of the first node (depth first) that shows mesh m, or nullptr when no node does.
bool findMeshTransform(const aiNode* node, const aiMatrix4x4& parent, unsigned m, aiMatrix4x4& out) {
  const aiMatrix4x4 global = parent * node->mTransformation;
  for (unsigned k = 0; k < node->mNumMeshes; ++k) {
    if (node->mMeshes[k] == m) {
      out = global;
      return true;
    }
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) {
    if (findMeshTransform(node->mChildren[c], global, m, out)) return true;
  }
  return false;
}

std::string shortest(double value) {
  char text[40];
  return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

// OBJ records for a document read from another format, so that one writer writes every document: a `v`
// (and `vt`, `vn` when the file had them) per vertex, then the faces with the same index for all three.
void addObjRecords(MeshDocument& document, bool hasUVs, bool hasNormals) {
  const int n = document.geometry.numVertices();
  for (int i = 0; i < n; ++i) document.records.push_back({ObjRecord::Kind::Position, i, ""});
  for (int i = 0; hasUVs && i < n; ++i) {
    document.records.push_back(
        {ObjRecord::Kind::Text, -1, "vt " + shortest(document.uvs(i, 0)) + " " + shortest(document.uvs(i, 1))});
  }
  for (int i = 0; hasNormals && i < n; ++i) document.records.push_back({ObjRecord::Kind::Normal, i, ""});
  for (const std::vector<int>& face : document.geometry.faces) {
    std::string line = "f";
    for (const int i : face) {
      const std::string index = std::to_string(i + 1);
      line += " " + index + (hasUVs || hasNormals ? "/" + (hasUVs ? index : "") : "") + (hasNormals ? "/" + index : "");
    }
    document.records.push_back({ObjRecord::Kind::Text, -1, line});
  }
  for (const std::vector<int>& polyline : document.geometry.lines) {
    std::string line = "l";
    for (const int i : polyline) line += " " + std::to_string(i + 1);
    document.records.push_back({ObjRecord::Kind::Text, -1, line});
  }
}

// A material as assimp gives it: glTF's base colour or the diffuse colour, the opacity, and the base-colour (or
// diffuse) texture, an image embedded in the file ("*0" or its name) as its bytes.
MeshMaterial materialOf(const aiScene& scene, const aiMaterial& source, const std::string& path) {
  MeshMaterial material;
  material.name = source.GetName().C_Str();
  aiColor4D colour;
  if (source.Get(AI_MATKEY_BASE_COLOR, colour) == AI_SUCCESS ||
      source.Get(AI_MATKEY_COLOR_DIFFUSE, colour) == AI_SUCCESS) {
    material.baseColor = Eigen::Vector4d(colour.r, colour.g, colour.b, colour.a);
  }
  float opacity = 1.0f;
  if (source.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && opacity < 1.0f) material.baseColor[3] = opacity;
  material.baseColor = material.baseColor.cwiseMax(0.0).cwiseMin(1.0);
  aiString texture;
  if (source.GetTexture(aiTextureType_BASE_COLOR, 0, &texture) != AI_SUCCESS &&
      source.GetTexture(aiTextureType_DIFFUSE, 0, &texture) != AI_SUCCESS) {
    return material;
  }
  if (const aiTexture* embedded = scene.GetEmbeddedTexture(texture.C_Str())) {
    if (embedded->mHeight == 0)  // compressed: the file's own PNG / JPEG bytes
      material.textureBytes.assign(reinterpret_cast<const char*>(embedded->pcData), embedded->mWidth);
    return material;
  }
  std::string name = texture.C_Str();
  std::replace(name.begin(), name.end(), '\\', '/');
  const std::filesystem::path file(name);
  material.texturePath = file.is_absolute() ? name : (std::filesystem::path(path).parent_path() / file).string();
  return material;
}

MeshDocument readWithAssimp(const std::string& path, const ReadOptions& options) {
  if (!std::filesystem::is_regular_file(path)) {
    throw InputError(path, -1, "cannot open the file", "check the path and the file name");
  }
  Assimp::Importer importer;
  // No post-processing that renumbers vertices (JoinIdenticalVertices, SortByPType, Triangulate). GlobalScale only
  // multiplies by the file's unit: FBX counts in centimetres times its UnitScaleFactor (Blender's default export is
  // 1 cm units under a 100x node scale), which assimp reports as its file scale; the step brings it to metres, as
  // glTF is by its specification (scale 1 there, and for the unitless formats).
  importer.SetPropertyFloat(AI_CONFIG_GLOBAL_SCALE_FACTOR_KEY, 1.0f);
  const aiScene* scene = importer.ReadFile(path, aiProcess_GlobalScale);
  if (!scene || !scene->mRootNode) {
    throw InputError(path, -1, std::string("cannot read the file: ") + importer.GetErrorString(),
                     "check that the file is a valid " + extensionOf(path) + " file (assimp reads it)");
  }
  MeshDocument document;
  document.sourcePath = path;
  std::vector<Eigen::RowVector3d> positions, normals;
  std::vector<Eigen::RowVector2d> uvs;
  bool allHaveUVs = scene->mNumMeshes > 0, allHaveNormals = scene->mNumMeshes > 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    allHaveUVs = allHaveUVs && mesh.HasTextureCoords(0);
    allHaveNormals = allHaveNormals && mesh.HasNormals();
  }
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    aiMatrix4x4 transform;
    findMeshTransform(scene->mRootNode, aiMatrix4x4(), m, transform);
    aiMatrix3x3 normalTransform(transform);
    normalTransform.Inverse().Transpose();
    const int offset = static_cast<int>(positions.size());
    std::string material;
    if (mesh.mMaterialIndex < scene->mNumMaterials) {
      const MeshMaterial found = materialOf(*scene, *scene->mMaterials[mesh.mMaterialIndex], path);
      material = found.name;
      const bool known = std::any_of(document.materials.begin(), document.materials.end(),
                                     [&](const MeshMaterial& m) { return m.name == found.name; });
      if (!known) document.materials.push_back(found);
    }
    for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
      const aiVector3D p = transform * mesh.mVertices[i];
      positions.emplace_back(p.x, p.y, p.z);
      if (allHaveUVs) uvs.emplace_back(mesh.mTextureCoords[0][i].x, mesh.mTextureCoords[0][i].y);
      if (allHaveNormals) {
        const aiVector3D n = (normalTransform * mesh.mNormals[i]).NormalizeSafe();
        normals.emplace_back(n.x, n.y, n.z);
      }
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      std::vector<int> indices(face.mIndices, face.mIndices + face.mNumIndices);
      for (int& i : indices) i += offset;
      if (indices.size() >= 3) {
        document.geometry.faces.push_back(indices);
        document.faceMaterial.push_back(material);
      } else if (indices.size() == 2) {
        document.geometry.lines.push_back(indices);
      }
    }
  }
  if (positions.empty()) {
    throw InputError(path, -1, "the file has no mesh vertices", "export the model with its mesh");
  }
  document.geometry.vertices.resize(static_cast<Eigen::Index>(positions.size()), 3);
  for (size_t i = 0; i < positions.size(); ++i)
    document.geometry.vertices.row(static_cast<Eigen::Index>(i)) = positions[i];
  if (options.weld) {
    document.geometry = weldVertices(document.geometry);
    allHaveUVs = allHaveNormals = false;  // per-corner attributes of welded vertices would have to be split
  }
  std::vector<std::vector<int>> noCornerData;
  for (const std::vector<int>& face : document.geometry.faces) noCornerData.emplace_back(face.size(), -1);
  document.faceUVs = allHaveUVs ? document.geometry.faces : noCornerData;
  document.faceNormals = allHaveNormals ? document.geometry.faces : noCornerData;
  if (allHaveUVs) {
    document.uvs.resize(static_cast<Eigen::Index>(uvs.size()), 2);
    for (size_t i = 0; i < uvs.size(); ++i) document.uvs.row(static_cast<Eigen::Index>(i)) = uvs[i];
  }
  if (allHaveNormals) {
    document.normalCount = static_cast<int>(normals.size());
    document.normals.resize(document.normalCount, 3);
    for (size_t i = 0; i < normals.size(); ++i) document.normals.row(static_cast<Eigen::Index>(i)) = normals[i];
  }
  addObjRecords(document, allHaveUVs, allHaveNormals);
  return document;
}

// ---- Writing ----

std::vector<std::string> writeObj(const std::string& path, const MeshDocument& document,
                                  const Eigen::MatrixXd& positions, const Eigen::MatrixXd& normals) {
  writeObjDocument(path, document, positions, normals);
  return {};
}

void appendBytes(std::string& out, const void* data, size_t size) { out.append(static_cast<const char*>(data), size); }

std::vector<std::string> writePly(const std::string& path, const MeshDocument& document,
                                  const Eigen::MatrixXd& positions, const Eigen::MatrixXd&) {
  const std::vector<std::vector<int>>& faces = document.geometry.faces;
  for (const std::vector<int>& face : faces) {
    if (face.size() > 255) {
      throw InputError(path, -1, "a face has " + std::to_string(face.size()) + " vertices",
                       "PLY face lists hold up to 255 vertices here: triangulate the mesh or write .obj");
    }
  }
  for (Eigen::Index i = 0; i < positions.rows(); ++i) {
    if (!positions.row(i).allFinite()) {
      throw InputError(path, -1, "vertex " + std::to_string(i) + " has a coordinate that is not finite",
                       "nothing was written");
    }
  }
  std::string out = "ply\nformat binary_little_endian 1.0\ncomment written by SomiCage\nelement vertex " +
                    std::to_string(positions.rows()) +
                    "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                    std::to_string(faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  for (Eigen::Index i = 0; i < positions.rows(); ++i) {
    for (Eigen::Index c = 0; c < 3; ++c) {
      const double x = c < positions.cols() ? positions(i, c) : 0.0;
      appendBytes(out, &x, sizeof x);  // the build machines are little-endian (x86-64, aarch64)
    }
  }
  for (const std::vector<int>& face : faces) {
    const unsigned char count = static_cast<unsigned char>(face.size());
    appendBytes(out, &count, 1);
    for (const int i : face) appendBytes(out, &i, sizeof i);
  }
  writeFileAtomic(path, out);
  std::vector<std::string> notes;
  if (document.uvs.rows() > 0 || document.normalCount > 0)
    notes.push_back("PLY is written with positions and faces only: UVs and normals were dropped (write .obj or .glb)");
  if (std::any_of(document.faceMaterial.begin(), document.faceMaterial.end(),
                  [](const std::string& m) { return !m.empty(); }))
    notes.push_back("PLY carries no materials or groups: they were dropped (write .obj to keep them)");
  if (!document.geometry.lines.empty()) notes.push_back("PLY is written without the `l` polylines");
  return notes;
}

std::vector<std::string> writeGlb(const std::string& path, const MeshDocument& document,
                                  const Eigen::MatrixXd& positions, const Eigen::MatrixXd&) {
  return writeGlbAnimation(path, document, {positions}, 24.0);
}

// One descriptor per format; a new format is a new row.
struct FormatDescriptor {
  const char* extension;
  MeshDocument (*read)(const std::string&, const ReadOptions&);
  // path, document, positions, normals (one per `vn`; empty: recomputed; only OBJ carries them)
  std::vector<std::string> (*write)(const std::string&, const MeshDocument&, const Eigen::MatrixXd&,
                                    const Eigen::MatrixXd&);
};

const std::vector<FormatDescriptor>& formats() {
  static const std::vector<FormatDescriptor> table = {
      {"obj", readObj, writeObj},       {"ply", readWithAssimp, writePly}, {"stl", readWithAssimp, nullptr},
      {"off", readWithAssimp, nullptr}, {"gltf", readWithAssimp, nullptr}, {"glb", readWithAssimp, writeGlb},
      {"fbx", readWithAssimp, nullptr},
  };
  return table;
}

std::string extensionList(bool writable) {
  std::string list;
  for (const FormatDescriptor& format : formats()) {
    if (writable && !format.write) continue;
    list += (list.empty() ? "." : ", .") + std::string(format.extension);
  }
  return list;
}

const FormatDescriptor* findFormat(const std::string& path) {
  const std::string extension = extensionOf(path);
  for (const FormatDescriptor& format : formats()) {
    if (extension == format.extension) return &format;
  }
  return nullptr;
}

}  // namespace

std::string readableExtensions() { return extensionList(false); }
std::string writableExtensions() { return extensionList(true); }

MeshDocument loadMeshDocument(const std::string& path, const ReadOptions& options) {
  std::error_code error;  // a folder has no format: say what it is (every command names it so)
  if (std::filesystem::is_directory(path, error))
    throw InputError(path, -1, "is a folder, not a file",
                     "give the path of a mesh file (" + readableExtensions() + ")");
  const FormatDescriptor* format = findFormat(path);
  if (!format) {
    const std::string extension = extensionOf(path);
    throw InputError(
        path, -1,
        extension.empty() ? "has no extension to tell its mesh format" : "unknown mesh format '." + extension + "'",
        "give a file ending in one of " + readableExtensions());
  }
  return format->read(path, options);
}

PolygonMesh loadAnyMesh(const std::string& path, const ReadOptions& options) {
  return loadMeshDocument(path, options).geometry;
}

Cage loadCage(const std::string& path, const ReadOptions& options) {
  return cageFromMesh(loadAnyMesh(path, options), path);
}

Eigen::MatrixXd loadPosedVertices(const std::string& path, const Cage& restCage, const ReadOptions& options) {
  return posedVerticesFromMesh(loadAnyMesh(path, options), restCage, path);
}

bool weldApplies(const std::string& path) {
  const FormatDescriptor* format = findFormat(path);
  return format && format->read == readWithAssimp;
}

std::vector<std::string> writeMeshDocument(const std::string& path, const MeshDocument& document,
                                           const Eigen::MatrixXd& positions, const Eigen::MatrixXd& normals) {
  const FormatDescriptor* format = findFormat(path);
  if (!format || !format->write) {
    throw InputError(path, -1, "cannot write meshes as '." + extensionOf(path) + "'",
                     "give an output file ending in one of " + writableExtensions());
  }
  return format->write(path, document, positions, normals);
}

PolygonMesh weldVertices(const PolygonMesh& mesh) {
  std::map<std::array<double, 3>, int> seen;
  std::vector<int> newIndex(static_cast<size_t>(mesh.numVertices()));
  std::vector<Eigen::Index> kept;
  for (int i = 0; i < mesh.numVertices(); ++i) {
    const std::array<double, 3> key{mesh.vertices(i, 0), mesh.vertices(i, 1), mesh.vertices(i, 2)};
    const auto [at, inserted] = seen.emplace(key, static_cast<int>(kept.size()));
    if (inserted) kept.push_back(i);
    newIndex[static_cast<size_t>(i)] = at->second;
  }
  PolygonMesh welded = mesh;
  welded.vertices.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (size_t k = 0; k < kept.size(); ++k)
    welded.vertices.row(static_cast<Eigen::Index>(k)) = mesh.vertices.row(kept[k]);
  for (auto* lists : {&welded.faces, &welded.lines}) {
    for (std::vector<int>& list : *lists) {
      for (int& i : list) i = newIndex[static_cast<size_t>(i)];
    }
  }
  return welded;
}

}  // namespace somicage
