// somicage animate and the lossless somicage deform, run as processes. A GLB written by `animate` is read back by
// this test's own GLB reader: one frame per timeline frame, and at every key the positions equal `somicage deform`
// of that key's pose (and parameters) to float precision; the OBJ sequence equals it to 1e-12 and keeps the
// mesh's records. Failures leave nothing behind. Morph targets are named by session frame; --out is a .glb or a
// folder, anything else refused before any work; the folder gets the user's umask. With Debian's blender installed, a
// headless import of the GLB sees the same frame count, and a textured OBJ deformed to GLB imports with its materials'
// colours, its texture's pixels and the OBJ's UVs on every corner (skipped without blender).
#include <stb_image_write.h>
#include <sys/stat.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>

#include "cli_test_support.h"
#include "io/obj_io.h"

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

// Rows with 17 significant digits: the session holds exactly the numbers the posed files of `deform` hold.
std::string exactRowsJson(const Eigen::MatrixXd& m) {
  std::string out = "[";
  char number[32];
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    out += i ? ", [" : "[";
    for (Eigen::Index c = 0; c < m.cols(); ++c) {
      std::snprintf(number, sizeof number, "%.17g", m(i, c));
      out += (c ? ", " : "") + std::string(number);
    }
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
                 exactRowsJson(poses[static_cast<size_t>(k)]) + "}";
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

// The GLB's morph targets are named by the session frame they hold: with --frames 4:12 the base mesh is frame 4 and
// the targets frame_5 ... frame_12, and the one named frame_6 (key 1's frame) is that key's `somicage deform`.
TEST_F(Animate, GlbMorphTargetsAreNamedBySessionFrame) {
  const std::string glbPath = dir.file("anim.glb");
  const RunResult r = runSomicage({"animate", "--session", sessionPath, "--out", glbPath, "--frames", "4:12"});
  ASSERT_EQ(r.exitCode, 0) << r;
  const Glb glb(readFile(glbPath));
  const Json& mesh = glb.json["meshes"].array.at(0);
  const std::vector<Json>& names = mesh["extras"]["targetNames"].array;
  ASSERT_EQ(names.size(), 8u);
  for (size_t t = 0; t < names.size(); ++t) EXPECT_EQ(names[t].string, "frame_" + std::to_string(5 + t));
  const Json& primitive = mesh["primitives"].array.at(0);
  const Eigen::MatrixXd base = glb.floats(static_cast<int>(primitive["attributes"]["POSITION"].number));
  for (size_t t = 0; t < names.size(); ++t) {
    if (names[t].string != "frame_6") continue;
    const Eigen::MatrixXd frame6 =
        base + glb.floats(static_cast<int>(primitive["targets"].array.at(t)["POSITION"].number));
    EXPECT_LE((frame6 - deformKey(1)).cwiseAbs().maxCoeff(), 1e-6) << "float32 positions";
  }
}

// --out is one .glb or a folder (a trailing '/', or no extension); anything else is refused with exit 2 before any
// work: the session here names a mesh that does not exist, and the message is about --out, not the mesh.
TEST_F(Animate, OutMustBeAGlbOrAFolder) {
  std::string session = readFile(sessionPath);
  session.replace(session.find("pyramid_mesh.obj"), 16, "absent_mesh.obj");
  std::ofstream(dir.file("absent.json")) << session;
  for (const std::string out : {"a.obj", "frames.d", "anim.gltf"}) {
    const RunResult r = runSomicage({"animate", "--session", dir.file("absent.json"), "--out", dir.file(out)});
    EXPECT_EQ(r.exitCode, 2) << r;
    EXPECT_NE(r.err.find(dir.file(out) + ": is neither a .glb file nor a folder"), std::string::npos) << r;
    EXPECT_FALSE(fs::exists(dir.file(out)));
  }
  const RunResult folder =
      runSomicage({"animate", "--session", sessionPath, "--out", dir.file("frames"), "--frames", "0:1"});
  ASSERT_EQ(folder.exitCode, 0) << folder;
  EXPECT_TRUE(fs::exists(dir.file("frames/pyramid_mesh_0001.obj")));
}

// The sequence's folder is made as mkdir makes one, with the user's umask (not mkdtemp's 0700).
TEST_F(Animate, SequenceFolderFollowsTheUmask) {
  for (const mode_t mask : {mode_t{022}, mode_t{027}}) {
    const std::string out = dir.file("seq" + std::to_string(mask));
    const mode_t previous = ::umask(mask);
    const RunResult r = runSomicage({"animate", "--session", sessionPath, "--out", out + "/", "--frames", "0:1"});
    ::umask(previous);
    ASSERT_EQ(r.exitCode, 0) << r;
    const fs::perms expected = fs::perms::all & ~static_cast<fs::perms>(mask);
    EXPECT_EQ(fs::status(out).permissions() & fs::perms::all, expected) << "umask " << std::oct << mask;
  }
}

bool haveBlender() { return std::system("command -v blender > /dev/null 2>&1") == 0; }

// Runs a Python script in headless Blender on a GLB; the script writes its findings to a text file, returned.
std::string runBlender(const ScratchDir& dir, const std::string& body, const std::string& glbPath) {
  const std::string script = dir.file("blender.py"), result = dir.file("blender.txt");
  // Debian's blender 3.4 importer still uses numpy.bool, which numpy 1.24 removed: the alias is restored first.
  std::ofstream(script) << "import bpy, sys, numpy\n"
                           "if not hasattr(numpy, 'bool'): numpy.bool = bool\n"
                           "glb, out = sys.argv[sys.argv.index('--') + 1:]\n"
                           "bpy.ops.import_scene.gltf(filepath=glb)\n"
                           "mesh = [o for o in bpy.context.scene.objects if o.type == 'MESH'][0]\n"
                        << body;
  const std::string command = "blender -b --factory-startup --python-exit-code 1 --python " + script + " -- " +
                              glbPath + " " + result + " > " + dir.file("blender.log") + " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << readFile(dir.file("blender.log"));
  return readFile(result);
}

TEST_F(Animate, BlenderImportsTheSameFrameCount) {
  if (!haveBlender()) GTEST_SKIP() << "blender is not installed";
  const std::string glbPath = dir.file("anim.glb");
  ASSERT_EQ(runSomicage({"animate", "--session", sessionPath, "--out", glbPath}).exitCode, 0);
  std::istringstream counts(runBlender(
      dir,
      "keys = mesh.data.shape_keys\n"
      "action = keys.animation_data.action\n"
      "frames = sorted({round(p.co[0], 3) for fc in action.fcurves for p in fc.keyframe_points})\n"
      "open(out, 'w').write('%d %d %d' % (len(keys.key_blocks) - 1, len(frames), len(mesh.data.vertices)))\n",
      glbPath));
  int shapeKeys = 0, frames = 0, vertices = 0;
  counts >> shapeKeys >> frames >> vertices;
  EXPECT_EQ(shapeKeys, 12) << "one shape key per frame after the first";
  EXPECT_EQ(frames, 13) << "keyframes at frames 0..12";
  EXPECT_EQ(vertices, 5);
}

// A textured OBJ (two materials, a 2 by 2 PNG) deformed at rest to GLB, imported by Blender: the untextured
// material's base colour is the .mtl's Kd, the textured one's image has the PNG's size and pixels, and every loop's
// UV is the OBJ's `vt` of that corner (found by the corner's position; Blender's glTF import turns y-up into z-up).
TEST(BlenderImport, TexturedGlbKeepsColoursImageAndUvs) {
  if (!haveBlender()) GTEST_SKIP() << "blender is not installed";
  ScratchDir dir;
  const unsigned char pixels[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  ASSERT_NE(stbi_write_png(dir.file("skin.png").c_str(), 2, 2, 4, pixels, 8), 0);
  std::ofstream(dir.file("tri.mtl")) << "newmtl skin\nKd 1 1 1\nmap_Kd skin.png\nnewmtl paint\nKd 0.25 0.5 0.75\n";
  std::ofstream(dir.file("tri.obj")) << "mtllib tri.mtl\nv -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0.25\nv -0.5 0.5 0\n"
                                        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.25 0.75\n"
                                        "usemtl skin\nf 1/1 2/2 3/3\nusemtl paint\nf 1/5 3/3 4/4\n";
  std::vector<std::string> args = cubeDeformArgs(dir.file("tri.glb"));
  args[6] = dir.file("tri.obj");
  const RunResult r = runSomicage(args);
  ASSERT_EQ(r.exitCode, 0) << r;
  std::istringstream found(runBlender(
      dir,
      "lines = []\n"
      "for slot in mesh.material_slots:\n"
      "    nodes = slot.material.node_tree.nodes\n"
      "    bsdf = [n for n in nodes if n.type == 'BSDF_PRINCIPLED'][0]\n"
      "    colour = bsdf.inputs['Base Color']\n"
      "    images = [n.image for n in nodes if n.type == 'TEX_IMAGE']\n"
      "    if images:\n"
      "        image = images[0]\n"
      "        lines.append('image %s %d %d %s' % (slot.material.name, image.size[0], image.size[1],\n"
      "                     ' '.join('%.4f' % p for p in image.pixels[:])))\n"
      "    else:\n"
      "        lines.append('colour %s %s' % (slot.material.name, ' '.join('%.6f' % c for c in "
      "colour.default_value)))\n"
      "uv = mesh.data.uv_layers.active.data\n"
      "for poly in mesh.data.polygons:\n"
      "    for loop in poly.loop_indices:\n"
      "        co = mesh.data.vertices[mesh.data.loops[loop].vertex_index].co\n"
      "        lines.append('loop %s %.6f %.6f %.6f %.6f %.6f' % (mesh.material_slots[poly.material_index].name,\n"
      "                     co[0], co[1], co[2], uv[loop].uv[0], uv[loop].uv[1]))\n"
      "open(out, 'w').write('\\n'.join(lines) + '\\n')\n",
      dir.file("tri.glb")));
  // OBJ corner (x, y, z) -> (material, u, v), and the expected Blender position (x, -z, y).
  const std::map<std::array<double, 3>, std::map<std::string, std::array<double, 2>>> corners = {
      {{-0.5, 0.0, -0.5}, {{"skin", {0, 0}}, {"paint", {0.25, 0.75}}}},
      {{0.5, 0.0, -0.5}, {{"skin", {1, 0}}}},
      {{0.5, -0.25, 0.5}, {{"skin", {1, 1}}, {"paint", {1, 1}}}},
      {{-0.5, 0.0, 0.5}, {{"paint", {0, 1}}}},
  };
  std::string kind, name;
  int loops = 0, images = 0, colours = 0;
  while (found >> kind >> name) {
    if (kind == "colour") {
      ++colours;
      EXPECT_EQ(name, "paint");
      const std::array<double, 4> expected{0.25, 0.5, 0.75, 1.0};
      for (const double e : expected) {
        double c = 0;
        found >> c;
        EXPECT_NEAR(c, e, 1e-6) << "the .mtl's Kd as the base colour";
      }
    } else if (kind == "image") {
      ++images;
      EXPECT_EQ(name, "skin");
      int width = 0, height = 0;
      found >> width >> height;
      ASSERT_EQ(width, 2);
      ASSERT_EQ(height, 2);
      for (int row = 1; row >= 0; --row) {  // Blender's rows run bottom-up
        for (int p = 0; p < 8; ++p) {
          double value = 0;
          found >> value;
          EXPECT_NEAR(value, pixels[row * 8 + p] / 255.0, 1e-4) << "pixel row " << row;
        }
      }
    } else {
      ++loops;
      std::array<double, 3> co{};
      std::array<double, 2> uv{};
      found >> co[0] >> co[1] >> co[2] >> uv[0] >> uv[1];
      const auto corner = corners.find(co);
      ASSERT_NE(corner, corners.end()) << co[0] << " " << co[1] << " " << co[2];
      const auto expected = corner->second.find(name);
      ASSERT_NE(expected, corner->second.end()) << name;
      EXPECT_NEAR(uv[0], expected->second[0], 1e-6);
      EXPECT_NEAR(uv[1], expected->second[1], 1e-6) << "Blender's v = the OBJ's v";
    }
  }
  EXPECT_EQ(colours, 1);
  EXPECT_EQ(images, 1);
  EXPECT_EQ(loops, 6);
}

// The OBJ sequence carries the mesh's normals by J: keyed at a quarter turn of the cube cage about z (which maps the
// cube's vertices onto each other exactly, and which Somigliana coordinates reproduce), the last frame's normals
// are R n / |n| to 1e-9 and the first frame's n / |n|; --recompute-normals gives the faces' normals instead.
TEST(AnimateNormals, ObjSequenceNormalsFollowTheRotation) {
  ScratchDir dir;
  const std::string mesh = dir.file("tet.obj");
  std::ofstream(mesh) << kTetWithNormals;
  const Eigen::MatrixXd rest = loadMesh(dataFile("cube_cage.obj")).vertices;
  Eigen::Matrix3d R;
  R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const std::string session =
      R"({"format": "somicage-session", "version": 2, "mesh": ")" + mesh + R"(", "cage": ")" +
      dataFile("cube_cage.obj") + R"(", "method": "somigliana",
      "params": {"blend": 0, "nu": 0, "gamma": 0, "tractionCorrection": true},
      "poses": [{"name": "rest", "vertices": )" +
      exactRowsJson(rest) + R"(}, {"name": "turned", "vertices": )" + exactRowsJson(rest * R.transpose()) +
      R"(}], "timeline": {"fps": 24, "first": 0, "last": 2, "loop": true, "interpolation": "linear",
      "keys": [{"frame": 0, "pose": "rest"}, {"frame": 2, "pose": "turned"}]}})";
  std::ofstream(dir.file("s.json")) << session;
  const std::vector<Eigen::Vector3d> input = objNormals(mesh);
  RunResult r = runSomicage({"animate", "--session", dir.file("s.json"), "--out", dir.file("seq") + "/"});
  ASSERT_EQ(r.exitCode, 0) << r;
  const std::vector<Eigen::Vector3d> first = objNormals(dir.file("seq/tet_0000.obj"));
  const std::vector<Eigen::Vector3d> last = objNormals(dir.file("seq/tet_0002.obj"));
  ASSERT_EQ(last.size(), 4u);
  for (size_t n = 0; n < 4; ++n) {
    EXPECT_LE((first[n] - input[n].normalized()).norm(), 1e-9) << "vn " << n << " at rest";
    EXPECT_LE((last[n] - R * input[n].normalized()).norm(), 1e-9) << "vn " << n << " turned";
  }
  r = runSomicage({"animate", "--session", dir.file("s.json"), "--out", dir.file("seq2") + "/", "--recompute-normals"});
  ASSERT_EQ(r.exitCode, 0) << r;
  const std::vector<Eigen::Vector3d> recomputed = objNormals(dir.file("seq2/tet_0002.obj"));
  EXPECT_GT((recomputed[0] - last[0]).norm(), 0.05) << "the faces' normals, not the file's";
}

// `animate` plays what the editor shows (issue 23): a version-3 session read by the editor's reader
// (core/engine/session.h), its inline cage and every parameter included, gives at every frame `somicage deform` of that
// frame's pose with the session's settings. Keys at frames 0 (rest) and 4 (a twist and a stretch), linear: frame 2 is
// their mean, which this test computes itself. Before, `animate` had its own reader, which opened the empty cage path
// of an inline cage ("unknown mesh format") and dropped "corotational".
class AnimateSettings : public ::testing::Test {
 protected:
  void SetUp() override {
    rest = loadMesh(dataFile("cube_cage.obj")).vertices;
    posed = rest;
    const double turn = 0.5;
    for (Eigen::Index i = 0; i < rest.rows(); ++i) {
      const double a = turn * (rest(i, 2) + 1) / 2;  // the top turns about z, the bottom stays: a twist
      posed(i, 0) = std::cos(a) * rest(i, 0) - std::sin(a) * rest(i, 1);
      posed(i, 1) = std::sin(a) * rest(i, 0) + std::cos(a) * rest(i, 1);
      posed(i, 2) = 1.3 * rest(i, 2);
    }
  }

  // The session, with the cage inline ("cage": "") or as the cube's file, and `extra` fields ("KEY": VALUE, ).
  std::string session(const std::string& method, const std::string& params, bool inlineCage,
                      const std::string& extra = "") {
    const PolygonMesh cage = loadMesh(dataFile("cube_cage.obj"));
    Eigen::MatrixXd faces(static_cast<Eigen::Index>(cage.faces.size()), 3);
    for (size_t f = 0; f < cage.faces.size(); ++f)
      for (int c = 0; c < 3; ++c) faces(static_cast<Eigen::Index>(f), c) = cage.faces[f][static_cast<size_t>(c)];
    std::string text = R"({"format": "somicage-session", "version": 3, "mesh": ")" + dataFile("pyramid_mesh.obj") +
                       R"(", "cage": ")" + (inlineCage ? "" : dataFile("cube_cage.obj")) + "\", ";
    if (inlineCage)
      text += R"("restCage": {"vertices": )" + exactRowsJson(rest) + R"(, "faces": )" + exactRowsJson(faces) + "}, ";
    text += extra + R"("demoDim": 3, "pose": [], "method": ")" + method + R"(", "params": )" + params + R"(,
      "compare": false, "compareMethods": [], "camera": {"target": [0, 0, 0], "distance": 5, "yaw": 0, "pitch": 0},
      "poses": [{"name": "rest", "vertices": )" +
            exactRowsJson(rest) + R"(}, {"name": "twist", "vertices": )" + exactRowsJson(posed) + R"(}],
      "timeline": {"fps": 24, "first": 0, "last": 4, "loop": false, "interpolation": "linear",
                   "keys": [{"frame": 0, "pose": "rest"}, {"frame": 4, "pose": "twist"}]}})";
    const std::string path = dir.file(method + ".json");
    std::ofstream(path) << text;
    return path;
  }

  // `somicage deform` of the pyramid in the cube cage moved to `pose`, with these options.
  Eigen::MatrixXd deform(const Eigen::MatrixXd& pose, const std::vector<std::string>& options) {
    const std::string posedFile = dir.file("posed.obj"), out = dir.file("deformed.obj");
    saveObj(posedFile, pose, loadMesh(dataFile("cube_cage.obj")));
    std::vector<std::string> args = cubeDeformArgs(out, options);
    args[4] = posedFile;
    const RunResult r = runSomicage(args);
    EXPECT_EQ(r.exitCode, 0) << r;
    return loadMesh(out).vertices;
  }

  // Frames 0, 2 and 4 of `animate` equal `deform` of rest, the mean pose and the twist, to 1e-9 of the cage's
  // diameter; and the settings matter: without them the twist deforms 1e-3 diameters or more elsewhere.
  void expectFramesEqualDeform(const std::string& sessionPath, const std::vector<std::string>& options,
                               const std::vector<std::string>& defaults) {
    const std::string out = dir.file("seq" + std::to_string(runs++));
    const RunResult r = runSomicage({"animate", "--session", sessionPath, "--out", out + "/"});
    ASSERT_EQ(r.exitCode, 0) << r;
    const double diameter = std::sqrt(12.0);  // the cube [-1, 1]^3
    const Eigen::MatrixXd mean = 0.5 * rest + 0.5 * posed;
    const std::pair<int, const Eigen::MatrixXd*> frames[] = {{0, &rest}, {2, &mean}, {4, &posed}};
    for (const auto& [frame, pose] : frames) {
      SCOPED_TRACE("frame " + std::to_string(frame));
      const Eigen::MatrixXd animated = loadMesh(out + "/pyramid_mesh_000" + std::to_string(frame) + ".obj").vertices;
      const Eigen::MatrixXd expected = deform(*pose, options);
      ASSERT_EQ(animated.rows(), expected.rows());
      EXPECT_LE((animated - expected).cwiseAbs().maxCoeff(), 1e-9 * diameter);
    }
    const Eigen::MatrixXd last = loadMesh(out + "/pyramid_mesh_0004.obj").vertices;
    EXPECT_GE((last - deform(posed, defaults)).cwiseAbs().maxCoeff(), 1e-3 * diameter) << "the settings are read";
  }

  ScratchDir dir;
  Eigen::MatrixXd rest, posed;
  int runs = 0;
};

TEST_F(AnimateSettings, InlineCageAndBemCorotational) {
  const std::string path =
      session("bem", R"({"blend": 0, "nu": 0.3, "gamma": 0, "tractionCorrection": true, "corotational": true})", true);
  expectFramesEqualDeform(path, {"--method", "bem", "--nu", "0.3", "--corotational"},
                          {"--method", "bem", "--nu", "0.3"});
}

TEST_F(AnimateSettings, SomiglianaLocalWithGamma) {
  const std::string path =
      session("somigliana",
              R"({"blend": 1, "nu": 0.2, "gamma": 0.5, "tractionCorrection": true, "corotational": false})", false);
  expectFramesEqualDeform(path, {"--variant", "local", "--nu", "0.2", "--gamma", "0.5"}, {"--nu", "0.2"});
}

// A Phong session keeps its tetrahedra: "methodOptions" names a MEDIT file next to the session (the cube coned from
// an off-centre point, not the cube's star from its centre that Phong uses by default), and animate deforms as
// `deform --method phong --tets` does.
TEST_F(AnimateSettings, PhongWithTheSessionsTetrahedra) {
  std::string medit = "MeshVersionFormatted 2\nDimension 3\nVertices\n9\n";
  for (Eigen::Index i = 0; i < rest.rows(); ++i)
    medit += std::to_string(rest(i, 0)) + " " + std::to_string(rest(i, 1)) + " " + std::to_string(rest(i, 2)) + " 0\n";
  medit += "0.3 -0.2 0.1 0\nTetrahedra\n12\n";
  for (const std::vector<int>& f : loadMesh(dataFile("cube_cage.obj")).faces)  // outward faces: positive with 9 last
    medit += std::to_string(f[0] + 1) + " " + std::to_string(f[2] + 1) + " " + std::to_string(f[1] + 1) + " 9 0\n";
  medit += "End\n";
  std::ofstream(dir.file("cube.mesh")) << medit;
  const std::string path =
      session("phong", R"({"blend": 0, "nu": 0.3, "gamma": 0, "tractionCorrection": true})", false,
              R"("methodOptions": {"tets": "cube.mesh"}, )");
  expectFramesEqualDeform(path, {"--method", "phong", "--nu", "0.3", "--tets", dir.file("cube.mesh")},
                          {"--method", "phong", "--nu", "0.3"});
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
