// somicage animate and the lossless somicage deform, run as processes. A GLB written by `animate` is read back by
// this test's own GLB reader: one frame per timeline frame, and at every key the positions equal `somicage deform`
// of that key's pose (and parameters) to float precision; the OBJ sequence equals it to 1e-12 and keeps the
// mesh's records. Failures leave nothing behind. With Debian's blender installed, a headless import of the GLB
// sees the same frame count (skipped without blender).
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "cli_test_support.h"
#include "obj_io.h"

namespace somicage {
namespace {

using namespace somicage::test;

// ---- a small GLB reader: the JSON chunk and the float accessors ----

struct Glb {
  Json json;
  std::string bin;

  explicit Glb(const std::string& bytes) {
    auto word = [&](size_t at) {
      uint32_t w = 0;
      std::memcpy(&w, bytes.data() + at, 4);
      return w;
    };
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0 || word(4) != 2) throw std::runtime_error("not GLB 2");
    if (word(8) != bytes.size()) throw std::runtime_error("GLB length field differs from the file size");
    const uint32_t jsonLength = word(12);
    if (word(16) != 0x4E4F534Au) throw std::runtime_error("first chunk is not JSON");
    json = JsonParser::parse(bytes.substr(20, jsonLength));
    const size_t binAt = 20 + jsonLength;
    if (bytes.size() >= binAt + 8 && word(binAt + 4) == 0x004E4942u) bin = bytes.substr(binAt + 8, word(binAt));
  }

  // An accessor of floats (SCALAR, VEC2 or VEC3) as rows.
  Eigen::MatrixXd floats(int accessor) const {
    const Json& a = json["accessors"].array.at(static_cast<size_t>(accessor));
    if (a["componentType"].number != 5126) throw std::runtime_error("not a float accessor");
    const std::string& type = a["type"].string;
    const int width = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : 3;
    const Json& view = json["bufferViews"].array.at(static_cast<size_t>(a["bufferView"].number));
    const size_t offset = static_cast<size_t>((view.has("byteOffset") ? view["byteOffset"].number : 0) +
                                              (a.has("byteOffset") ? a["byteOffset"].number : 0));
    const int count = static_cast<int>(a["count"].number);
    Eigen::MatrixXd out(count, width);
    for (int i = 0; i < count; ++i) {
      for (int c = 0; c < width; ++c) {
        float f = 0;
        std::memcpy(&f, bin.data() + offset + 4 * (static_cast<size_t>(i) * width + c), 4);
        out(i, c) = f;
      }
    }
    return out;
  }
};

std::string matrixJson(const Eigen::MatrixXd& m) {
  std::string out = "[";
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    out += i ? ", [" : "[";
    for (Eigen::Index c = 0; c < m.cols(); ++c) out += (c ? ", " : "") + std::to_string(m(i, c));
    out += "]";
  }
  return out + "]";
}

// Three poses of the cube cage keyed at frames 0, 6 and 12 (the middle one with nu 0.3, which the last key holds),
// Catmull-Rom.
class Animate : public ::testing::Test {
 protected:
  void SetUp() override {
    rest = loadMesh(dataFile("cube_cage.obj")).vertices;
    poses = {rest, rest, rest};
    for (Eigen::Index i = 0; i < rest.rows(); ++i) {
      if (rest(i, 2) > 0) poses[1].row(i) += Eigen::RowVector3d(0.3, 0.1, 0.2);
      if (rest(i, 0) > 0) poses[2].row(i) *= 1.2;
    }
    for (int k = 0; k < 3; ++k) {
      // Written as the session holds them (std::to_string: 6 decimals), so the deform reference uses the same numbers.
      poses[static_cast<size_t>(k)] = (poses[static_cast<size_t>(k)] * 1e6).array().round() / 1e6;
    }
    std::string session = R"({"format": "somicage-session", "version": 2, "mesh": ")" + dataFile("pyramid_mesh.obj") +
                          R"(", "cage": ")" + dataFile("cube_cage.obj") +
                          R"(", "method": "somigliana",
      "params": {"blend": 0, "nu": 0, "gamma": 0, "tractionCorrection": true},
      "poses": [)";
    for (int k = 0; k < 3; ++k) {
      session += (k ? ", " : "") + std::string(R"({"name": "p)") + std::to_string(k) + R"(", "vertices": )" +
                 matrixJson(poses[static_cast<size_t>(k)]) + "}";
    }
    session += R"(], "timeline": {"fps": 24, "first": 0, "last": 12, "loop": true, "interpolation": "catmull-rom",
      "keys": [{"frame": 0, "pose": "p0"}, {"frame": 6, "pose": "p1", "nu": 0.3}, {"frame": 12, "pose": "p2"}]}})";
    sessionPath = dir.file("s.json");
    std::ofstream(sessionPath) << session;
  }

  // `somicage deform` of the pyramid with key k's pose (and parameters).
  Eigen::MatrixXd deformKey(int k) {
    const std::string posed = dir.file("key" + std::to_string(k) + ".obj");
    PolygonMesh cage = loadMesh(dataFile("cube_cage.obj"));
    saveObj(posed, poses[static_cast<size_t>(k)], cage);
    const std::string out = dir.file("deformed" + std::to_string(k) + ".obj");
    std::vector<std::string> args = cubeDeformArgs(out);
    args[4] = posed;
    if (k >= 1) args.insert(args.end(), {"--nu", "0.3"});  // key 2 sets no nu: it holds key 1's
    const RunResult r = runSomicage(args);
    EXPECT_EQ(r.exitCode, 0) << r;
    return loadMesh(out).vertices;
  }

  ScratchDir dir;
  Eigen::MatrixXd rest;
  std::vector<Eigen::MatrixXd> poses;
  std::string sessionPath;
};

TEST_F(Animate, GlbHasOneFramePerTimelineFrameAndTheKeysAreDeformPoses) {
  const std::string glbPath = dir.file("anim.glb");
  const RunResult r = runSomicage({"animate", "--session", sessionPath, "--out", glbPath, "--fps", "12"});
  ASSERT_EQ(r.exitCode, 0) << r;
  const Glb glb(readFile(glbPath));
  const Json& animation = glb.json["animations"].array.at(0);
  const Json& sampler = animation["samplers"].array.at(0);
  const Eigen::MatrixXd times = glb.floats(static_cast<int>(sampler["input"].number));
  ASSERT_EQ(times.rows(), 13) << "frames 0..12";
  EXPECT_NEAR(times(12, 0), 1.0, 1e-6) << "12 frames at 12 fps";
  EXPECT_EQ(animation["channels"].array.at(0)["target"]["path"].string, "weights");
  const Json& primitive = glb.json["meshes"].array.at(0)["primitives"].array.at(0);
  const Eigen::MatrixXd base = glb.floats(static_cast<int>(primitive["attributes"]["POSITION"].number));
  ASSERT_EQ(primitive["targets"].array.size(), 12u);
  const Eigen::MatrixXd weights = glb.floats(static_cast<int>(sampler["output"].number));
  ASSERT_EQ(weights.rows(), 13 * 12);
  const auto frame = [&](int f) {
    Eigen::MatrixXd positions = base;
    for (int t = 0; t < 12; ++t) {
      const double w = weights(f * 12 + t, 0);
      if (w != 0)
        positions +=
            w * glb.floats(static_cast<int>(primitive["targets"].array[static_cast<size_t>(t)]["POSITION"].number));
    }
    return positions;
  };
  for (int k = 0; k < 3; ++k) {
    SCOPED_TRACE("key " + std::to_string(k));
    const Eigen::MatrixXd expected = deformKey(k);
    ASSERT_EQ(base.rows(), expected.rows());
    EXPECT_LE((frame(6 * k) - expected).cwiseAbs().maxCoeff(), 1e-6) << "float32 positions";
  }
}

TEST_F(Animate, ObjSequenceKeepsTheMeshAndEqualsDeformAtKeys) {
  const std::string out = dir.file("seq");
  const RunResult r = runSomicage({"animate", "--session", sessionPath, "--out", out + "/", "--frames", "4:12"});
  ASSERT_EQ(r.exitCode, 0) << r;
  int files = 0;
  for (const auto& entry : fs::directory_iterator(out)) files += entry.path().extension() == ".obj";
  EXPECT_EQ(files, 9);
  const PolygonMesh key = loadMesh(out + "/pyramid_mesh_0006.obj");
  EXPECT_LE((key.vertices - deformKey(1)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(key.faces, loadMesh(dataFile("pyramid_mesh.obj")).faces);
  const std::string text = readFile(out + "/pyramid_mesh_0012.obj");
  EXPECT_EQ(text.rfind("# A small mesh inside cube_cage.obj", 0), 0u) << "the comment line is kept";
}

TEST_F(Animate, FailuresLeaveNothingBehind) {
  const std::string occupied = dir.file("occupied");
  fs::create_directories(occupied);
  std::ofstream(occupied + "/keep.txt") << "mine";
  RunResult r = runSomicage({"animate", "--session", sessionPath, "--out", occupied});
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_NE(r.err.find("not an empty folder"), std::string::npos) << r;

  std::string broken = readFile(sessionPath);
  broken.replace(broken.find("\"pose\": \"p2\""), 12, "\"pose\": \"px\"");
  std::ofstream(dir.file("broken.json")) << broken;
  r = runSomicage({"animate", "--session", dir.file("broken.json"), "--out", dir.file("broken.glb")});
  EXPECT_EQ(r.exitCode, 2) << r;
  EXPECT_NE(r.err.find("\"px\""), std::string::npos) << r;
  r = runSomicage({"animate", "--session", sessionPath, "--out", dir.file("x.glb"), "--frames", "9:3"});
  EXPECT_EQ(r.exitCode, 2) << r;
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir.path())) left.push_back(entry.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"broken.json", "occupied", "s.json"}));
  EXPECT_EQ(readFile(occupied + "/keep.txt"), "mine");
}

TEST_F(Animate, BlenderImportsTheSameFrameCount) {
  if (std::system("command -v blender > /dev/null 2>&1") != 0) GTEST_SKIP() << "blender is not installed";
  const std::string glbPath = dir.file("anim.glb");
  ASSERT_EQ(runSomicage({"animate", "--session", sessionPath, "--out", glbPath}).exitCode, 0);
  const std::string script = dir.file("count.py"), result = dir.file("count.txt");
  // Debian's blender 3.4 importer still uses numpy.bool, which numpy 1.24 removed: the alias is restored first.
  std::ofstream(script) << "import bpy, sys, numpy\n"
                           "if not hasattr(numpy, 'bool'): numpy.bool = bool\n"
                           "glb, out = sys.argv[sys.argv.index('--') + 1:]\n"
                           "bpy.ops.import_scene.gltf(filepath=glb)\n"
                           "mesh = [o for o in bpy.context.scene.objects if o.type == 'MESH'][0]\n"
                           "keys = mesh.data.shape_keys\n"
                           "action = keys.animation_data.action\n"
                           "frames = sorted({round(p.co[0], 3) for fc in action.fcurves for p in fc.keyframe_points})\n"
                           "open(out, 'w').write('%d %d %d' % (len(keys.key_blocks) - 1, len(frames), "
                           "len(mesh.data.vertices)))\n";
  const std::string command = "blender -b --factory-startup --python-exit-code 1 --python " + script + " -- " +
                              glbPath + " " + result + " > " + dir.file("blender.log") + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << readFile(dir.file("blender.log"));
  std::istringstream counts(readFile(result));
  int shapeKeys = 0, frames = 0, vertices = 0;
  counts >> shapeKeys >> frames >> vertices;
  EXPECT_EQ(shapeKeys, 12) << "one shape key per frame after the first";
  EXPECT_EQ(frames, 13) << "keyframes at frames 0..12";
  EXPECT_EQ(vertices, 5);
}

TEST(DeformLossless, TexturedObjAtRestKeepsEveryRecord) {
  ScratchDir dir;
  const std::string mesh = dir.file("tri.obj"), out = dir.file("out.obj");
  const std::string text =
      "mtllib tri.mtl\no Tri\ng body\nv 0 0 0\nv 0.5 0 0\nv 0 0.5 0.2\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
      "usemtl skin\ns 1\nf 1/1/1 2/2/1 3/3/1\n";
  std::ofstream(mesh) << text;
  std::ofstream(dir.file("tri.mtl")) << "newmtl skin\nKd 0.8 0.5 0.4\n";
  for (const char* method : {"somigliana", "green", "mvc"}) {
    SCOPED_TRACE(method);
    std::vector<std::string> args = cubeDeformArgs(out, {"--method", method});
    args[6] = mesh;
    const RunResult r = runSomicage(args);
    ASSERT_EQ(r.exitCode, 0) << r;
    const std::string written = readFile(out);
    std::istringstream a(text), b(written);
    std::string lineA, lineB;
    while (std::getline(a, lineA)) {
      ASSERT_TRUE(std::getline(b, lineB));
      if (lineA.rfind("v ", 0) != 0 && lineA.rfind("vn ", 0) != 0) {
        EXPECT_EQ(lineB, lineA);
      }
    }
    EXPECT_FALSE(std::getline(b, lineB)) << "no extra lines";
    EXPECT_EQ(written.back(), '\n');
    EXPECT_LE((loadMesh(out).vertices - loadMesh(mesh).vertices).cwiseAbs().maxCoeff(), 1e-12);
  }
}

}  // namespace
}  // namespace somicage
