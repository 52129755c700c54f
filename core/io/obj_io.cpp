#include "io/obj_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <numeric>
#include <string_view>

#include "base/errors.h"

namespace somicage {

bool isBlank(char c) { return c == ' ' || c == '\t'; }

void splitTokens(std::string_view s, std::vector<std::string_view>& tokens) {
  tokens.clear();
  size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && isBlank(s[i])) ++i;
    const size_t start = i;
    while (i < s.size() && !isBlank(s[i])) ++i;
    if (i > start) tokens.push_back(s.substr(start, i - start));
  }
}

std::vector<std::string_view> splitTokens(std::string_view s) {
  std::vector<std::string_view> tokens;
  splitTokens(s, tokens);
  return tokens;
}

std::string_view objKeyword(std::string_view line) {
  const size_t end = line.find_first_of(" \t");
  return end == std::string_view::npos ? std::string_view() : line.substr(0, end);
}

namespace {

// ---------------------------------------------------------------------------------------------------------------
// Reading the text
// ---------------------------------------------------------------------------------------------------------------

std::string readTextFile(const std::string& path) {
  struct stat info;
  if (::stat(path.c_str(), &info) != 0) {
    const int error = errno;
    throw InputError(path, -1, std::string("cannot open the file: ") + std::strerror(error),
                     error == ENOENT ? "check the path and the file name" : "check that the file is readable");
  }
  if (S_ISDIR(info.st_mode)) throw InputError(path, -1, "is a folder, not a file", "give the path of an .obj file");

  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) {
    const int error = errno;
    throw InputError(path, -1, std::string("cannot open the file: ") + std::strerror(error),
                     "check that the file is readable");
  }
  std::string text;
  char buffer[1 << 16];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, n);
  const bool failed = std::ferror(file) != 0;
  const int error = errno;
  std::fclose(file);
  if (failed) {
    throw InputError(path, -1, std::string("cannot read the file: ") + std::strerror(error),
                     "check that the file is readable");
  }
  return text;
}

// The 1-based line that holds text[offset].
long lineAt(std::string_view text, size_t offset) {
  LineCursor cursor(text.substr(0, offset + 1));
  std::string_view line;
  while (cursor.next(line)) continue;
  return cursor.lineNumber();
}

// The vertex part of a face or line token (i, i/t, i//n, i/t/n): a nonzero integer, negative = relative.
bool parseVertexIndex(std::string_view token, long long& index) {
  const std::string_view part = token.substr(0, token.find('/'));
  const char* end = part.data() + part.size();
  const auto result = std::from_chars(part.data(), end, index);
  return result.ec == std::errc() && result.ptr == end && !part.empty();
}

std::string quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

// What the one pass over the file collects: vertex positions (see parseObjNumber), faces and `l` polylines
// (tinyobjloader 2.0.0rc10 drops line groups before a `g` and repeats them after a `usemtl`), each element with
// its line.
struct ObjScan {
  std::vector<double> coordinates;            // 3 per vertex
  std::vector<std::vector<long long>> faces;  // resolved 0-based indices, range checked later
  std::vector<long> faceLines;
  std::vector<std::vector<long long>> lines;  // the same for `l` elements
  std::vector<long> lineLines;
  std::vector<std::string_view> tokens;  // the current line's, kept to reuse its memory
};

// A 1-based index, or a negative one relative to the vertices read so far, as a 0-based index.
long long resolveIndex(long long index, const ObjScan& scan) {
  return index > 0 ? index - 1 : static_cast<long long>(scan.coordinates.size() / 3) + index;
}

void scanVertex(const std::string& source, long lineNumber, std::string_view rest, ObjScan& scan) {
  const long index = static_cast<long>(scan.coordinates.size() / 3);
  std::vector<std::string_view>& tokens = scan.tokens;
  splitTokens(rest, tokens);
  // Messages are composed only when one is thrown: a file has a hundred thousand lines that need none.
  const auto element = [&] { return "vertex " + std::to_string(index); };
  if (tokens.size() < 2) {
    throw InputError(
        source, lineNumber,
        element() + " has " + std::to_string(tokens.size()) + (tokens.size() == 1 ? " coordinate" : " coordinates"),
        "write vertices as `v x y z`, or `v x y` in a 2D file");
  }
  const size_t count = std::min<size_t>(tokens.size(), 3);
  for (size_t k = 0; k < 3; ++k) {
    double value = 0.0;
    if (k < count) {
      static const char* const kAxis[3] = {"x", "y", "z"};
      const auto what = [&] { return element() + ": " + kAxis[k] + " = " + quoted(tokens[k]); };
      switch (parseObjNumber(tokens[k], value)) {
        case ObjNumberStatus::Ok:
          break;
        case ObjNumberStatus::NotANumber:
          throw InputError(source, lineNumber, what() + " is not a number", "write coordinates as decimal numbers");
        case ObjNumberStatus::OutOfRange:
          throw InputError(source, lineNumber, what() + " is outside the range of a double",
                           "scale the model to a reasonable size");
        case ObjNumberStatus::NotFinite:
          throw InputError(source, lineNumber, what() + " is not finite",
                           "every coordinate must be a finite number: fix or remove this vertex");
      }
    }
    scan.coordinates.push_back(value);
  }
}

void scanFace(const std::string& source, long lineNumber, std::string_view rest, ObjScan& scan) {
  const auto element = [&] { return "face " + std::to_string(scan.faceLines.size()); };
  std::vector<std::string_view>& tokens = scan.tokens;
  splitTokens(rest, tokens);
  std::vector<long long> indices;
  indices.reserve(tokens.size());
  for (const std::string_view token : tokens) {
    long long index = 0;
    if (!parseVertexIndex(token, index)) {
      throw InputError(source, lineNumber, element() + ": " + quoted(token) + " is not a vertex index",
                       "write faces as `f i j k ...` with 1-based vertex indices; i/t/n forms are fine");
    }
    if (index == 0) {
      throw InputError(source, lineNumber, element() + " uses vertex index 0, which does not exist",
                       "OBJ vertex indices start at 1; negative ones count back from the last vertex");
    }
    if (index > INT_MAX || index < -static_cast<long long>(INT_MAX)) {
      throw InputError(source, lineNumber, element() + ": vertex index " + quoted(token) + " is out of range",
                       "the file does not have that many vertices");
    }
    indices.push_back(resolveIndex(index, scan));
  }
  if (tokens.size() < 3) {
    throw InputError(source, lineNumber, element() + " has " + std::to_string(tokens.size()) + " vertices",
                     "a face needs at least 3 vertices: if the file was cut short here, export it again (an edge of a polyline "
                     "is an `l i j` line)");
  }
  if (tokens.size() > 255) {
    throw InputError(source, lineNumber, element() + " has " + std::to_string(tokens.size()) + " vertices",
                     "faces of up to 255 vertices are supported: split this polygon");
  }
  scan.faces.push_back(std::move(indices));
  scan.faceLines.push_back(lineNumber);
}

void scanLine(const std::string& source, long lineNumber, std::string_view rest, ObjScan& scan) {
  const auto element = [&] { return "line element " + std::to_string(scan.lines.size()); };
  std::vector<long long> indices;
  splitTokens(rest, scan.tokens);
  for (const std::string_view token : scan.tokens) {
    long long index = 0;
    if (!parseVertexIndex(token, index) || index == 0) {
      throw InputError(source, lineNumber, element() + ": " + quoted(token) + " is not a vertex index",
                       "write polylines as `l i j ...` with 1-based vertex indices");
    }
    indices.push_back(resolveIndex(index, scan));
  }
  if (indices.size() < 2) {
    throw InputError(source, lineNumber, element() + " has " + std::to_string(indices.size()) + " vertices",
                     "an `l` element needs at least 2 vertices");
  }
  scan.lines.push_back(std::move(indices));
  scan.lineLines.push_back(lineNumber);
}

ObjScan scanObj(std::string_view text, const std::string& source, const ObjLineVisitor& visitor) {
  ObjScan scan;
  LineCursor cursor(text);
  std::string_view raw;
  while (cursor.next(raw)) {
    std::string_view line = raw;
    while (!line.empty() && isBlank(line.front())) line.remove_prefix(1);
    const std::string_view keyword = objKeyword(line);
    if (keyword.size() == 1) {  // else blank, a comment, or another record
      const std::string_view rest = line.substr(2);
      if (keyword[0] == 'v') scanVertex(source, cursor.lineNumber(), rest, scan);
      if (keyword[0] == 'f') scanFace(source, cursor.lineNumber(), rest, scan);
      if (keyword[0] == 'l') scanLine(source, cursor.lineNumber(), rest, scan);
    }
    if (visitor) visitor(cursor.lineNumber(), raw, line, keyword);
  }
  return scan;
}

std::string outOfRangeMessage(const std::string& element, long long index, int vertexCount) {
  const std::string which =
      index >= 0 ? "index " + std::to_string(index + 1) : "a vertex before the first (relative index)";
  return element + " refers to " + which + ", but the file has " + std::to_string(vertexCount) + " vertices";
}

// ---------------------------------------------------------------------------------------------------------------
// Triangulation
// ---------------------------------------------------------------------------------------------------------------

double orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

double minAngle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const auto angle = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));
  };
  return std::min({angle(b - a, c - a), angle(c - b, a - b), angle(a - c, b - c)});
}

// Ear clipping of one polygon in the plane of its Newell normal; triangles keep the polygon's winding.
void triangulatePolygon(const Eigen::MatrixXd& V, const std::vector<int>& polygon,
                        std::vector<std::array<int, 3>>& triangles) {
  const int n = static_cast<int>(polygon.size());
  if (n == 3) {
    triangles.push_back({polygon[0], polygon[1], polygon[2]});
    return;
  }
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const int i : polygon) centre += V.row(i).transpose();
  centre /= n;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d a = V.row(polygon[k]).transpose() - centre;
    const Eigen::Vector3d b = V.row(polygon[(k + 1) % n]).transpose() - centre;
    normal += a.cross(b);
  }
  if (normal.norm() == 0.0) normal = Eigen::Vector3d::UnitZ();
  normal.normalize();
  // (u, v, normal) is right-handed, so the projected polygon turns counter-clockwise.
  const Eigen::Vector3d u = normal.unitOrthogonal();
  const Eigen::Vector3d v = normal.cross(u);
  std::vector<Eigen::Vector2d> P(n);
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d p = V.row(polygon[k]).transpose() - centre;
    P[k] = Eigen::Vector2d(p.dot(u), p.dot(v));
  }

  std::vector<int> remaining(n);
  std::iota(remaining.begin(), remaining.end(), 0);
  while (remaining.size() > 3) {
    const int m = static_cast<int>(remaining.size());
    int best = -1, mostConvex = 0;
    double bestScore = -1.0, bestTurn = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < m; ++k) {
      const int a = remaining[(k + m - 1) % m], b = remaining[k], c = remaining[(k + 1) % m];
      const double turn = orient2d(P[a], P[b], P[c]);
      if (turn > bestTurn) bestTurn = turn, mostConvex = k;
      if (turn <= 0.0) continue;
      bool blocked = false;
      for (const int q : remaining) {
        if (q == a || q == b || q == c || P[q] == P[a] || P[q] == P[b] || P[q] == P[c]) continue;
        if (orient2d(P[a], P[b], P[q]) >= 0 && orient2d(P[b], P[c], P[q]) >= 0 && orient2d(P[c], P[a], P[q]) >= 0) {
          blocked = true;
          break;
        }
      }
      if (blocked) continue;
      const double score = minAngle(P[a], P[b], P[c]);
      if (score > bestScore) bestScore = score, best = k;
    }
    if (best < 0) best = mostConvex;  // no proper ear (self-overlapping polygon): validation reports the result
    triangles.push_back(
        {polygon[remaining[(best + m - 1) % m]], polygon[remaining[best]], polygon[remaining[(best + 1) % m]]});
    remaining.erase(remaining.begin() + best);
  }
  triangles.push_back({polygon[remaining[0]], polygon[remaining[1]], polygon[remaining[2]]});
}

// ---------------------------------------------------------------------------------------------------------------
// 2D loops
// ---------------------------------------------------------------------------------------------------------------

long sourceLine(const std::vector<long>& lines, size_t k) { return k < lines.size() ? lines[k] : -1; }

// Chains the `l` elements, in file order, into one vertex loop (the closing repeat of the first vertex dropped).
std::vector<int> chainLines(const PolygonMesh& mesh, const std::string& source) {
  std::vector<int> loop = mesh.lines[0];
  for (size_t k = 1; k < mesh.lines.size(); ++k) {
    const std::vector<int>& line = mesh.lines[k];
    if (loop.size() > 1 && loop.front() == loop.back()) {
      throw InputError(source, sourceLine(mesh.lineSourceLines, k),
                       "line element " + std::to_string(k) + " comes after the polygon loop was already closed",
                       "a 2D cage is one polygon: write it as a single `l` loop");
    }
    if (line.front() != loop.back()) {
      throw InputError(source, sourceLine(mesh.lineSourceLines, k),
                       "line element " + std::to_string(k) + " starts at index " + std::to_string(line.front() + 1) +
                           ", not where the previous one ends (index " + std::to_string(loop.back() + 1) + ")",
                       "a 2D cage is one polygon: write `l` elements that continue each other, or a single loop");
    }
    loop.insert(loop.end(), line.begin() + 1, line.end());
  }
  if (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
  return loop;
}

void checkLoop(const std::vector<int>& loop, int vertexCount, const std::string& source, long line) {
  if (loop.size() < 3) {
    throw InputError(source, line, "the polygon has " + std::to_string(loop.size()) + " vertices",
                     "a 2D cage needs at least 3 vertices");
  }
  std::vector<int> seen(vertexCount, 0);
  for (const int i : loop) {
    if (seen[i]++) {
      throw InputError(source, line, "the polygon visits index " + std::to_string(i + 1) + " twice",
                       "a 2D cage is a simple polygon: every vertex appears once in the loop");
    }
  }
  for (int i = 0; i < vertexCount; ++i) {
    if (!seen[i]) {
      throw InputError(
          source, line,
          "vertex " + std::to_string(i) + " (index " + std::to_string(i + 1) + ") is not on the polygon loop",
          "remove the vertex or add it to the loop: every vertex of a 2D cage is on its polygon");
    }
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Writing
// ---------------------------------------------------------------------------------------------------------------

mode_t newFileMode() {
  mode_t mask = 022;
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "Umask:") {
      std::string value;
      status >> value;
      mask = static_cast<mode_t>(std::strtol(value.c_str(), nullptr, 8));
      break;
    }
  }
  return 0666 & ~mask;
}

// Writes the data to a temporary file next to path, flushes it to disk and renames it over path.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path) : path_(path) {
    std::string pattern = path + ".tmp-XXXXXX";
    tempName_.assign(pattern.begin(), pattern.end());
    tempName_.push_back('\0');
    fd_ = ::mkstemp(tempName_.data());
    if (fd_ < 0) {
      const int error = errno;
      throw InputError(path_, -1, std::string("cannot create a file in this folder: ") + std::strerror(error),
                       "check that the folder exists and that you may write to it");
    }
    struct stat old;
    const mode_t mode =
        (::stat(path.c_str(), &old) == 0 && S_ISREG(old.st_mode)) ? (old.st_mode & 07777) : newFileMode();
    ::fchmod(fd_, mode);
    buffer_.reserve(kBufferSize + 256);
  }

  ~AtomicFile() { abandon(); }
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::string& buffer() { return buffer_; }
  void flushIfFull() {
    if (buffer_.size() >= kBufferSize) flush();
  }

  void commit() {
    flush();
    if (::fsync(fd_) != 0) fail("cannot flush the file to disk");
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail("cannot close the file");
    if (std::rename(tempName_.data(), path_.c_str()) != 0) fail("cannot replace the file");
    committed_ = true;
    // Make the rename itself durable (best effort: some file systems cannot sync a folder).
    const int dir = ::open(folderOf(path_).c_str(), O_RDONLY | O_DIRECTORY);
    if (dir >= 0) {
      ::fsync(dir);
      ::close(dir);
    }
  }

 private:
  static constexpr size_t kBufferSize = 1 << 20;

  static std::string folderOf(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
  }

  void flush() {
    const char* data = buffer_.data();
    size_t left = buffer_.size();
    while (left > 0) {
      const ssize_t written = ::write(fd_, data, left);
      if (written < 0) {
        if (errno == EINTR) continue;
        fail("cannot write the file");
      }
      data += written;
      left -= static_cast<size_t>(written);
    }
    buffer_.clear();
  }

  [[noreturn]] void fail(const std::string& what) {
    const int error = errno;
    abandon();
    throw InputError(path_, -1, what + ": " + std::strerror(error),
                     "the previous file, if any, was left unchanged; check the free space and the permissions");
  }

  void abandon() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!committed_ && !tempName_.empty()) ::unlink(tempName_.data());
    committed_ = true;  // nothing left to clean up
  }

  std::string path_;
  std::vector<char> tempName_;
  int fd_ = -1;
  bool committed_ = false;
  std::string buffer_;
};

void appendNumber(std::string& out, double value) {
  char text[40];
  const auto result = std::to_chars(text, text + sizeof text, value, std::chars_format::general, 17);
  out.append(text, result.ptr);
}

void appendIndexList(std::string& out, char record, const std::vector<int>& indices) {
  out += record;
  for (const int i : indices) {
    out += ' ';
    out += std::to_string(i + 1);
  }
  out += '\n';
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------------
// Public functions
// ---------------------------------------------------------------------------------------------------------------

// Correctly rounded and locale-independent (tinyobjloader's parser is neither, and reads "nan" as 0: why the file
// is parsed here, in one pass, rather than by it).
ObjNumberStatus parseObjNumber(std::string_view token, double& value) {
  if (!token.empty() && token[0] == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token[0] == '-') return ObjNumberStatus::NotANumber;
  }
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  if (result.ptr != end || token.empty()) return ObjNumberStatus::NotANumber;
  if (result.ec == std::errc::result_out_of_range) return ObjNumberStatus::OutOfRange;
  if (result.ec != std::errc()) return ObjNumberStatus::NotANumber;
  if (!std::isfinite(value)) return ObjNumberStatus::NotFinite;
  return ObjNumberStatus::Ok;
}

PolygonMesh parseObj(const std::string& rawText, const std::string& source, const ObjLineVisitor& visitor) {
  std::string_view text(rawText);
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark
  if (text.empty()) {
    throw InputError(source, -1, "the file is empty", "an OBJ file lists vertices as `v x y z` lines");
  }
  // A NUL byte means a binary file, whatever the rest looks like.
  if (const size_t nul = text.find('\0'); nul != std::string_view::npos) {
    throw InputError(source, lineAt(text, nul), "the file contains a NUL byte: it is not a text OBJ file",
                     "export the model again as a text .obj file");
  }
  const ObjScan scan = scanObj(text, source, visitor);
  const int vertexCount = static_cast<int>(scan.coordinates.size() / 3);
  if (vertexCount == 0) {
    throw InputError(source, -1, "the file has no vertices", "an OBJ file lists vertices as `v x y z` lines");
  }

  PolygonMesh mesh;
  mesh.vertices = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(scan.coordinates.data(),
                                                                                              vertexCount, 3);

  // Elements refer to vertices by index: each must exist.
  auto resolve = [&](const std::vector<long long>& element, const std::string& name, long line) {
    std::vector<int> out;
    for (const long long i : element) {
      if (i < 0 || i >= vertexCount) {
        throw InputError(source, line, outOfRangeMessage(name, i, vertexCount),
                         "OBJ vertex indices run from 1 to the vertex count; negative ones count back");
      }
      out.push_back(static_cast<int>(i));
    }
    return out;
  };
  for (size_t f = 0; f < scan.faces.size(); ++f)
    mesh.faces.push_back(resolve(scan.faces[f], "face " + std::to_string(f), scan.faceLines[f]));
  mesh.faceSourceLines = scan.faceLines;
  for (size_t k = 0; k < scan.lines.size(); ++k)
    mesh.lines.push_back(resolve(scan.lines[k], "line element " + std::to_string(k), scan.lineLines[k]));
  mesh.lineSourceLines = scan.lineLines;
  return mesh;
}

PolygonMesh loadMesh(const std::string& path) { return parseObj(readTextFile(path), path); }

Eigen::MatrixXi triangulatePolygons(const Eigen::MatrixXd& vertices, const std::vector<std::vector<int>>& faces) {
  SOMICAGE_ASSERT(vertices.cols() == 3, "triangulatePolygons takes 3D vertices");
  std::vector<std::array<int, 3>> triangles;
  triangles.reserve(faces.size() * 2);
  for (const std::vector<int>& face : faces) {
    SOMICAGE_ASSERT(face.size() >= 3, "a polygon has at least 3 vertices");
    triangulatePolygon(vertices, face, triangles);
  }
  Eigen::MatrixXi T(static_cast<Eigen::Index>(triangles.size()), 3);
  for (size_t t = 0; t < triangles.size(); ++t) {
    T.row(static_cast<Eigen::Index>(t)) << triangles[t][0], triangles[t][1], triangles[t][2];
  }
  return T;
}

Cage cageFromMesh(const PolygonMesh& mesh, const std::string& source) {
  const int vertexCount = mesh.numVertices();
  if (vertexCount == 0) throw InputError(source, -1, "the cage has no vertices", "give a cage with vertices");
  const bool planar = (mesh.vertices.col(2).array() == 0.0).all();

  if (!planar) {
    if (mesh.faces.empty()) {
      throw InputError(source, -1, "the cage has no faces",
                       "a 3D cage is a closed triangle mesh of `f` lines; for a 2D polygon cage set every z to 0");
    }
    Cage cage;
    cage.vertices = mesh.vertices;
    cage.faces = triangulatePolygons(mesh.vertices, mesh.faces);
    return cage;
  }

  std::vector<int> loop;
  long line = -1;
  if (mesh.faces.empty() && mesh.lines.empty()) {
    loop.resize(vertexCount);
    std::iota(loop.begin(), loop.end(), 0);
  } else if (mesh.faces.empty()) {
    loop = chainLines(mesh, source);
    line = sourceLine(mesh.lineSourceLines, 0);
  } else if (mesh.faces.size() == 1 && mesh.lines.empty()) {
    loop = mesh.faces[0];
    if (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
    line = sourceLine(mesh.faceSourceLines, 0);
  } else {
    throw InputError(source, sourceLine(mesh.faceSourceLines, mesh.faces.size() > 1 ? 1 : 0),
                     "every vertex has z = 0 (a 2D cage), but the file has " + std::to_string(mesh.faces.size()) +
                         " faces and " + std::to_string(mesh.lines.size()) + " line elements",
                     "a 2D cage is one polygon: its vertices in order, one `l` loop or one face; a 3D cage must "
                     "enclose a volume");
  }
  checkLoop(loop, vertexCount, source, line);

  const Eigen::MatrixXd xy = mesh.vertices.leftCols(2);
  bool inFileOrder = true;
  for (int k = 0; k < vertexCount; ++k) inFileOrder = inFileOrder && loop[k] == k;
  if (inFileOrder) return makePolygonCage(xy);
  Cage cage;  // keep the file's vertex order so that posed files match; the edges follow the loop
  cage.vertices = xy;
  cage.faces.resize(vertexCount, 2);
  for (int k = 0; k < vertexCount; ++k) cage.faces.row(k) << loop[k], loop[(k + 1) % vertexCount];
  return cage;
}

void requirePosedVertexCount(const Cage& restCage, long vertices, const std::string& source) {
  if (vertices != restCage.numVertices()) {
    throw InputError(source, -1,
                     "the posed cage has " + std::to_string(vertices) + " vertices, the rest cage has " +
                         std::to_string(restCage.numVertices()),
                     "a pose lists the rest cage's vertices, in the same order");
  }
}

Eigen::MatrixXd posedVerticesFromMesh(const PolygonMesh& mesh, const Cage& restCage, const std::string& source) {
  requirePosedVertexCount(restCage, mesh.numVertices(), source);
  return restCage.dim() == 3 ? mesh.vertices : Eigen::MatrixXd(mesh.vertices.leftCols(2));
}

PolygonMesh cageTopology(const Cage& cage) {
  PolygonMesh mesh;
  mesh.vertices = Eigen::MatrixXd::Zero(cage.numVertices(), 3);
  mesh.vertices.leftCols(cage.dim()) = cage.vertices;
  if (cage.dim() == 3) {
    for (int j = 0; j < cage.numFaces(); ++j)
      mesh.faces.push_back({cage.faces(j, 0), cage.faces(j, 1), cage.faces(j, 2)});
    return mesh;
  }
  // One closed `l` loop when the edges follow each other, else one `l` per edge.
  std::vector<int> loop;
  bool chained = cage.numFaces() > 0;
  for (int j = 0; j < cage.numFaces() && chained; ++j) {
    if (j == 0) loop.push_back(cage.faces(0, 0));
    chained = cage.faces(j, 0) == loop.back();
    loop.push_back(cage.faces(j, 1));
  }
  if (chained && loop.front() == loop.back()) {
    mesh.lines.push_back(loop);
  } else {
    for (int j = 0; j < cage.numFaces(); ++j) mesh.lines.push_back({cage.faces(j, 0), cage.faces(j, 1)});
  }
  return mesh;
}

void saveObj(const std::string& path, const Eigen::MatrixXd& vertices, const PolygonMesh& topology) {
  if (vertices.cols() != 2 && vertices.cols() != 3) {
    throw InputError(path, -1, "cannot write vertices with " + std::to_string(vertices.cols()) + " coordinates",
                     "give #V by 2 or #V by 3 vertices");
  }
  const Eigen::Index n = vertices.rows();
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!vertices.row(i).allFinite()) {
      throw InputError(path, -1, "vertex " + std::to_string(i) + " has a coordinate that is not finite",
                       "nothing was written: the points that could not be computed lie on the cage or far outside");
    }
  }
  const auto checkIndices = [&](const std::vector<std::vector<int>>& lists, const char* what) {
    for (size_t k = 0; k < lists.size(); ++k) {
      for (const int i : lists[k]) {
        if (i < 0 || i >= n) {
          throw InputError(path, -1,
                           std::string(what) + " " + std::to_string(k) + " refers to vertex " + std::to_string(i) +
                               " of " + std::to_string(n),
                           "nothing was written: the topology does not match the vertices");
        }
      }
    }
  };
  checkIndices(topology.faces, "face");
  checkIndices(topology.lines, "line element");

  AtomicFile file(path);
  std::string& out = file.buffer();
  for (Eigen::Index i = 0; i < n; ++i) {
    out += "v ";
    appendNumber(out, vertices(i, 0));
    out += ' ';
    appendNumber(out, vertices(i, 1));
    out += ' ';
    appendNumber(out, vertices.cols() == 3 ? vertices(i, 2) : 0.0);
    out += '\n';
    file.flushIfFull();
  }
  for (const std::vector<int>& face : topology.faces) {
    appendIndexList(out, 'f', face);
    file.flushIfFull();
  }
  for (const std::vector<int>& line : topology.lines) {
    appendIndexList(out, 'l', line);
    file.flushIfFull();
  }
  file.commit();
}

void saveTextFile(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  file.buffer() = text;
  file.commit();
}

}  // namespace somicage
