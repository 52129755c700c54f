// The command line as a whole, run as a process: help, unknown commands, and bad input of every kind, which must
// exit 2 with exactly one line on stderr naming the option or file (and line), what is wrong and what to do.
#include "cli_test_support.h"
#include "deform/method.h"
#include "io/mesh_formats.h"

namespace somicage {
namespace {

using namespace somicage::test;

TEST(CliHelp, ListsTheCommands) {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"help"}, {"--help"}, {"-h"}}) {
    const RunResult r = runSomicage(args);
    EXPECT_EQ(r.exitCode, 0) << r;
    for (const char* command : {"deform", "check", "help"}) EXPECT_NE(r.out.find(command), std::string::npos) << r;
    EXPECT_TRUE(r.err.empty()) << r;
  }
}

TEST(CliHelp, ShowsTheOptionsOfACommand) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"help", "deform"}, {"deform", "--help"}, {"deform", "--cage", "x.obj", "-h"}}) {
    const RunResult r = runSomicage(args);
    EXPECT_EQ(r.exitCode, 0) << r;
    for (const char* option : {"--cage", "--posed", "--mesh", "--out", "--method", "--variant", "--blend", "--nu",
                               "--gamma", "--no-traction-fix", "--threads"}) {
      EXPECT_NE(r.out.find(option), std::string::npos) << option << "\n" << r;
    }
  }
  // Every method of the registry has its line, with its display name and description (Blender's tooltips).
  const RunResult deform = runSomicage({"deform", "--help"});
  for (Method m : allMethods()) {
    const std::string line = "  " + std::string(m->name);
    const std::size_t at = deform.out.find(line, deform.out.find("methods (--method):"));
    ASSERT_NE(at, std::string::npos) << m->name << "\n" << deform;
    const std::string text = deform.out.substr(at, deform.out.find('\n', at) - at);
    EXPECT_NE(text.find(std::string(m->displayName) + ": " + m->description), std::string::npos) << text;
  }
  const RunResult check = runSomicage({"check", "--help"});
  EXPECT_EQ(check.exitCode, 0) << check;
  EXPECT_NE(check.out.find("--json"), std::string::npos) << check;
}

struct BadInput {
  const char* name;
  std::vector<std::string> args;
  std::string message;  // a part of the one line on stderr
};

// Runs every case and checks: exit 2, nothing on stdout, one line on stderr containing the message.
void expectBadInput(const std::vector<BadInput>& cases) {
  for (const BadInput& c : cases) {
    SCOPED_TRACE(c.name);
    const RunResult r = runSomicage(c.args);
    EXPECT_EQ(r.exitCode, 2) << r;
    EXPECT_TRUE(r.out.empty()) << r;
    EXPECT_EQ(r.errLines(), 1) << r;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << "expected: " << c.message << "\n" << r;
  }
}

std::vector<std::string> deformArgs(const std::vector<std::string>& extra) {
  return cubeDeformArgs("/tmp/unused.obj", extra);
}

TEST(CliErrors, BadOptionsExitTwoWithOneMessage) {
  expectBadInput({
      {"unknown command", {"defrom"}, "unknown command 'defrom' (did you mean 'deform'?"},
      {"unknown help topic", {"help", "bench-press"}, "bench-press: is not a command"},
      {"unknown option", deformArgs({"--nuu", "0.3"}), "--nuu: unknown option (did you mean --nu?"},
      {"missing value", deformArgs({"--nu"}), "--nu: needs a value (write --nu V"},
      {"value eaten by the next option", deformArgs({"--gamma", "--nu", "0.2"}), "--gamma: needs a value"},
      {"not a number", deformArgs({"--gamma", "abc"}), "--gamma: 'abc' is not a number"},
      {"trailing garbage", deformArgs({"--blend", "0.5x"}), "--blend: '0.5x' is not a number"},
      {"NaN", deformArgs({"--nu", "nan"}), "--nu: 'nan' is not a number"},
      {"nu out of range", deformArgs({"--nu", "0.5"}), "--nu: Poisson ratio"},
      {"nu below -1", deformArgs({"--nu", "-1"}), "--nu: Poisson ratio"},
      {"negative gamma", deformArgs({"--gamma", "-0.1"}), "--gamma: bulging scale"},
      {"blend above 1", deformArgs({"--blend", "1.5"}), "--blend: blend"},
      {"unknown method", deformArgs({"--method", "harmonic"}), "--method: unknown method 'harmonic'"},
      {"unknown variant", deformArgs({"--variant", "sideways"}),
       "--variant: 'sideways' is not a choice (use global, local, affine or stable"},
      {"negative threads", deformArgs({"--threads", "-1"}), "--threads: -1 is out of range"},
      {"fractional threads", deformArgs({"--threads", "2.5"}), "--threads: '2.5' is not a whole number"},
      {"flag with a value", deformArgs({"--no-traction-fix=yes"}), "--no-traction-fix: takes no value"},
      {"option twice", deformArgs({"--nu", "0.1", "--nu", "0.2"}), "--nu: is given twice"},
      {"stray argument", deformArgs({"extra.obj"}), "extra.obj: unexpected argument"},
      {"missing required option", {"deform", "--cage", dataFile("cube_cage.obj")}, "--posed: is missing"},
      {"check without cage", {"check", "--json"}, "--cage: is missing"},
      {"phong at nu = inf", deformArgs({"--method", "phong", "--nu", "inf"}), "--nu: Poisson ratio inf leaves"},
      {"unknown tetrahedral mesh level", deformArgs({"--method", "phong", "--tet-level", "7"}),
       "--tet-level: '7' is not a tetrahedral mesh level"},
  });
}

// --tets: a MEDIT file's problems name its line; a cage vertex out of place names the vertex and the distance.
TEST(CliErrors, BadTetrahedralMeshesNameTheirLine) {
  ScratchDir dir;
  const std::string cage = dataFile("cube_cage.obj"), mesh = dataFile("pyramid_mesh.obj"), out = dir.file("out.obj");
  const Cage cube = loadCage(cage);
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir.file(name)) << text;
    return dir.file(name);
  };
  std::string vertices = "MeshVersionFormatted 2\nDimension 3\nVertices\n9\n";
  for (int i = 0; i < 8; ++i) {
    const double shift = i == 6 ? 0.5 : 0.0;  // vertex 7 (line 11) half a unit off
    vertices += std::to_string(cube.vertices(i, 0) + shift) + " " + std::to_string(cube.vertices(i, 1)) + " " +
                std::to_string(cube.vertices(i, 2)) + " 0\n";
  }
  const std::string moved = write("moved.mesh", vertices + "0 0 0 0\nTetrahedra\n1\n9 1 2 3 0\nEnd\n");
  const std::string badIndex = write("bad.mesh",
                                     "MeshVersionFormatted 2\nDimension 3\nVertices\n1\n0 0 0 0\n"
                                     "Tetrahedra\n1\n1 1 1 2 0\nEnd\n");
  const std::vector<std::string> phong = {"deform", "--cage", cage, "--posed",  cage,    "--mesh",
                                          mesh,     "--out",  out,  "--method", "phong", "--tets"};
  auto with = [&](const std::string& file) {
    std::vector<std::string> args = phong;
    args.push_back(file);
    return args;
  };
  expectBadInput({
      {"index out of range", with(badIndex), badIndex + ":8: index 4 of element 1 2 is outside [1, 1]"},
      {"cage vertex moved", with(moved), moved + ":11: vertex 7 is"},
  });
}

TEST(CliErrors, BadFilesExitTwoWithOneMessage) {
  ScratchDir dir;
  Cage cube = loadCage(dataFile("cube_cage.obj"));
  cube.faces.conservativeResize(11, 3);  // a hole: no repair makes that usable
  const std::string open = dir.file("open.obj");
  saveObj(open, cube.vertices, cageTopology(cube));
  const std::string cage = dataFile("cube_cage.obj"), mesh = dataFile("pyramid_mesh.obj");
  const std::string missing = dir.file("missing.obj");
  const std::string badFace = dataFile("bad_face_out_of_range.obj");
  const std::string out = dir.file("out.obj");
  expectBadInput({
      {"missing cage",
       {"deform", "--cage", missing, "--posed", cage, "--mesh", mesh, "--out", out},
       missing + ": cannot open the file: No such file or directory"},
      {"missing mesh",
       {"deform", "--cage", cage, "--posed", cage, "--mesh", missing, "--out", out},
       missing + ": cannot open the file"},
      {"bad face in the mesh",
       {"deform", "--cage", cage, "--posed", cage, "--mesh", badFace, "--out", out},
       badFace + ":9: face 1 refers to index 9, but the file has 4 vertices"},
      {"NaN in the pose",
       {"deform", "--cage", cage, "--posed", dataFile("bad_nan_coordinate.obj"), "--mesh", mesh, "--out", out},
       "bad_nan_coordinate.obj:5: vertex 1: x = 'nan' is not finite"},
      {"pose with another vertex count",
       {"deform", "--cage", cage, "--posed", mesh, "--mesh", mesh, "--out", out},
       "the posed cage has 5 vertices, the rest cage has 8"},
      {"open cage",
       {"deform", "--cage", open, "--posed", open, "--mesh", mesh, "--out", out},
       open + ": the cage cannot be used: the cage is not closed: 3 edges have only one face"},
      {"open cage in bench",
       {"bench", "--cage", open, "--mesh", mesh},
       open + ": the cage cannot be used: the cage is not closed"},
      {"output folder missing",
       {"deform", "--cage", cage, "--posed", cage, "--mesh", mesh, "--out", dir.file("no/such/folder/out.obj")},
       "cannot create a file in this folder: No such file or directory"},
      {"check: folder as cage", {"check", "--cage", dir.path().string()}, "is a folder, not a file"},
      {"check: empty mesh", {"check", "--cage", cage, "--mesh", dataFile("bad_empty.obj")}, "the file is empty"},
  });
  EXPECT_FALSE(fs::exists(out)) << "nothing may be written on bad input";
}

}  // namespace
}  // namespace somicage
