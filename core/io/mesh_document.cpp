#include "io/mesh_document.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <string_view>

#include "base/errors.h"
#include "base/file_util.h"

namespace somicage {

namespace {

namespace fs = std::filesystem;

// Index part k (1 = texture, 2 = normal) of a face corner `v/t/n` as a 0-based index, -1 when absent.
int cornerIndex(std::string_view corner, int part, int count, const std::string& source, long line) {
  for (int k = 0; k < part; ++k) {
    const size_t slash = corner.find('/');
    if (slash == std::string_view::npos) return -1;
    corner.remove_prefix(slash + 1);
  }
  corner = corner.substr(0, corner.find('/'));
  if (corner.empty()) return -1;
  long long index = 0;
  const auto result = std::from_chars(corner.data(), corner.data() + corner.size(), index);
  const long long resolved = index > 0 ? index - 1 : count + index;
  if (result.ec != std::errc() || result.ptr != corner.data() + corner.size() || index == 0 || resolved < 0 ||
      resolved >= count) {
    throw InputError(source, line,
                     std::string(part == 1 ? "texture" : "normal") + " index '" + std::string(corner) +
                         "' does not name one of the " + std::to_string(count) + (part == 1 ? " `vt`" : " `vn`") +
                         " records before it",
                     "OBJ indices start at 1 and may only refer to records earlier in the file");
  }
  return static_cast<int>(resolved);
}

// The numbers of a `vn` or `vt` record, read as a `v` record's (parseObjNumber).
Eigen::RowVector3d numbersOf(const std::vector<std::string_view>& tokens, size_t count, const std::string& source,
                             long line) {
  Eigen::RowVector3d value = Eigen::RowVector3d::Zero();
  for (size_t k = 1; k <= count && k < tokens.size(); ++k) {
    if (parseObjNumber(tokens[k], value[k - 1]) != ObjNumberStatus::Ok) {
      throw InputError(
          source, line,
          "`" + std::string(tokens[0]) + "` value '" + std::string(tokens[k]) + "' is not a finite decimal number",
          "write `vt u v` and `vn x y z` with decimal numbers");
    }
  }
  return value;
}

void appendNumber(std::string& out, double value) {
  char text[40];
  const auto result = std::to_chars(text, text + sizeof text, value, std::chars_format::general, 17);
  out.append(text, result.ptr);
}

std::string folderOf(const std::string& path) {
  const fs::path folder = fs::path(path).parent_path();
  return folder.empty() ? "." : folder.string();
}

// An `mtllib` line for an output in another folder: each library that exists next to the source is named by its
// path relative to the output's folder (absolute when there is none).
std::string relocatedMaterialLibraries(std::string_view line, const std::string& source, const std::string& out) {
  std::error_code error;
  const fs::path sourceFolder = fs::weakly_canonical(folderOf(source), error);
  const fs::path outFolder = fs::weakly_canonical(folderOf(out), error);
  if (error || sourceFolder == outFolder) return std::string(line);
  std::string rewritten = "mtllib";
  const std::vector<std::string_view> tokens = splitTokens(line);
  for (size_t k = 1; k < tokens.size(); ++k) {
    const fs::path name{std::string(tokens[k])};
    fs::path target = name;
    if (name.is_relative() && fs::exists(sourceFolder / name, error)) {
      target = fs::relative(sourceFolder / name, outFolder, error);
      if (error || target.empty()) target = sourceFolder / name;
    }
    rewritten += ' ' + target.generic_string();
  }
  return rewritten;
}

}  // namespace

MeshDocument parseObjDocument(const std::string& text, const std::string& source) {
  MeshDocument document;
  document.sourcePath = source;
  std::vector<Eigen::RowVector3d> normals, uvs;
  std::string material;
  int vertexCount = 0;
  std::vector<std::string_view> tokens;  // the current line's, reused
  // The records, in parseObj's one pass (it reads the positions, faces and lines itself).
  document.geometry = parseObj(
      text, source, [&](long lineNumber, std::string_view rawLine, std::string_view line, std::string_view keyword) {
        ObjRecord record;
        if (keyword == "v") {  // the position is the geometry's; the record keeps what follows it
          splitTokens(line, tokens);
          record.kind = ObjRecord::Kind::Position;
          record.index = vertexCount++;
          for (size_t k = 4; k < tokens.size(); ++k) record.text += ' ' + std::string(tokens[k]);
        } else {
          record.text = std::string(rawLine);
        }
        if (keyword == "vn") {
          record.kind = ObjRecord::Kind::Normal;
          record.index = static_cast<int>(normals.size());
          normals.push_back(numbersOf(splitTokens(line), 3, source, lineNumber));
        } else if (keyword == "vt") {
          uvs.push_back(numbersOf(splitTokens(line), 2, source, lineNumber));
        } else if (keyword == "usemtl") {
          splitTokens(line, tokens);
          material = tokens.size() > 1 ? std::string(tokens[1]) : std::string();
        } else if (keyword == "f") {
          std::vector<int> faceNormals, faceUVs;
          splitTokens(line, tokens);
          faceNormals.reserve(tokens.size());
          faceUVs.reserve(tokens.size());
          for (size_t k = 1; k < tokens.size(); ++k) {
            faceUVs.push_back(cornerIndex(tokens[k], 1, static_cast<int>(uvs.size()), source, lineNumber));
            faceNormals.push_back(cornerIndex(tokens[k], 2, static_cast<int>(normals.size()), source, lineNumber));
          }
          document.faceNormals.push_back(std::move(faceNormals));
          document.faceUVs.push_back(std::move(faceUVs));
          document.faceMaterial.push_back(material);
        }
        document.records.push_back(std::move(record));
      });
  document.normalCount = static_cast<int>(normals.size());
  document.normals.resize(document.normalCount, 3);
  for (int n = 0; n < document.normalCount; ++n) document.normals.row(n) = normals[static_cast<size_t>(n)];
  document.uvs.resize(static_cast<Eigen::Index>(uvs.size()), 2);
  for (size_t t = 0; t < uvs.size(); ++t) document.uvs.row(static_cast<Eigen::Index>(t)) = uvs[t].head<2>();
  return document;
}

Eigen::MatrixXd recomputeNormals(const MeshDocument& document, const Eigen::MatrixXd& positions) {
  Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(document.normalCount, 3);
  const auto point = [&](int i) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    p.head(std::min<Eigen::Index>(positions.cols(), 3)) =
        positions.row(i).head(std::min<Eigen::Index>(positions.cols(), 3)).transpose();
    return p;
  };
  const std::vector<std::vector<int>>& faces = document.geometry.faces;
  for (size_t f = 0; f < faces.size(); ++f) {
    const std::vector<int>& face = faces[f];
    const size_t n = face.size();
    Eigen::Vector3d newell = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < n; ++k) newell += point(face[k]).cross(point(face[(k + 1) % n]));
    if (newell.norm() == 0.0) continue;
    const Eigen::Vector3d unit = newell.normalized();
    for (size_t k = 0; k < n; ++k) {
      const int normal = document.faceNormals[f][k];
      if (normal < 0) continue;
      const Eigen::Vector3d a = point(face[(k + n - 1) % n]) - point(face[k]);
      const Eigen::Vector3d b = point(face[(k + 1) % n]) - point(face[k]);
      const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
      sums.row(normal) += angle * unit.transpose();
    }
  }
  Eigen::MatrixXd normals = document.normals;
  for (int i = 0; i < document.normalCount; ++i) {
    if (sums.row(i).norm() > 0.0) normals.row(i) = sums.row(i).normalized();
  }
  return normals;
}

void writeObjDocument(const std::string& path, const MeshDocument& document, const Eigen::MatrixXd& positions,
                      const Eigen::MatrixXd& givenNormals) {
  if (document.records.empty()) {
    saveObj(path, positions, document.geometry);
    return;
  }
  if (positions.rows() != document.geometry.numVertices() || (positions.cols() != 2 && positions.cols() != 3)) {
    throw InputError(path, -1,
                     "cannot write " + std::to_string(positions.rows()) + " positions for a mesh of " +
                         std::to_string(document.geometry.numVertices()) + " vertices",
                     "nothing was written: give one position per vertex of the mesh");
  }
  for (Eigen::Index i = 0; i < positions.rows(); ++i) {
    if (!positions.row(i).allFinite()) {
      throw InputError(path, -1, "vertex " + std::to_string(i) + " has a coordinate that is not finite",
                       "nothing was written: the points that could not be computed lie on the cage or far outside");
    }
  }
  SOMICAGE_ASSERT(givenNormals.size() == 0 || givenNormals.rows() == document.normalCount,
                  "writeObjDocument takes one normal per `vn` record");
  const Eigen::MatrixXd normals = givenNormals.size() ? givenNormals : recomputeNormals(document, positions);
  std::string out;
  out.reserve(static_cast<size_t>(positions.rows()) * 64 + document.records.size() * 32);
  for (const ObjRecord& record : document.records) {
    if (record.kind == ObjRecord::Kind::Position) {
      out += "v";
      for (Eigen::Index c = 0; c < 3; ++c) {
        out += ' ';
        appendNumber(out, c < positions.cols() ? positions(record.index, c) : 0.0);
      }
      out += record.text;
    } else if (record.kind == ObjRecord::Kind::Normal) {
      out += "vn";
      for (Eigen::Index c = 0; c < 3; ++c) {
        out += ' ';
        appendNumber(out, normals(record.index, c));
      }
    } else if (objKeyword(record.text) == "mtllib") {
      out += relocatedMaterialLibraries(record.text, document.sourcePath, path);
    } else {
      out += record.text;
    }
    out += '\n';
  }
  writeFileAtomic(path, out);
}

DocumentMaterials documentMaterials(const MeshDocument& document) {
  DocumentMaterials out;
  std::vector<MeshMaterial> known = document.materials;
  const fs::path folder = fs::path(document.sourcePath).parent_path();
  for (const ObjRecord& record : document.records) {
    if (record.kind != ObjRecord::Kind::Text) continue;
    const std::vector<std::string_view> tokens = splitTokens(record.text);
    if (tokens.empty() || tokens[0] != "mtllib") continue;
    for (size_t k = 1; k < tokens.size(); ++k) {
      const fs::path name{std::string(tokens[k])};
      const std::string library = name.is_absolute() ? name.string() : (folder / name).string();
      std::error_code error;
      if (!fs::is_regular_file(library, error)) {
        out.notes.push_back("the material library " + library + " was not found: its materials are written white");
        continue;
      }
      for (MeshMaterial& material : parseMtl(readTextFile(library), library)) known.push_back(std::move(material));
    }
  }
  std::vector<std::string> undefined;
  for (const std::string& name : document.faceMaterial) {
    if (std::any_of(out.materials.begin(), out.materials.end(), [&](const MeshMaterial& m) { return m.name == name; }))
      continue;
    // The first definition counts, as in every OBJ reader.
    const auto found = std::find_if(known.begin(), known.end(), [&](const MeshMaterial& m) { return m.name == name; });
    if (found != known.end()) {
      out.materials.push_back(*found);
      continue;
    }
    MeshMaterial white;
    white.name = name;
    out.materials.push_back(white);
    if (!name.empty()) undefined.push_back(name);
  }
  for (const std::string& name : undefined)
    out.notes.push_back("the material '" + name + "' is not defined in the mesh's material libraries: written white");
  return out;
}

}  // namespace somicage
