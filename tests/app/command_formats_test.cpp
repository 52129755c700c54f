// Every command reads every mesh format through deform's loader (mesh_formats.h: loadAnyMesh), issue 23: the cube
// cage, a posed cube and a triangulated pyramid written as PLY, OFF, STL and GLB give `check` and `analyze` the
// numbers they give from OBJ, and `cage` and `bench` (slow) two formats each. The coordinates are binary fractions,
// so the float formats hold them exactly. STL (a vertex per face corner) is read with --weld, which joins the
// corners in order of first appearance, so sums may run in another order: every number must agree to 1e-12
// relative; timings are not compared. FBX goes through the same loader but is read in metres from its unit
// (mesh_units_test.cpp), so its numbers are not the OBJ's.
#include <cmath>
#include <cstdio>

#include "cli_test_support.h"
#include "io/mesh_formats.h"

namespace somicage {
namespace {

using namespace somicage::test;

// Timings, thread counts and memory differ from run to run; paths differ by format.
bool variesByRun(const std::string& key) {
  auto endsWith = [&](const std::string& tail) {
    return key.size() >= tail.size() && key.compare(key.size() - tail.size(), tail.size(), tail) == 0;
  };
  return endsWith("_s") || endsWith("_ms") || endsWith("seconds") || endsWith("speedup") || key == "threads" ||
         key == "peak_rss_bytes";
}

void expectSameNumbers(const Json& obj, const Json& other, const std::string& where) {
  ASSERT_EQ(obj.type, other.type) << where;
  switch (obj.type) {
    case Json::Type::Number:
      EXPECT_NEAR(other.number, obj.number, 1e-12 * std::max(1.0, std::abs(obj.number))) << where;
      break;
    case Json::Type::Bool:
      EXPECT_EQ(other.boolean, obj.boolean) << where;
      break;
    case Json::Type::Array:
      ASSERT_EQ(other.array.size(), obj.array.size()) << where;
      for (size_t i = 0; i < obj.array.size(); ++i)
        if (obj.array[i].type != Json::Type::String)
          expectSameNumbers(obj.array[i], other.array[i], where + "[" + std::to_string(i) + "]");
      break;
    case Json::Type::Object:
      for (const auto& [key, value] : obj.object) {
        ASSERT_TRUE(other.has(key)) << where << "." << key;
        if (!variesByRun(key)) expectSameNumbers(value, other[key], where + "." + key);
      }
      EXPECT_EQ(other.object.size(), obj.object.size()) << where;
      break;
    default:  // strings name the files
      break;
  }
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

class CommandFormats : public ::testing::Test {
 protected:
  void SetUp() override {
    const PolygonMesh cube = loadMesh(dataFile("cube_cage.obj"));
    Eigen::MatrixXd posed = cube.vertices;
    posed.col(0) += 0.25 * cube.vertices.col(2);
    posed.col(1) *= 1.25;
    posed.col(2) -= 0.125 * cube.vertices.col(0);
    PolygonMesh pyramid;
    pyramid.vertices.resize(5, 3);
    pyramid.vertices << -0.5, -0.5, -0.5, 0.5, -0.5, -0.5, 0.5, 0.5, -0.5, -0.5, 0.5, -0.5, 0.125, 0.25, 0.625;
    pyramid.faces = {{0, 2, 1}, {0, 3, 2}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    meshes = {
        {"cage", cube.vertices, cube.faces}, {"posed", posed, cube.faces}, {"mesh", pyramid.vertices, pyramid.faces}};
    for (const Mesh& m : meshes) {
      PolygonMesh topology;
      topology.faces = m.faces;
      saveObj(dir.file(m.name + ".obj"), m.vertices, topology);
    }
  }

  struct Mesh {
    std::string name;
    Eigen::MatrixXd vertices;
    std::vector<std::vector<int>> faces;
  };

  // The three meshes as files of the format `ext`, written here (PLY, OFF and STL as text, GLB by the project's
  // writer).
  void write(const std::string& ext) {
    for (const Mesh& m : meshes) {
      const std::string obj = dir.file(m.name + ".obj"), out = dir.file(m.name + "." + ext);
      std::string text;
      if (ext == "ply" || ext == "off") {
        text = ext == "ply"
                   ? "ply\nformat ascii 1.0\nelement vertex " + std::to_string(m.vertices.rows()) +
                         "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                         std::to_string(m.faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n"
                   : "OFF\n" + std::to_string(m.vertices.rows()) + " " + std::to_string(m.faces.size()) + " 0\n";
        for (Eigen::Index v = 0; v < m.vertices.rows(); ++v)
          text += number(m.vertices(v, 0)) + " " + number(m.vertices(v, 1)) + " " + number(m.vertices(v, 2)) + "\n";
        for (const auto& f : m.faces)
          text += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
      } else if (ext == "stl") {
        text = "solid " + m.name + "\n";
        for (const auto& f : m.faces) {
          text += "facet normal 0 0 0\nouter loop\n";
          for (int c = 0; c < 3; ++c) {
            const Eigen::RowVector3d p = m.vertices.row(f[static_cast<size_t>(c)]);
            text += "vertex " + number(p[0]) + " " + number(p[1]) + " " + number(p[2]) + "\n";
          }
          text += "endloop\nendfacet\n";
        }
        text += "endsolid " + m.name + "\n";
      } else if (ext == "glb") {
        const MeshDocument document = loadMeshDocument(obj);
        ASSERT_TRUE(writeMeshDocument(out, document, document.geometry.vertices).empty());
        continue;
      }
      std::ofstream(out) << text;
    }
  }

  // The command's --json with the inputs of format ext (and --weld where given).
  Json run(const std::string& ext, std::vector<std::string> args, bool weld) {
    for (std::string& a : args)
      if (a == "CAGE" || a == "POSED" || a == "MESH")
        a = dir.file((a == "CAGE" ? "cage" : a == "POSED" ? "posed" : "mesh") + std::string(".") + ext);
    args.push_back("--json");
    if (weld) args.push_back("--weld");
    const RunResult r = runSomicage(args);
    EXPECT_EQ(r.exitCode, 0) << ext << ": " << r;
    try {
      return JsonParser::parse(r.out);
    } catch (const std::exception& e) {
      ADD_FAILURE() << ext << ": " << e.what() << "\n" << r.out;
      return Json();
    }
  }

  // The slow commands (cage generation, bench's timings) read two of the formats, so CI stays fast: each format is
  // read by check and analyze anyway, through the same loader.
  void expectEveryFormatAsObj(const std::vector<std::string>& args,
                              const std::vector<std::string>& formats = {"ply", "off", "stl", "glb"}) {
    const Json obj = run("obj", args, false);
    for (const std::string& ext : formats) {
      SCOPED_TRACE(args[0] + " from ." + ext);
      write(ext);
      expectSameNumbers(obj, run(ext, args, ext == "stl"), args[0]);
    }
  }

  ScratchDir dir;
  std::vector<Mesh> meshes;
};

TEST_F(CommandFormats, CheckReadsEveryFormat) { expectEveryFormatAsObj({"check", "--cage", "CAGE", "--mesh", "MESH"}); }

TEST_F(CommandFormats, AnalyzeReadsEveryFormat) {
  expectEveryFormatAsObj({"analyze", "--cage", "CAGE", "--posed", "POSED", "--mesh", "MESH", "--nu", "0.3"});
}

TEST_F(CommandFormats, CageReadsStlAndGlb) {
  expectEveryFormatAsObj({"cage", "--mesh", "MESH", "--out", dir.file("made.obj"), "--faces", "50"}, {"stl", "glb"});
}

TEST_F(CommandFormats, BenchReadsOffAndStl) {
  expectEveryFormatAsObj({"bench", "--cage", "CAGE", "--posed", "POSED", "--mesh", "MESH", "--frames", "1", "--repeat",
                          "1", "--baseline-points", "0"});
}

}  // namespace
}  // namespace somicage
