// OBJ reading and writing: every cage and mesh in the shared models, the bad files in tests/data (each names the
// loader, the line and the message it must produce in its first lines), bit-exact round trips, atomic writes.
#include "io/obj_io.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>

#include "base/errors.h"
#include "cage/cage_validation.h"
#include "io/mesh_formats.h"

namespace somicage {
namespace {

namespace fs = std::filesystem;

const fs::path kDataDir = SOMICAGE_TEST_DATA_DIR;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Every file under the models folder whose name (lower-cased unless caseSensitive) matches the pattern.
std::vector<fs::path> modelFiles(const std::string& pattern, bool caseSensitive = false) {
  std::vector<fs::path> files;
  const std::regex re(pattern);
  for (const auto& entry : fs::recursive_directory_iterator(SOMICAGE_MODELS_DIR)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && std::regex_match(caseSensitive ? name : lower(name), re)) {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

#define SKIP_WITHOUT_MODELS()                                                                            \
  if (!fs::is_directory(SOMICAGE_MODELS_DIR)) {                                                          \
    GTEST_SKIP() << "models folder " << SOMICAGE_MODELS_DIR << " is absent (set -DSOMICAGE_MODELS_DIR)"; \
  }

std::string readAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// A fresh folder, removed (with what is in it) at the end of the test.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "somicage-obj-test-XXXXXX").string();
    path_ = ::mkdtemp(pattern.data());
  }
  ~TempDir() {
    std::error_code ignored;
    fs::permissions(path_, fs::perms::owner_all, ignored);
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(path_)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  fs::path path_;
};

void expectClosedManifoldOutward(const Cage& cage) {
  const CageReport report = validateCage(cage);
  EXPECT_TRUE(report.closed());
  EXPECT_TRUE(report.manifold());
  EXPECT_TRUE(report.consistentlyOriented());
  EXPECT_TRUE(report.outward()) << "signed volume " << report.signedVolume;
  EXPECT_TRUE(report.valid());
  for (const std::string& problem : describeCageProblems(report)) ADD_FAILURE() << problem;
}

// ---------------------------------------------------------------------------------------------------------------
// The shared models
// ---------------------------------------------------------------------------------------------------------------

TEST(ObjModels, TriangleCagesAreClosedManifoldOutward) {
  SKIP_WITHOUT_MODELS();
  const auto files = modelFiles(R"(.*_cages_triangulated.*\.obj|(deformed_)?bounding_mesh.*\.obj|)"
                                R"(deformed_fixed_.*\.obj|bar_cage.*\.obj)");
  EXPECT_EQ(files.size(), 42u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const PolygonMesh mesh = loadMesh(file.string());
    for (const auto& face : mesh.faces) ASSERT_EQ(face.size(), 3u) << "not a triangle cage";
    const Cage cage = loadCage(file.string());
    ASSERT_EQ(cage.dim(), 3);
    EXPECT_EQ(cage.numFaces(), mesh.numFaces());
    EXPECT_EQ(cage.vertices, mesh.vertices);
    expectClosedManifoldOutward(cage);
  }
}

TEST(ObjModels, QuadCagesTriangulateToClosedManifoldCages) {
  SKIP_WITHOUT_MODELS();
  const auto files = modelFiles(R"(.*_Cage(_Deformed)?\.obj)", true);  // the QMVC quad cages
  EXPECT_EQ(files.size(), 16u);
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const PolygonMesh mesh = loadMesh(file.string());
    size_t triangles = 0, polygons = 0;
    for (const auto& face : mesh.faces) triangles += face.size() - 2, polygons += face.size() > 3;
    EXPECT_GT(polygons, 0u) << "expected quads";
    const Cage cage = loadCage(file.string());
    ASSERT_EQ(cage.dim(), 3);
    EXPECT_EQ(static_cast<size_t>(cage.numFaces()), triangles);
    expectClosedManifoldOutward(cage);
  }
}

// The rest cage of a pose file, by the naming conventions of models/README.md.
fs::path restCageOf(const fs::path& pose) {
  const std::string name = pose.filename().string();
  std::smatch match;
  if (std::regex_match(name, match, std::regex(R"(deformed_bounding_mesh\d+(b?)\.obj)"))) {
    return pose.parent_path() / ("bounding_mesh" + match[1].str() + ".obj");
  }
  if (std::regex_match(name, std::regex(R"(deformed_fixed_\d+\.obj)"))) return pose.parent_path() / "bounding_mesh.obj";
  return pose.parent_path() / std::regex_replace(name, std::regex("_[dD]eformed"), "");
}

TEST(ObjModels, PosesMatchTheirRestCages) {
  SKIP_WITHOUT_MODELS();
  const auto poses = modelFiles(R"(.*deformed.*\.obj)");
  EXPECT_EQ(poses.size(), 33u);
  for (const fs::path& pose : poses) {
    SCOPED_TRACE(pose.string());
    const fs::path rest = restCageOf(pose);
    ASSERT_TRUE(fs::exists(rest)) << rest;
    const Cage cage = loadCage(rest.string());
    const Eigen::MatrixXd posed = loadPosedVertices(pose.string(), cage);
    EXPECT_EQ(posed.rows(), cage.numVertices());
    EXPECT_EQ(posed.cols(), 3);
    EXPECT_TRUE(posed.allFinite());
  }
}

TEST(ObjModels, CrlfPoseLoadsLikeAnyOther) {
  SKIP_WITHOUT_MODELS();
  const fs::path pose = fs::path(SOMICAGE_MODELS_DIR) / "horse" / "deformed_bounding_mesh4b.obj";
  ASSERT_NE(readAll(pose).find("\r\n"), std::string::npos) << "models/README.md says this file has CRLF endings";
  const PolygonMesh mesh = loadMesh(pose.string());
  EXPECT_EQ(mesh.numVertices(), 51);
  EXPECT_EQ(mesh.numFaces(), 98);
}

TEST(ObjModels, MeshesLoadWithTheirDocumentedCounts) {
  SKIP_WITHOUT_MODELS();
  struct Expected {
    const char* file;
    int vertices, faces, faceSize;  // faceSize 0: any
  };
  const Expected expected[] = {
      {"firehydrant/fireHydrant.obj", 39028, 76444, 3},
      {"spikybox/SpikyBox.obj", 60802, 60800, 4},
      {"bench/Bench.obj", 65430, 65406, 4},
      {"cactus/cactus.obj", 2052, 3072, 3},
      {"bar/bar.OBJ", 386, 768, 3},
      {"horse/horse.obj", 48485, 96966, 3},
      {"sphere/sphere.obj", 642, 1280, 3},
      {"armadillo/armadilloman.obj", 15002, 30000, 3},
  };
  for (const Expected& e : expected) {
    SCOPED_TRACE(e.file);
    const PolygonMesh mesh = loadMesh((fs::path(SOMICAGE_MODELS_DIR) / e.file).string());
    EXPECT_EQ(mesh.numVertices(), e.vertices);
    EXPECT_EQ(mesh.numFaces(), e.faces);
    EXPECT_TRUE(mesh.vertices.allFinite());
    for (const auto& face : mesh.faces) ASSERT_EQ(static_cast<int>(face.size()), e.faceSize);
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Bad files
// ---------------------------------------------------------------------------------------------------------------

struct Expectation {
  std::string loader;
  long line = -2;
  std::string error;
};

Expectation readExpectation(const fs::path& file) {
  Expectation expectation;
  std::istringstream text(readAll(file));
  std::string line;
  // The files may use CR, LF or CRLF: split on either.
  while (std::getline(text, line, '\n')) {
    std::istringstream parts(line);
    std::string piece;
    while (std::getline(parts, piece, '\r')) {
      const auto value = [&](const std::string& key) { return piece.substr(key.size()); };
      if (piece.rfind("# expect-loader: ", 0) == 0) expectation.loader = value("# expect-loader: ");
      if (piece.rfind("# expect-line: ", 0) == 0) expectation.line = std::stol(value("# expect-line: "));
      if (piece.rfind("# expect-error: ", 0) == 0) expectation.error = value("# expect-error: ");
    }
  }
  return expectation;
}

TEST(ObjBadFiles, NameTheFileTheLineAndTheProblem) {
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(kDataDir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("bad_", 0) != 0 || name == "bad_empty.obj") continue;
    SCOPED_TRACE(name);
    const Expectation expected = readExpectation(entry.path());
    ASSERT_FALSE(expected.error.empty()) << "no '# expect-error:' line";
    ASSERT_NE(expected.line, -2) << "no '# expect-line:' line";
    const std::string path = entry.path().string();
    try {
      if (expected.loader == "mesh") {
        loadMesh(path);
      } else if (expected.loader == "cage") {
        loadCage(path);
      } else {
        FAIL() << "unknown loader '" << expected.loader << "'";
      }
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), path);
      EXPECT_EQ(e.line(), expected.line) << e.what();
      EXPECT_NE(std::string(e.what()).find(expected.error), std::string::npos)
          << "message: " << e.what() << "\nexpected to contain: " << expected.error;
      EXPECT_FALSE(e.hint().empty());
    }
    ++checked;
  }
  EXPECT_GE(checked, 19);
}

TEST(ObjBadFiles, EmptyMissingAndFolder) {
  const std::string empty = (kDataDir / "bad_empty.obj").string();
  try {
    loadMesh(empty);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), empty);
    EXPECT_EQ(e.problem(), "the file is empty");
  }
  const std::string missing = (kDataDir / "no_such_file.obj").string();
  try {
    loadCage(missing);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), missing);
    EXPECT_NE(e.problem().find(std::strerror(ENOENT)), std::string::npos) << e.what();
  }
  try {
    loadMesh(kDataDir.string());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("folder"), std::string::npos) << e.what();
  }
}

TEST(ObjBadFiles, PoseWithAnotherVertexCount) {
  const Cage cube = loadCage((kDataDir / "cube_cage.obj").string());
  try {
    loadPosedVertices((kDataDir / "pyramid_mesh.obj").string(), cube);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("the posed cage has 5 vertices, the rest cage has 8"), std::string::npos) << e.what();
  }
}

TEST(ObjBadFiles, FaceWithMoreThan255Vertices) {
  std::string text;
  for (int i = 0; i < 300; ++i)
    text += "v " + std::to_string(std::cos(i * 0.02)) + " " + std::to_string(std::sin(i * 0.02)) + " 1\n";
  text += "f";
  for (int i = 1; i <= 300; ++i) text += " " + std::to_string(i);
  text += "\n";
  try {
    parseObj(text, "big");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 301);
    EXPECT_NE(e.problem().find("has 300 vertices"), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Reading
// ---------------------------------------------------------------------------------------------------------------

TEST(ObjIo, CrlfGroupsMaterialsAndTextureIndicesDoNotChangeTheMesh) {
  const PolygonMesh plain = loadMesh((kDataDir / "cube_cage.obj").string());
  const PolygonMesh fancy = loadMesh((kDataDir / "cube_crlf_vtvn.obj").string());
  EXPECT_EQ(plain.vertices, fancy.vertices);
  EXPECT_EQ(plain.faces, fancy.faces);
  EXPECT_TRUE(fancy.lines.empty());
}

TEST(ObjIo, ParsesTheForgivingPartsOfTheFormat) {
  const std::string text =
      "\xEF\xBB\xBF# byte order mark, tabs, relative indices, 2-coordinate and 4-coordinate vertices\n"
      "\tv 1 2\n"
      "v  +0.5\t-1.5e-3 2 1\n"
      "v .25 5. -0\n"
      "vn 0 0 1\n"
      "g a\n"
      "l 1 2\n"
      "g b\n"
      "f -3 -2 -1\n"
      "usemtl x\n"
      "l 2 3 1\n"
      "f 1/1 2/2 3/3\n";
  const PolygonMesh mesh = parseObj(text, "inline");
  ASSERT_EQ(mesh.numVertices(), 3);
  EXPECT_EQ(mesh.vertices.row(0), Eigen::RowVector3d(1, 2, 0));
  EXPECT_EQ(mesh.vertices.row(1), Eigen::RowVector3d(0.5, -1.5e-3, 2));
  EXPECT_EQ(mesh.vertices.row(2), Eigen::RowVector3d(0.25, 5, 0));
  EXPECT_TRUE(std::signbit(mesh.vertices(2, 2)));
  EXPECT_EQ(mesh.faces, (std::vector<std::vector<int>>{{0, 1, 2}, {0, 1, 2}}));
  EXPECT_EQ(mesh.lines, (std::vector<std::vector<int>>{{0, 1}, {1, 2, 0}}));
  EXPECT_EQ(mesh.faceSourceLines, (std::vector<long>{9, 12}));
  EXPECT_EQ(mesh.lineSourceLines, (std::vector<long>{7, 11}));
}

TEST(ObjIo, PointSetHasNoFaces) {
  const PolygonMesh points = loadMesh((kDataDir / "square_points.obj").string());
  EXPECT_EQ(points.numVertices(), 5);
  EXPECT_TRUE(points.faces.empty());
  EXPECT_TRUE(points.lines.empty());
}

TEST(ObjIo, QuadCubeTriangulatesKeepingTheWinding) {
  const PolygonMesh quads = loadMesh((kDataDir / "cube_quads.obj").string());
  const Cage cage = loadCage((kDataDir / "cube_quads.obj").string());
  ASSERT_EQ(cage.numFaces(), 12);
  const Eigen::MatrixXd normals = faceNormals(cage, cage.vertices);
  for (int t = 0; t < 12; ++t) {
    // Triangles 2q and 2q+1 come from quad q; all four corners of a cube face share the outward normal.
    const auto& quad = quads.faces[t / 2];
    const Eigen::Vector3d a = quads.vertices.row(quad[0]), b = quads.vertices.row(quad[1]),
                          c = quads.vertices.row(quad[2]);
    EXPECT_NEAR((normals.row(t).transpose() - (b - a).cross(c - a).normalized()).norm(), 0.0, 1e-15) << t;
  }
  expectClosedManifoldOutward(cage);
}

TEST(ObjIo, EarClippingHandlesConcaveTiltedPolygons) {
  // A star with 5 spikes in a tilted plane: fan triangulation from vertex 0 would leave the polygon.
  const int spikes = 5, n = 2 * spikes;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  Eigen::MatrixXd V(n, 3);
  std::vector<int> polygon;
  double area = 0.0;
  for (int k = 0; k < n; ++k) {
    const double r = k % 2 ? 0.4 : 1.0, angle = 2 * M_PI * k / n;
    V.row(k) = (R * Eigen::Vector3d(r * std::cos(angle), r * std::sin(angle), 0.3)).transpose();
    polygon.push_back(k);
  }
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d a = R.transpose() * V.row(k).transpose(), b = R.transpose() * V.row((k + 1) % n).transpose();
    area += 0.5 * (a.x() * b.y() - a.y() * b.x());
  }
  const Eigen::MatrixXi T = triangulatePolygons(V, {polygon});
  ASSERT_EQ(T.rows(), n - 2);
  const Eigen::Vector3d normal = R.col(2);
  double sum = 0.0;
  for (int t = 0; t < T.rows(); ++t) {
    const Eigen::Vector3d a = V.row(T(t, 0)), b = V.row(T(t, 1)), c = V.row(T(t, 2));
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    EXPECT_GT(cross.dot(normal), 0.0) << "triangle " << t << " is flipped or degenerate";
    sum += 0.5 * cross.norm();
  }
  EXPECT_NEAR(sum, area, 1e-12) << "triangles overlap or leave the polygon";
}

TEST(ObjIo, PolygonCagesIn2D) {
  const Cage square = loadCage((kDataDir / "square_polygon.obj").string());
  ASSERT_EQ(square.dim(), 2);
  EXPECT_EQ(square.numVertices(), 4);
  EXPECT_EQ(square.faces, makePolygonCage(square.vertices).faces);
  EXPECT_TRUE(validateCage(square).valid());

  const Cage lShape = loadCage((kDataDir / "l_shape_loop.obj").string());
  ASSERT_EQ(lShape.dim(), 2);
  EXPECT_EQ(lShape.numFaces(), 6);
  EXPECT_TRUE(validateCage(lShape).valid());
  EXPECT_DOUBLE_EQ(validateCage(lShape).signedVolume, 3.0);

  // The same square as one face, as chained segments, and as a loop in another order than the vertices.
  const std::string vertices = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n";
  EXPECT_EQ(cageFromMesh(parseObj(vertices + "f 1 2 3 4\n", "face"), "face").faces, square.faces);
  EXPECT_EQ(cageFromMesh(parseObj(vertices + "l 1 2\nl 2 3 4\nl 4 1\n", "chain"), "chain").faces, square.faces);
  const std::string shuffled = "v -1 -1 0\nv 1 1 0\nv 1 -1 0\nv -1 1 0\nl 1 3 2 4 1\n";
  const Cage permuted = cageFromMesh(parseObj(shuffled, "permuted"), "permuted");
  EXPECT_EQ(permuted.vertices.row(1), Eigen::RowVector2d(1, 1)) << "vertex order must follow the file";
  EXPECT_EQ(permuted.faces.row(0), Eigen::RowVector2i(0, 2));
  EXPECT_TRUE(validateCage(permuted).valid());
}

// ---------------------------------------------------------------------------------------------------------------
// Writing
// ---------------------------------------------------------------------------------------------------------------

TEST(ObjIo, SaveThenLoadIsBitExact) {
  std::mt19937_64 random(12345);
  std::uniform_int_distribution<uint64_t> bits;
  Eigen::MatrixXd V(64, 3);
  for (int i = 0; i < V.rows(); ++i) {
    for (int k = 0; k < 3; ++k) {
      double x;
      do {
        const uint64_t b = bits(random);
        std::memcpy(&x, &b, sizeof x);
      } while (!std::isfinite(x));
      V(i, k) = x;  // every finite double is fair: subnormals, huge and tiny exponents, -0
    }
  }
  V.row(0) << 0.1, -0.0, 1.0 / 3.0;
  V.row(1) << 4.9406564584124654e-324, -1.7976931348623157e308, 2.2250738585072014e-308;
  PolygonMesh topology;
  topology.faces = {{0, 1, 2}, {3, 4, 5, 6}, {63, 7, 8, 9, 10}};
  topology.lines = {{11, 12}, {13, 14, 15, 13}};

  TempDir dir;
  const std::string path = (dir.path() / "round trip.obj").string();
  saveObj(path, V, topology);
  const PolygonMesh back = loadMesh(path);
  ASSERT_EQ(back.vertices.rows(), V.rows());
  EXPECT_EQ(std::memcmp(back.vertices.data(), V.data(), sizeof(double) * V.size()), 0) << "not bit-exact";
  EXPECT_EQ(back.faces, topology.faces);
  EXPECT_EQ(back.lines, topology.lines);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"round trip.obj"}) << "a temporary file was left";

  // A 2D array is written with z = 0 and a 2D cage survives the trip through cageTopology.
  const Cage lShape = loadCage((kDataDir / "l_shape_loop.obj").string());
  saveObj(path, lShape.vertices, cageTopology(lShape));
  const Cage lBack = loadCage(path);
  EXPECT_EQ(lBack.vertices, lShape.vertices);
  EXPECT_EQ(lBack.faces, lShape.faces);
  const Cage cube = loadCage((kDataDir / "cube_quads.obj").string());
  saveObj(path, cube.vertices, cageTopology(cube));
  EXPECT_EQ(loadCage(path).faces, cube.faces);
}

TEST(ObjIo, SaveRefusesBadDataAndKeepsTheOldFile) {
  TempDir dir;
  const std::string path = (dir.path() / "out.obj").string();
  const PolygonMesh cube = loadMesh((kDataDir / "cube_cage.obj").string());
  saveObj(path, cube.vertices, cube);
  const std::string before = readAll(path);

  Eigen::MatrixXd bad = cube.vertices;
  bad(3, 1) = std::nan("");
  EXPECT_THROW(saveObj(path, bad, cube), InputError);
  PolygonMesh wrong = cube;
  wrong.faces[2][1] = 8;
  EXPECT_THROW(saveObj(path, cube.vertices, wrong), InputError);
  EXPECT_EQ(readAll(path), before);

  // The target is a folder: the rename fails, the temporary file goes away.
  fs::create_directory(dir.path() / "folder");
  std::ofstream(dir.path() / "folder" / "keep.txt") << "keep";
  try {
    saveObj((dir.path() / "folder").string(), cube.vertices, cube);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(e.problem().find("cannot replace the file"), std::string::npos) << e.what();
  }
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"folder", "out.obj"}));
  EXPECT_EQ(readAll(path), before);
}

TEST(ObjIo, AtomicWriteKeepsTheOldFileWhenTheFolderIsNotWritable) {
  TempDir dir;
  const std::string path = (dir.path() / "out.obj").string();
  const PolygonMesh cube = loadMesh((kDataDir / "cube_cage.obj").string());
  saveObj(path, cube.vertices, cube);
  const std::string before = readAll(path);
  Eigen::MatrixXd moved = cube.vertices * 2.0;
  ASSERT_EQ(::chmod(dir.path().c_str(), 0555), 0);

  // Root ignores folder permissions: try the write from a child process that gave up root.
  const bool root = ::geteuid() == 0;
  std::string message;
  if (!root) {
    try {
      saveObj(path, moved, cube);
    } catch (const InputError& e) {
      message = e.what();
    }
  } else {
    int pipeFds[2];
    ASSERT_EQ(::pipe(pipeFds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::close(pipeFds[0]);
      if (::setgid(65534) != 0 || ::setuid(65534) != 0) ::_exit(3);
      std::string result = "saved";
      try {
        saveObj(path, moved, cube);
      } catch (const InputError& e) {
        result = e.what();
      } catch (...) {
        result = "unexpected exception";
      }
      const ssize_t written = ::write(pipeFds[1], result.data(), result.size());
      ::_exit(written == static_cast<ssize_t>(result.size()) ? 0 : 4);
    }
    ::close(pipeFds[1]);
    char buffer[4096];
    ssize_t n;
    while ((n = ::read(pipeFds[0], buffer, sizeof buffer)) > 0) message.append(buffer, static_cast<size_t>(n));
    ::close(pipeFds[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 3) GTEST_SKIP() << "cannot drop root to test permissions";
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "child failed";
  }
  EXPECT_NE(message.find(std::strerror(EACCES)), std::string::npos) << "message: " << message;
  EXPECT_NE(message.find(path), std::string::npos) << "message: " << message;
  EXPECT_EQ(readAll(path), before);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.obj"});
}

}  // namespace
}  // namespace somicage
