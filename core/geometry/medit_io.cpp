#include "geometry/medit_io.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string_view>
#include <vector>

#include "base/errors.h"
#include "base/file_util.h"

namespace somicage {

namespace {

constexpr const char* kFormatHint =
    "write MeshVersionFormatted, Dimension 3, Vertices (x y z ref), Tetrahedra (four 1-based indices and a ref) "
    "and End, as CGAL, TetGen (-g) or Gmsh write .mesh files";

// Whitespace-separated tokens with their lines; `#` comments run to the end of the line. CR, LF and CRLF end lines.
class Tokens {
 public:
  Tokens(const std::string& text, std::string source) : text_(text), source_(std::move(source)) {}

  // The next token, or false at the end of the text.
  bool next(std::string_view& token) {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') ++pos_;
      } else if (c == '\n' || (c == '\r' && (pos_ + 1 >= text_.size() || text_[pos_ + 1] != '\n'))) {
        ++line_;
        ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++pos_;
      } else {
        break;
      }
    }
    if (pos_ >= text_.size()) return false;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_])) && text_[pos_] != '#') ++pos_;
    token = std::string_view(text_).substr(start, pos_ - start);
    return true;
  }

  std::string_view expect(const std::string& what) {
    std::string_view token;
    if (!next(token)) fail("the file ends where " + what + " should follow", kFormatHint);
    return token;
  }

  double number(const std::string& what) {
    const std::string_view token = expect(what);
    double value = 0;
    const char* end = token.data() + token.size();
    const auto result = std::from_chars(token.data(), end, value);
    if (result.ec != std::errc() || result.ptr != end || !std::isfinite(value))
      fail(what + " '" + std::string(token) + "' is not a finite number", "write a decimal number such as 0.25");
    return value;
  }

  long long integer(const std::string& what, long long lo, long long hi) {
    const std::string_view token = expect(what);
    long long value = 0;
    const char* end = token.data() + token.size();
    const auto result = std::from_chars(token.data(), end, value);
    if (result.ec != std::errc() || result.ptr != end)
      fail(what + " '" + std::string(token) + "' is not a whole number", kFormatHint);
    if (value < lo || value > hi)
      fail(what + " " + std::to_string(value) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]",
           kFormatHint);
    return value;
  }

  [[noreturn]] void fail(const std::string& problem, const std::string& hint) const {
    throw InputError(source_, line_, problem, hint);
  }
  long line() const { return line_; }

 private:
  const std::string& text_;
  std::string source_;
  std::size_t pos_ = 0;
  long line_ = 1;
};

bool sameKeyword(std::string_view token, const char* keyword) {
  const std::string_view k(keyword);
  if (token.size() != k.size()) return false;
  for (std::size_t i = 0; i < k.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(token[i])) != std::tolower(static_cast<unsigned char>(k[i])))
      return false;
  return true;
}

// Sections skipped, with the numbers per entry.
struct SkippedSection {
  const char* keyword;
  int numbers;
};
constexpr SkippedSection kSkipped[] = {
    {"Edges", 3},    {"Triangles", 4},        {"Quadrilaterals", 5}, {"Corners", 1},
    {"Ridges", 1},   {"RequiredVertices", 1}, {"RequiredEdges", 1},  {"RequiredTriangles", 1},
    {"Hexahedra", 9}};

// Far more than any cage's volume mesh; keeps a corrupt count from reserving the machine's memory.
constexpr long long kMaxEntries = 50000000;

}  // namespace

MeditMesh parseMedit(const std::string& text, const std::string& source) {
  Tokens in(text, source);
  MeditMesh out;
  out.source.name = source;
  int dim = 0;
  bool haveVersion = false, haveVertices = false, haveElements = false, ended = false;
  std::vector<double> coordinates;
  std::vector<int> indices;
  std::string_view token;
  while (!ended && in.next(token)) {
    if (sameKeyword(token, "MeshVersionFormatted")) {
      in.integer("the version", 1, 2);
      haveVersion = true;
    } else if (sameKeyword(token, "Dimension")) {
      dim = static_cast<int>(in.integer("the dimension", 2, 3));
    } else if (sameKeyword(token, "Vertices")) {
      if (dim == 0) in.fail("Vertices comes before Dimension", kFormatHint);
      if (haveVertices) in.fail("a second Vertices section", "write the vertices in one section");
      const long long n = in.integer("the vertex count", 1, kMaxEntries);
      for (long long v = 0; v < n; ++v) {
        for (int a = 0; a < dim; ++a) {
          coordinates.push_back(
              in.number("coordinate " + std::to_string(a + 1) + " of vertex " + std::to_string(v + 1)));
          if (a == 0) out.source.vertexLines.push_back(in.line());  // the line of its first number
        }
        in.integer("the reference of vertex " + std::to_string(v + 1), -(1LL << 31), (1LL << 31) - 1);
      }
      haveVertices = true;
    } else if (dim != 0 && sameKeyword(token, dim == 3 ? "Tetrahedra" : "Triangles")) {
      if (!haveVertices) in.fail(std::string(token) + " comes before Vertices", kFormatHint);
      if (haveElements) in.fail("a second " + std::string(token) + " section", "write the elements in one section");
      const long long n = in.integer("the element count", 1, kMaxEntries);
      const long long vertices = static_cast<long long>(out.source.vertexLines.size());
      for (long long s = 0; s < n; ++s) {
        for (int k = 0; k <= dim; ++k) {
          indices.push_back(static_cast<int>(
              in.integer("index " + std::to_string(k + 1) + " of element " + std::to_string(s + 1), 1, vertices) - 1));
          if (k == 0) out.source.simplexLines.push_back(in.line());
        }
        in.integer("the reference of element " + std::to_string(s + 1), -(1LL << 31), (1LL << 31) - 1);
      }
      haveElements = true;
    } else if (sameKeyword(token, "End")) {
      ended = true;
    } else {
      const SkippedSection* skipped = nullptr;
      for (const SkippedSection& s : kSkipped)
        if (sameKeyword(token, s.keyword)) skipped = &s;
      if (skipped == nullptr)
        in.fail("unknown keyword '" + std::string(token) + "'",
                "a volume mesh has MeshVersionFormatted, Dimension, Vertices, " +
                    std::string(dim == 2 ? "Triangles" : "Tetrahedra") +
                    " and End (Edges, Triangles, Corners, "
                    "Ridges and Required* are skipped)");
      const long long n = in.integer("the entry count of " + std::string(skipped->keyword), 0, kMaxEntries);
      for (long long e = 0; e < n * skipped->numbers; ++e) in.expect("an entry of " + std::string(skipped->keyword));
    }
  }
  if (!haveVersion) in.fail("no MeshVersionFormatted line", kFormatHint);
  if (!haveVertices) in.fail("no Vertices section", kFormatHint);
  if (!haveElements) in.fail(std::string("no ") + (dim == 3 ? "Tetrahedra" : "Triangles") + " section", kFormatHint);
  if (!ended) in.fail("no End keyword: the file looks cut short", "write End after the last section");
  const int n = static_cast<int>(out.source.vertexLines.size()), m = static_cast<int>(out.source.simplexLines.size());
  out.mesh.vertices.resize(n, dim);
  for (int v = 0; v < n; ++v)
    for (int a = 0; a < dim; ++a) out.mesh.vertices(v, a) = coordinates[static_cast<std::size_t>(v * dim + a)];
  out.mesh.simplices.resize(m, dim + 1);
  for (int s = 0; s < m; ++s)
    for (int k = 0; k <= dim; ++k) out.mesh.simplices(s, k) = indices[static_cast<std::size_t>(s * (dim + 1) + k)];
  return out;
}

MeditMesh readMedit(const std::string& path) { return parseMedit(readTextFile(path), path); }

std::string formatMedit(const VolumeMesh& mesh) {
  const int dim = mesh.dim();
  std::string out = "MeshVersionFormatted 2\nDimension " + std::to_string(dim) + "\nVertices\n" +
                    std::to_string(mesh.numVertices()) + "\n";
  char number[40];
  for (int v = 0; v < mesh.numVertices(); ++v) {
    for (int a = 0; a < dim; ++a) {
      std::snprintf(number, sizeof number, "%.17g ", mesh.vertices(v, a));
      out += number;
    }
    out += "0\n";
  }
  out += std::string(dim == 3 ? "Tetrahedra" : "Triangles") + "\n" + std::to_string(mesh.numSimplices()) + "\n";
  for (int s = 0; s < mesh.numSimplices(); ++s) {
    for (int k = 0; k <= dim; ++k) out += std::to_string(mesh.simplices(s, k) + 1) + " ";
    out += "0\n";
  }
  return out + "End\n";
}

}  // namespace somicage
