// Wavefront OBJ input and output: meshes and point sets (any OBJ), cages (3D triangle meshes or 2D polygons)
// and posed cages. Only positions, faces (`f`) and polylines (`l`) are read; materials, texture coordinates
// and normals are ignored, so `f a/b/c`, `f a//c` and missing .mtl files are fine. Line endings may be LF,
// CRLF or CR.
//
// Every problem with a file throws somicage::InputError naming the file, the line (or -1), what is wrong and
// what to do about it. Elements are named 0-based ("face 3", with its line); "index N" is a vertex index as written
// in the file (1-based).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/cage.h"

namespace somicage {

// A mesh as written in the file.
//   vertices: #V by 3 positions (a 2D file has z = 0).
//   faces:    polygons as 0-based vertex index lists, in file order and winding (3 or more vertices each).
//   lines:    `l` polylines as 0-based vertex index lists, in file order (2 or more vertices each).
// A file with vertices only (no faces, no lines) is a point set.
struct PolygonMesh {
  Eigen::MatrixXd vertices;
  std::vector<std::vector<int>> faces;
  std::vector<std::vector<int>> lines;
  // 1-based line in the file of each face and each line element (empty for meshes made in code).
  std::vector<long> faceSourceLines;
  std::vector<long> lineSourceLines;

  int numVertices() const { return static_cast<int>(vertices.rows()); }
  int numFaces() const { return static_cast<int>(faces.size()); }
};

// OBJ separates tokens by spaces and tabs; every reader of OBJ lines splits them with these.
bool isBlank(char c);

// Splits text into lines: LF, CRLF or a lone CR ends a line (OBJ and MTL files come from every platform).
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}

  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const size_t end = text_.find_first_of("\r\n", pos_);
    ++lineNumber_;
    if (end == std::string_view::npos) {
      line = text_.substr(pos_);
      pos_ = text_.size();
      return true;
    }
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    if (text_[end] == '\r' && pos_ < text_.size() && text_[pos_] == '\n') ++pos_;
    return true;
  }

  long lineNumber() const { return lineNumber_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  long lineNumber_ = 0;
};

// The blank-separated tokens of a line.
std::vector<std::string_view> splitTokens(std::string_view line);
// The same into `tokens` (cleared first), whose capacity a loop over many lines reuses.
void splitTokens(std::string_view line, std::vector<std::string_view>& tokens);
// The record keyword of a line without leading blanks, as the parser reads it: its first token when a blank follows
// ("v", "vn", "usemtl"), else empty.
std::string_view objKeyword(std::string_view line);

// Sees every line of an OBJ text in the parser's one pass, in order, after the parser has read the line's own `v`,
// `f` or `l` record: its 1-based number, the line as written (no end of line), the line without leading blanks and
// its keyword (the first token when a blank follows it, else empty). How mesh_document.h keeps the other records.
using ObjLineVisitor =
    std::function<void(long lineNumber, std::string_view rawLine, std::string_view line, std::string_view keyword)>;

// The one reader of an OBJ number (`v`, `vn` and `vt` records alike): the whole token (an optional '+' or '-', no
// trailing text: "1.5x" is NotANumber), correctly rounded, locale-independent, and finite.
enum class ObjNumberStatus { Ok, NotANumber, OutOfRange, NotFinite };
ObjNumberStatus parseObjNumber(std::string_view token, double& value);

// Parses OBJ text. source names the text in error messages (normally the file path).
PolygonMesh parseObj(const std::string& text, const std::string& source, const ObjLineVisitor& visitor = {});

// Reads any OBJ file (mesh, polygon soup or point set). OBJ only: the front ends read every format through
// mesh_formats.h (loadAnyMesh, loadCage, loadPosedVertices), which parses OBJ with the same parser.
PolygonMesh loadMesh(const std::string& path);

// Triangulates polygons (#F polygons -> #T by 3), keeping the winding of each polygon: triangles stay as they
// are, larger polygons are cut by ear clipping in the plane of their Newell normal (the best-shaped ear first,
// so a quad is split along the diagonal that gives the larger minimum angle).
Eigen::MatrixXi triangulatePolygons(const Eigen::MatrixXd& vertices, const std::vector<std::vector<int>>& faces);

// Turns a mesh into a cage; source names it in error messages.
//   3D (some z != 0): the faces, triangulated (see triangulatePolygons); #V by 3 vertices.
//   2D (every z == 0): one polygon, #V by 2 vertices, in one of these forms:
//     - no faces and no lines: the vertices in file order are the loop;
//     - `l` elements that chain end to start into one closed loop (one `l a b c ... a`, or `l a b`, `l b c`...);
//     - exactly one face: its vertices are the loop.
//   The loop must visit every vertex exactly once. Vertex order is kept (cage vertex i = file vertex i), so a
//   posed file with the same vertex order matches. The loader never reorders or flips faces: validateCage
//   (cage_validation.h) reports a cage that is not closed, not manifold or inside out.
Cage cageFromMesh(const PolygonMesh& mesh, const std::string& source);

// Throws InputError naming source unless a pose has the rest cage's vertex count.
void requirePosedVertexCount(const Cage& restCage, long vertices, const std::string& source);
// The vertices of a posed cage (#V by d, d = restCage.dim(); a 2D cage takes x, y). The mesh must have the
// rest cage's vertex count, in the same order; its faces are not compared (a pose may list them in another order).
// source names it in error messages.
Eigen::MatrixXd posedVerticesFromMesh(const PolygonMesh& mesh, const Cage& restCage, const std::string& source);

// The topology to write a cage with saveObj: triangles (3D) or one closed `l` loop (2D). Vertices are copied.
PolygonMesh cageTopology(const Cage& cage);

// Writes vertices (#V by 2 or 3; 2 columns are written with z = 0) with %.17g, so that loadMesh reads back the
// same doubles, then topology's faces and lines in its order (topology.vertices is not used). Throws
// InputError if a coordinate is not finite or an index is out of range, without touching the file.
// The write is atomic: the data go to PATH.tmp-XXXXXX in the same folder, are flushed to disk (fsync) and
// renamed over PATH. On any failure the temporary file is removed, an existing PATH is left as it was, and an
// InputError carries the system's reason (strerror).
void saveObj(const std::string& path, const Eigen::MatrixXd& vertices, const PolygonMesh& topology);

// Writes text to path with saveObj's atomic replace (same guarantees and errors).
void saveTextFile(const std::string& path, const std::string& text);

}  // namespace somicage
