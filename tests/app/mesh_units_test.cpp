// Meshes and cages from other tools, run through `somicage deform` (issue 22). FBX comes in metres: its
// UnitScaleFactor says how many centimetres one of its units is (FBX's own unit), so a file of the pyramid's
// coordinates in centimetres, or in inches, deforms at rest to the pyramid in metres, with no warning about units;
// an FBX that Blender 3.4 exports with its default settings (1 cm units under a 100x node scale) too. glTF is in
// metres by its specification and reads as written. A cage from STL, FBX or GLB that is open only because the file
// repeats a vertex per face corner is refused with --weld as the remedy, before any self-intersection report.
#include <assimp/scene.h>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <cstdlib>

#include "cli_test_support.h"
#include "io/mesh_formats.h"

namespace somicage {
namespace {

using namespace somicage::test;

// max over a's rows of the distance to the nearest row of b, and the same from b to a: 0 when the point sets agree.
double setDistance(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  double worst = 0;
  for (const auto* pair : {&a, &b}) {
    const Eigen::MatrixXd& from = *pair;
    const Eigen::MatrixXd& to = pair == &a ? b : a;
    for (Eigen::Index i = 0; i < from.rows(); ++i)
      worst = std::max(worst, (to.rowwise() - from.row(i)).rowwise().norm().minCoeff());
  }
  return worst;
}

// The mesh in path (any format assimp reads), written by assimp's exporter as ASCII FBX, with the FBX's
// UnitScaleFactor (assimp writes 1: centimetres) replaced by unitScale when given.
void writeFbx(const std::string& path, const std::string& fbx, const std::string& unitScale = "") {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, 0);
  ASSERT_NE(scene, nullptr) << importer.GetErrorString();
  Assimp::Exporter exporter;
  ASSERT_EQ(exporter.Export(scene, "fbxa", fbx), AI_SUCCESS) << exporter.GetErrorString();
  if (unitScale.empty()) return;
  std::string text = readFile(fbx);
  const std::string property = "\"UnitScaleFactor\", \"double\", \"Number\", \"\", ";
  const size_t at = text.find(property + "1\n");
  ASSERT_NE(at, std::string::npos) << "assimp's FBX writes UnitScaleFactor 1";
  text.replace(at + property.size(), 1, unitScale);
  std::ofstream(fbx, std::ios::binary) << text;
}

// `somicage deform` of mesh in the cube cage at rest; the deformed vertices (the identity, to 1e-12: the mesh as read).
Eigen::MatrixXd readThroughDeform(const ScratchDir& dir, const std::string& mesh, RunResult& run) {
  const std::string out = dir.file("read.obj");
  std::vector<std::string> args = cubeDeformArgs(out);
  args[6] = mesh;
  run = runSomicage(args);
  EXPECT_EQ(run.exitCode, 0) << run;
  return run.exitCode == 0 ? loadMesh(out).vertices : Eigen::MatrixXd();
}

TEST(MeshUnits, FbxIsReadInMetresByItsUnitScaleFactor) {
  ScratchDir dir;
  const Eigen::MatrixXd pyramid = loadMesh(dataFile("pyramid_mesh.obj")).vertices;
  const PolygonMesh topology = loadMesh(dataFile("pyramid_mesh.obj"));
  // centimetres (UnitScaleFactor 1) and inches (2.54 cm): the file holds the pyramid's metres in that unit.
  const std::pair<double, std::string> units[] = {{1.0, ""}, {2.54, "2.54"}};
  for (const auto& [centimetres, factor] : units) {
    SCOPED_TRACE("UnitScaleFactor " + std::to_string(centimetres));
    const std::string source = dir.file("source.obj"), fbx = dir.file("pyramid.fbx");
    saveObj(source, pyramid * (100.0 / centimetres), topology);
    writeFbx(source, fbx, factor);
    RunResult run;
    const Eigen::MatrixXd read = readThroughDeform(dir, fbx, run);
    ASSERT_GT(read.rows(), 0);
    EXPECT_LE(setDistance(read, pyramid), 1e-6) << "float32 coordinates, in metres";
    EXPECT_EQ(run.err.find("warning"), std::string::npos) << run;
  }
}

TEST(MeshUnits, GlbIsReadAsWritten) {
  ScratchDir dir;
  const std::string glb = dir.file("pyramid.glb");
  ASSERT_EQ(runSomicage(cubeDeformArgs(glb)).exitCode, 0);
  RunResult run;
  const Eigen::MatrixXd read = readThroughDeform(dir, glb, run);
  EXPECT_LE(setDistance(read, loadMesh(dataFile("pyramid_mesh.obj")).vertices), 1e-6);
}

// Blender 3.4 exports with its defaults (Apply Scalings "All Local", Y up, -Z forward): the FBX holds 1 cm units
// under a 100x scale on the object's node, and Blender's (x, y, z) becomes (x, z, -y).
TEST(MeshUnits, FbxExportedByBlenderWithDefaultSettingsIsInMetres) {
  if (std::system("command -v blender > /dev/null 2>&1") != 0) GTEST_SKIP() << "blender is not installed";
  ScratchDir dir;
  const Eigen::MatrixXd pyramid = loadMesh(dataFile("pyramid_mesh.obj")).vertices;
  std::string vertices;
  for (Eigen::Index i = 0; i < pyramid.rows(); ++i)
    vertices += "(" + std::to_string(pyramid(i, 0)) + ", " + std::to_string(-pyramid(i, 2)) + ", " +
                std::to_string(pyramid(i, 1)) + "), ";
  const std::string fbx = dir.file("blender.fbx");
  std::ofstream(dir.file("export.py"))
      << "import bpy\n"
         "bpy.ops.wm.read_factory_settings(use_empty=True)\n"
         "mesh = bpy.data.meshes.new('pyramid')\n"
         "mesh.from_pydata(["
      << vertices
      << "], [], [(0, 3, 2, 1), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)])\n"
         "bpy.context.scene.collection.objects.link(bpy.data.objects.new('pyramid', mesh))\n"
         "bpy.ops.export_scene.fbx(filepath=r'"
      << fbx << "')\n";
  const std::string command = "blender -b --factory-startup --python-exit-code 1 --python " + dir.file("export.py") +
                              " > " + dir.file("blender.log") + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << readFile(dir.file("blender.log"));
  RunResult run;
  const Eigen::MatrixXd read = readThroughDeform(dir, fbx, run);
  ASSERT_GT(read.rows(), 0);
  EXPECT_LE(setDistance(read, pyramid), 1e-6) << "metres, not 100x";
  EXPECT_EQ(run.err.find("different units"), std::string::npos) << run;
}

// The cube cage as an ASCII STL: 36 vertices, one per face corner.
std::string cubeStl(int faces = 12) {
  const Cage cube = loadCage(dataFile("cube_cage.obj"));
  std::string stl = "solid cube\n";
  for (int f = 0; f < faces; ++f) {
    stl += " facet normal 0 0 0\n  outer loop\n";
    for (int c = 0; c < 3; ++c) {
      const Eigen::RowVector3d v = cube.vertices.row(cube.faces(f, c));
      stl += "   vertex " + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
    }
    stl += "  endloop\n endfacet\n";
  }
  return stl + "endsolid cube\n";
}

RunResult deformWithCage(const ScratchDir& dir, const std::string& cage, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {
      "deform", "--cage", cage, "--posed", cage, "--mesh", dataFile("pyramid_mesh.obj"), "--out", dir.file("out.obj")};
  args.insert(args.end(), extra.begin(), extra.end());
  return runSomicage(args);
}

TEST(WeldHint, AnUnweldedCageFromStlFbxOrGlbIsRefusedWithWeldFirst) {
  ScratchDir dir;
  const std::string stl = dir.file("cage.stl"), fbx = dir.file("cage.fbx"), glb = dir.file("cage.glb");
  std::ofstream(stl) << cubeStl();
  writeFbx(dataFile("cube_cage.obj"), fbx);
  // A GLB with one glTF vertex per (vertex, UV) pair: every corner of the cube gets its own UV.
  std::string uvCube = readFile(dataFile("cube_cage.obj")), faces;
  std::istringstream lines(uvCube);
  std::string line, text;
  int corner = 0;
  while (std::getline(lines, line)) {
    if (line.rfind("f ", 0) != 0) {
      text += line + "\n";
      continue;
    }
    std::istringstream indices(line.substr(2));
    std::string index;
    faces += "f";
    while (indices >> index) {
      text += "vt " + std::to_string(0.01 * corner) + " 0\n";
      faces += " " + index + "/" + std::to_string(++corner);
    }
    faces += "\n";
  }
  std::ofstream(dir.file("uv_cube.obj")) << text << faces;
  std::vector<std::string> toGlb = cubeDeformArgs(glb);
  toGlb[6] = dir.file("uv_cube.obj");
  ASSERT_EQ(runSomicage(toGlb).exitCode, 0);

  for (const std::string& cage : {stl, fbx, glb}) {
    SCOPED_TRACE(cage);
    const RunResult r = deformWithCage(dir, cage);
    EXPECT_EQ(r.exitCode, 2) << r;
    EXPECT_NE(r.err.find(cage + ": the cage is not closed as read"), std::string::npos) << r;
    EXPECT_NE(r.err.find("read it with --weld, which joins vertices at equal positions: welded, the cage is closed"),
              std::string::npos)
        << r;
    EXPECT_EQ(r.err.find("intersects itself"), std::string::npos) << "no report of touching corners: " << r;
    EXPECT_EQ(r.errLines(), 1) << r;
  }
  // Welded, the STL and GLB cages are the cube (the FBX one, in centimetres, is 1/100 of it: a units warning).
  for (const std::string& cage : {stl, glb}) {
    const RunResult r = deformWithCage(dir, cage, {"--weld"});
    EXPECT_EQ(r.exitCode, 0) << r;
    EXPECT_EQ(r.err.find("warning"), std::string::npos) << r;
  }
}

TEST(WeldHint, AnStlCageWithAHoleStillMentionsWeld) {
  ScratchDir dir;
  const std::string stl = dir.file("open.stl");
  std::ofstream(stl) << cubeStl(11);
  const RunResult r = deformWithCage(dir, stl);
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_NE(r.err.find("read it with --weld, which joins vertices at equal positions; welded, 3 edges still have "
                       "only one face: fill those holes"),
            std::string::npos)
      << r;
  const RunResult welded = deformWithCage(dir, stl, {"--weld"});
  EXPECT_EQ(welded.exitCode, 2) << welded;
  EXPECT_NE(welded.err.find("the cage is not closed: 3 edges have only one face"), std::string::npos) << welded;
}

}  // namespace
}  // namespace somicage
