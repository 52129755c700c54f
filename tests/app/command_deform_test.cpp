// somicage deform, run as a process: the rest pose reproduces the input (every method and variant, 2D and 3D)
// to 1e-8 of the cage size, a similarity pose moves it by that similarity, and the output keeps the input's
// vertex order and faces.
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "cli_test_support.h"
#include "io/mesh_formats.h"

namespace somicage {
namespace {

using namespace somicage::test;

double maxDistance(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).rowwise().norm().maxCoeff(); }

struct MethodCase {
  const char* name;
  std::vector<std::string> options;
};

const std::vector<MethodCase> kMethods = {
    {"somigliana global", {}},
    {"somigliana local", {"--variant", "local"}},
    {"somigliana blend 0.5, nu 0.3, gamma 1", {"--blend", "0.5", "--nu", "0.3", "--gamma", "1"}},
    {"somigliana nu -inf, no traction fix", {"--nu", "-inf", "--no-traction-fix", "--threads", "1"}},
    {"somigliana nu inf", {"--nu=inf", "--variant=local"}},
    {"green", {"--method", "green"}},
    {"mvc", {"--method", "mvc"}},
    {"bem nu 0.3", {"--method", "bem", "--nu", "0.3"}},
    {"bem nu inf, corotational", {"--method", "bem", "--nu", "inf", "--corotational"}},
};

RunResult deform(const std::string& cage, const std::string& posed, const std::string& mesh, const std::string& out,
                 const std::vector<std::string>& options) {
  std::vector<std::string> args = {"deform", "--cage", cage, "--posed", posed, "--mesh", mesh, "--out", out};
  args.insert(args.end(), options.begin(), options.end());
  return runSomicage(args);
}

// Deforms mesh with every method and checks the result against expected (#V by 3) within tolerance.
void expectEveryMethodGives(const std::string& cage, const std::string& posed, const std::string& mesh,
                            const Eigen::MatrixXd& expected, double tolerance) {
  ScratchDir dir;
  const PolygonMesh input = loadMesh(mesh);
  for (const MethodCase& method : kMethods) {
    SCOPED_TRACE(method.name);
    const std::string out = dir.file("out.obj");
    const RunResult r = deform(cage, posed, mesh, out, method.options);
    ASSERT_EQ(r.exitCode, 0) << r;
    EXPECT_TRUE(r.out.empty()) << r;
    EXPECT_EQ(r.errLines(), 1) << "only the summary line: " << r;
    EXPECT_NE(r.err.find("precompute"), std::string::npos) << r;
    const PolygonMesh output = loadMesh(out);
    EXPECT_EQ(output.faces, input.faces);
    EXPECT_EQ(output.lines, input.lines);
    ASSERT_EQ(output.vertices.rows(), expected.rows());
    EXPECT_LE(maxDistance(output.vertices, expected), tolerance);
  }
}

// A similarity (scale 1.7, a rotation, a translation) applied to the rows of V (#V by dim).
Eigen::MatrixXd similarity(const Eigen::MatrixXd& V, int dim) {
  Eigen::MatrixXd out = V;
  if (dim == 3) {
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
    out.leftCols(3) = ((1.7 * R * V.leftCols(3).transpose()).colwise() + Eigen::Vector3d(0.3, -2, 5)).transpose();
  } else {
    const Eigen::Matrix2d R = Eigen::Rotation2Dd(0.9).toRotationMatrix();
    out.leftCols(2) = ((1.7 * R * V.leftCols(2).transpose()).colwise() + Eigen::Vector2d(0.3, -2)).transpose();
  }
  return out;
}

// The cube_quads cage, the pyramid mesh inside it, and the cage moved by the 3D similarity (dir/posed.obj).
struct CubeSimilarityPose {
  explicit CubeSimilarityPose(const ScratchDir& dir) : posed(dir.file("posed.obj")) {
    saveObj(posed, similarity(rest.vertices, 3), cageTopology(rest));
  }
  std::string cage = dataFile("cube_quads.obj"), mesh = dataFile("pyramid_mesh.obj");
  Cage rest = loadCage(cage);
  std::string posed;
};

TEST(CliDeform, RestPoseReproducesTheMesh3D) {
  const std::string cage = dataFile("cube_cage.obj"), mesh = dataFile("pyramid_mesh.obj");
  const double size = cageDiameter(loadCage(cage).vertices);
  expectEveryMethodGives(cage, cage, mesh, loadMesh(mesh).vertices, 1e-8 * size);
}

TEST(CliDeform, RestPoseReproducesThePoints2D) {
  const std::string square = dataFile("square_polygon.obj"), points = dataFile("square_points.obj");
  expectEveryMethodGives(square, square, points, loadMesh(points).vertices, 1e-8 * 2 * std::sqrt(2.0));

  // A concave polygon written as an `l` loop, and points with z != 0: x, y deform, z is kept.
  ScratchDir dir;
  const std::string lPoints = dir.file("l_points.obj");
  Eigen::MatrixXd P(5, 3);
  P << 0.5, 0.5, 3, 1.5, 0.5, -1, 0.5, 1.5, 0.25, 0.1, 0.1, 0, 1.9, 0.9, 7;
  saveObj(lPoints, P, PolygonMesh{});
  const std::string lShape = dataFile("l_shape_loop.obj");
  expectEveryMethodGives(lShape, lShape, lPoints, P, 1e-8 * 2 * std::sqrt(2.0));
}

TEST(CliDeform, SimilarityPoseMovesTheMeshBySimilarity) {
  ScratchDir dir;
  const CubeSimilarityPose cube(dir);
  const double size = 1.7 * cageDiameter(cube.rest.vertices);
  expectEveryMethodGives(cube.cage, cube.posed, cube.mesh, similarity(loadMesh(cube.mesh).vertices, 3), 1e-8 * size);

  const std::string square = dataFile("square_polygon.obj"), points = dataFile("square_points.obj");
  const Cage rest2d = loadCage(square);
  const std::string posed2d = dir.file("posed2d.obj");
  saveObj(posed2d, similarity(rest2d.vertices, 2), cageTopology(rest2d));
  Eigen::MatrixXd expected = similarity(loadMesh(points).vertices, 2);
  expectEveryMethodGives(square, posed2d, points, expected, 1e-8 * 1.7 * 2 * std::sqrt(2.0));
}

TEST(CliDeform, SharedModelsDeform) {
  if (!fs::is_directory(kModelsDir)) GTEST_SKIP() << "models folder " << kModelsDir << " is absent";
  ScratchDir dir;
  const fs::path sphere = kModelsDir / "sphere";
  const std::string cage = (sphere / "sphere_cages_triangulated.obj").string();
  const std::string posed = (sphere / "sphere_cages_triangulated_deformed.obj").string();
  const std::string mesh = (sphere / "sphere.obj").string();
  const PolygonMesh input = loadMesh(mesh);
  const double size = cageDiameter(loadCage(cage).vertices);

  RunResult r = deform(cage, cage, mesh, dir.file("rest.obj"), {});
  ASSERT_EQ(r.exitCode, 0) << r;
  EXPECT_LE(maxDistance(loadMesh(dir.file("rest.obj")).vertices, input.vertices), 1e-8 * size);

  // The artist's pose, and the same pose moved by a similarity S: Somigliana coordinates are similarity-invariant
  // in every variant and for any gamma (docs/method.md, "Invariants"), so the second output is S of the first, to
  // round-off, on a real model and pose (a deformer that moved points anywhere else would fail here).
  const std::vector<std::string> local = {"--variant", "local", "--nu", "0.4", "--gamma", "0.5"};
  r = deform(cage, posed, mesh, dir.file("posed.obj"), local);
  ASSERT_EQ(r.exitCode, 0) << r;
  const PolygonMesh output = loadMesh(dir.file("posed.obj"));
  EXPECT_EQ(output.faces, input.faces);
  EXPECT_GT(maxDistance(output.vertices, input.vertices), 1e-2 * size) << "the pose should move the mesh";
  const Cage posedCage{loadMesh(posed).vertices, loadCage(cage).faces};
  saveObj(dir.file("moved_pose.obj"), similarity(posedCage.vertices, 3), cageTopology(posedCage));
  r = deform(cage, dir.file("moved_pose.obj"), mesh, dir.file("moved.obj"), local);
  ASSERT_EQ(r.exitCode, 0) << r;
  EXPECT_LE(maxDistance(loadMesh(dir.file("moved.obj")).vertices, similarity(output.vertices, 3)), 1e-8 * 1.7 * size);

  // The boundary element reference is linear elasticity: the displacement is linear in the cage's displacement,
  // so half the pose moves every point half as far (to the solve's round-off).
  r = deform(cage, posed, mesh, dir.file("bem.obj"), {"--method", "bem", "--nu", "0.3"});
  ASSERT_EQ(r.exitCode, 0) << r;
  const PolygonMesh bem = loadMesh(dir.file("bem.obj"));
  EXPECT_GT(maxDistance(bem.vertices, input.vertices), 1e-2 * size) << "the pose should move the mesh";
  const Eigen::MatrixXd rest = loadMesh(cage).vertices;
  saveObj(dir.file("half_pose.obj"), 0.5 * (rest + posedCage.vertices), cageTopology(posedCage));
  r = deform(cage, dir.file("half_pose.obj"), mesh, dir.file("bem_half.obj"), {"--method", "bem", "--nu", "0.3"});
  ASSERT_EQ(r.exitCode, 0) << r;
  EXPECT_LE(maxDistance(loadMesh(dir.file("bem_half.obj")).vertices, 0.5 * (input.vertices + bem.vertices)),
            1e-8 * size);
  r = deform(cage, posed, mesh, dir.file("half.obj"), {"--method", "bem", "--nu", "0.5"});
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("incompressible"), std::string::npos) << r;

  // A quad cage (triangulated on load) at rest.
  const fs::path wire = kModelsDir / "wiresphere";
  const std::string quads = (wire / "WireSphere_Cage.obj").string();
  const std::string wireMesh = (wire / "wireSphere.obj").string();
  r = deform(quads, quads, wireMesh, dir.file("wire.obj"), {"--method", "green"});
  ASSERT_EQ(r.exitCode, 0) << r;
  EXPECT_LE(maxDistance(loadMesh(dir.file("wire.obj")).vertices, loadMesh(wireMesh).vertices),
            1e-8 * cageDiameter(loadCage(quads).vertices));
}

// A cage with reversed faces, or inside out, is repaired with a note on stderr and gives exactly the clean cage's
// result; a self-intersecting cage deforms with a warning.
TEST(CliDeform, RepairedCageGivesTheCleanCagesResult) {
  ScratchDir dir;
  const std::string clean = dataFile("cube_cage.obj"), flipped = dataFile("cube_cage_flipped_faces.obj");
  const std::string mesh = dataFile("pyramid_mesh.obj");
  Cage cube = loadCage(clean);
  Eigen::MatrixXd bent = cube.vertices;
  bent.col(0) *= 1.3;
  bent(7, 2) += 0.4;
  const std::string posed = dir.file("posed.obj");
  saveObj(posed, bent, cageTopology(cube));
  cube.faces = cube.faces.rowwise().reverse().eval();
  const std::string insideOut = dir.file("inside_out.obj");
  saveObj(insideOut, cube.vertices, cageTopology(cube));

  const RunResult expected = deform(clean, posed, mesh, dir.file("clean.obj"), {"--variant", "local"});
  ASSERT_EQ(expected.exitCode, 0) << expected;
  EXPECT_EQ(expected.err.find("note:"), std::string::npos) << expected;
  const std::pair<std::string, std::string> cases[] = {
      {flipped, "flipped 3 faces (1, 4, 7) to match their neighbours' orientation"},
      {insideOut, "the cage's normals pointed inward (signed volume -8): flipped all 12 faces"}};
  for (const auto& [cage, fix] : cases) {
    SCOPED_TRACE(cage);
    const RunResult r = deform(cage, posed, mesh, dir.file("repaired.obj"), {"--variant", "local"});
    ASSERT_EQ(r.exitCode, 0) << r;
    EXPECT_EQ(r.err.rfind("somicage: note: " + cage + ": " + fix + "\n", 0), 0u) << "the first line: " << r;
    EXPECT_EQ(readFile(dir.file("repaired.obj")), readFile(dir.file("clean.obj")));
  }

  const std::string pierced = dataFile("cube_pierced_by_spike.obj");
  const RunResult r = deform(pierced, pierced, mesh, dir.file("pierced.obj"), {});
  ASSERT_EQ(r.exitCode, 0) << r;
  EXPECT_EQ(r.err.rfind("somicage: warning: " + pierced + ": the cage intersects itself: 3 pairs of faces meet", 0), 0u)
      << r;
}

TEST(CliDeform, MeshInOtherUnitsIsReported) {
  ScratchDir dir;
  const std::string cage = dataFile("cube_cage.obj");
  const PolygonMesh pyramid = loadMesh(dataFile("pyramid_mesh.obj"));
  const std::pair<double, std::string> cases[] = {
      {1000.0, "the mesh is 517 times the size of the cage: are the two files in different units"},
      {1e-4, "the mesh is 19335 times smaller than the cage: are the two files in different units"}};
  for (const auto& [scale, message] : cases) {
    SCOPED_TRACE(scale);
    const std::string mesh = dir.file("scaled.obj");
    saveObj(mesh, pyramid.vertices * scale, pyramid);
    const RunResult r = deform(cage, cage, mesh, dir.file("out.obj"), {});
    ASSERT_EQ(r.exitCode, 0) << r;  // a warning, not a refusal: the result is defined (docs/engine.md)
    EXPECT_NE(r.err.find("somicage: warning: the mesh " + mesh + " and the cage " + cage + " do not fit: " + message),
              std::string::npos)
        << r;
  }
  const std::string beside = dir.file("beside.obj");
  saveObj(beside, pyramid.vertices.rowwise() + Eigen::RowVector3d(50, 0, 0), pyramid);
  const RunResult r = deform(cage, cage, beside, dir.file("out.obj"), {});
  ASSERT_EQ(r.exitCode, 0) << r;
  EXPECT_NE(r.err.find("do not overlap: the mesh lies beside the cage"), std::string::npos) << r;

  const RunResult fits = deform(cage, cage, dataFile("pyramid_mesh.obj"), dir.file("out.obj"), {});
  EXPECT_EQ(fits.err.find("warning"), std::string::npos) << fits;
}

TEST(CliDeform, OverwritesTheOutputAndLeavesNoTemporaryFile) {
  ScratchDir dir;
  const std::string cage = dataFile("cube_cage.obj"), mesh = dataFile("pyramid_mesh.obj"), out = dir.file("out.obj");
  {
    std::ofstream old(out);
    old << "old contents\n";
  }
  const RunResult r = deform(cage, cage, mesh, out, {});
  ASSERT_EQ(r.exitCode, 0) << r;
  EXPECT_EQ(loadMesh(out).numVertices(), 5);
  std::vector<std::string> entries;
  for (const auto& entry : fs::directory_iterator(dir.path())) entries.push_back(entry.path().filename().string());
  EXPECT_EQ(entries, std::vector<std::string>{"out.obj"});
}

// An affine pose A of the cube cage under mean value coordinates (which reproduce affine maps): the mesh's own
// normals come out as A^-T n, normalised; with --recompute-normals they are the corner-angle-weighted normals of the
// deformed faces instead (computed here).
TEST(CliDeform, NormalsFollowTheGradientOrAreRecomputed) {
  ScratchDir dir;
  const std::string mesh = dir.file("tet.obj"), posed = dir.file("posed.obj"), out = dir.file("out.obj");
  std::ofstream(mesh) << kTetWithNormals;
  Eigen::Matrix3d A;
  A << 1.2, 0.3, 0, -0.1, 0.9, 0.2, 0.1, 0, 1.4;
  PolygonMesh cage = loadMesh(dataFile("cube_cage.obj"));
  saveObj(posed, cage.vertices * A.transpose(), cage);

  RunResult r = deform(dataFile("cube_cage.obj"), posed, mesh, out, {"--method", "mvc"});
  ASSERT_EQ(r.exitCode, 0) << r;
  const std::vector<Eigen::Vector3d> input = objNormals(mesh), carried = objNormals(out);
  ASSERT_EQ(carried.size(), 4u);
  for (size_t n = 0; n < 4; ++n) {
    const Eigen::Vector3d expected = (A.inverse().transpose() * input[n]).normalized();
    EXPECT_LE((carried[n] - expected).norm(), 1e-9) << "vn " << n;
  }

  r = deform(dataFile("cube_cage.obj"), posed, mesh, out, {"--method", "mvc", "--recompute-normals"});
  ASSERT_EQ(r.exitCode, 0) << r;
  const PolygonMesh deformed = loadMesh(out);
  std::vector<Eigen::Vector3d> sums(4, Eigen::Vector3d::Zero());
  for (const std::vector<int>& face : deformed.faces) {
    for (size_t k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = deformed.vertices.row(face[k]), a = deformed.vertices.row(face[(k + 1) % 3]),
                            b = deformed.vertices.row(face[(k + 2) % 3]);
      const double angle = std::acos((a - p).normalized().dot((b - p).normalized()));
      sums[static_cast<size_t>(face[k])] += angle * (a - p).cross(b - p).normalized();
    }
  }
  const std::vector<Eigen::Vector3d> recomputed = objNormals(out);
  for (size_t n = 0; n < 4; ++n) EXPECT_LE((recomputed[n] - sums[n].normalized()).norm(), 1e-9) << "vn " << n;
  EXPECT_GT((recomputed[0] - carried[0]).norm(), 0.05) << "the two differ on this mesh";
}

// --device: an unknown name lists the devices; cuda either gives the CPU's result (with a device) or, without one
// (this build machine), fails before any precompute with what is missing and what to use, writing nothing.
TEST(CliDeform, DeviceOptionRunsOnTheDeviceOrSaysWhyNot) {
  ScratchDir dir;
  const CubeSimilarityPose pose(dir);
  const std::string &cage = pose.cage, &mesh = pose.mesh, &posed = pose.posed;

  const RunResult unknown = deform(cage, posed, mesh, dir.file("unknown.obj"), {"--device", "tpu"});
  EXPECT_EQ(unknown.exitCode, 2) << unknown;
  EXPECT_NE(unknown.err.find("unknown device 'tpu' (this executable offers cpu"), std::string::npos) << unknown;
  EXPECT_FALSE(fs::exists(dir.file("unknown.obj")));

  const RunResult cpu = deform(cage, posed, mesh, dir.file("cpu.obj"), {"--variant", "local", "--device", "cpu"});
  ASSERT_EQ(cpu.exitCode, 0) << cpu;
  const RunResult cuda = deform(cage, posed, mesh, dir.file("cuda.obj"), {"--variant", "local", "--device", "cuda"});
  if (cuda.exitCode == 0) {
    const double size = 1.7 * cageDiameter(pose.rest.vertices);
    EXPECT_LE(maxDistance(loadMesh(dir.file("cuda.obj")).vertices, loadMesh(dir.file("cpu.obj")).vertices),
              1e-9 * size);
  } else {
    EXPECT_EQ(cuda.exitCode, 2) << cuda;
    EXPECT_NE(cuda.err.find("somicage deform: --device cuda: not usable here: "), std::string::npos) << cuda;
    EXPECT_NE(cuda.err.find("(use --device cpu)"), std::string::npos) << cuda;
    EXPECT_EQ(cuda.err.find("precompute"), std::string::npos) << "refused before the precompute: " << cuda;
    EXPECT_FALSE(fs::exists(dir.file("cuda.obj")));
  }
}

}  // namespace
}  // namespace somicage
