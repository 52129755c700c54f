// Session JSON: exact round trip (numbers written as their shortest exact text), infinities, the inline cage of a cage
// without a file, and errors that name the problem.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>

#include "base/errors.h"
#include "base/json.h"
#include "core/test_shapes.h"
#include "engine/session.h"
#include "methods/method_descriptors.h"

using namespace somicage;

namespace {
Session sample() {
  Session s;
  s.meshPath = "/models/a \"quoted\" mesh.obj";
  s.cagePath = "/models/cage.obj";
  s.pose.resize(3, 3);
  s.pose << 0.1, 0.2, 0.3, 1.0 / 3.0, -2.5e-7, 1e8, 4, 5, 6;
  s.method = methods::green();
  s.params.nu = -std::numeric_limits<double>::infinity();
  s.params.gamma = 2.25;
  s.params.blend = 0.125;
  s.params.tractionCorrection = false;
  s.params.corotational = true;
  s.compare = true;
  s.compareViews = viewsOf({methods::somigliana(), methods::bem(), methods::mvc()});
  s.camera.target = Eigen::Vector3d(0.1, -0.2, 0.3);
  s.camera.distance = 7.5;
  s.camera.yaw = -1.25;
  s.camera.pitch = 0.5;
  return s;
}

// A session whose cage has no file: an icosahedron with coordinates that need all 17 digits, posed.
Session inlineCageSample() {
  Session s = sample();
  s.cagePath.clear();
  s.restCage = test::makeIcosphere(0);
  s.restCage.vertices *= 1.0 / 3.0;
  s.restCage.vertices.col(0).array() += 1e-9;
  s.pose = s.restCage.vertices;
  s.pose(0, 0) += 0.1;
  return s;
}

// The message of the InputError that reading `text` as s.json throws ("accepted" when it reads).
std::string rejection(const std::string& text) {
  try {
    sessionFromJson(text, "s.json");
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "s.json");
    return e.what();
  }
  return "accepted";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}
}  // namespace

TEST(EditorSession, RoundTripIsExact) {
  const Session a = sample();
  const Session b = sessionFromJson(sessionToJson(a), "test");
  EXPECT_EQ(b.meshPath, a.meshPath);
  EXPECT_EQ(b.cagePath, a.cagePath);
  EXPECT_EQ(b.pose, a.pose);
  EXPECT_EQ(b.method, a.method);
  EXPECT_TRUE(std::isinf(b.params.nu) && b.params.nu < 0);
  EXPECT_EQ(b.params.gamma, a.params.gamma);
  EXPECT_EQ(b.params.blend, a.params.blend);
  EXPECT_EQ(b.params.tractionCorrection, a.params.tractionCorrection);
  EXPECT_EQ(b.params.corotational, a.params.corotational);
  EXPECT_EQ(b.compare, a.compare);
  EXPECT_TRUE(b.compareViews == a.compareViews);
  EXPECT_EQ(b.camera.target, a.camera.target);
  EXPECT_EQ(b.camera.distance, a.camera.distance);
  EXPECT_EQ(b.camera.yaw, a.camera.yaw);
  EXPECT_EQ(b.camera.pitch, a.camera.pitch);
}

TEST(EditorSession, DemoSessionWithoutPoseRoundTrips) {
  Session a;
  a.demoDim = 2;
  const Session b = sessionFromJson(sessionToJson(a), "test");
  EXPECT_TRUE(b.meshPath.empty());
  EXPECT_EQ(b.demoDim, 2);
  EXPECT_EQ(b.pose.rows(), 0);
}

TEST(EditorSession, FileRoundTripIsAtomic) {
  const std::string path = ::testing::TempDir() + "somicage_session_test.json";
  saveSession(path, sample());
  EXPECT_EQ(loadSession(path).pose, sample().pose);
  std::remove(path.c_str());
}

TEST(EditorSession, SyntaxErrorsNameTheLine) {
  try {
    sessionFromJson("{\n  \"format\": \"somicage-session\",\n  \"version\" 1\n}", "broken.json");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "broken.json");
    EXPECT_EQ(e.line(), 3);
  }
}

TEST(EditorSession, BadFieldsAreRejectedWithTheirName) {
  std::string text = sessionToJson(sample());
  const std::string good = "\"method\": \"green\"";
  ASSERT_NE(text.find(good), std::string::npos);
  text.replace(text.find(good), good.size(), "\"method\": \"bogus\"");
  try {
    sessionFromJson(text, "s.json");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bogus"), std::string::npos);
  }
  EXPECT_THROW(sessionFromJson("{\"format\": \"other\"}", "s.json"), InputError);
  EXPECT_THROW(sessionFromJson("[1, 2]", "s.json"), InputError);
}

TEST(EditorJson, StringsWithEscapesRoundTrip) {
  JsonValue v = JsonValue::object();
  v.set("s", JsonValue::string("tab\there \"q\" back\\slash\nnew\x01"));
  const JsonValue w = parseJson(v.dump(2), "t");
  EXPECT_EQ(w.find("s")->asString(), v.find("s")->asString());
  EXPECT_EQ(parseJson("\"\\u00e9\"", "t").asString(), "\xc3\xa9");
}

// Found by tests/fuzz/fuzz_session_loader (inputs in tests/fuzz/corpus/session/regress_*.json): a huge or NaN
// demoDim was cast to int (undefined behaviour), and strtod let nan, inf, 1e999 and hexadecimal through as numbers.
TEST(EditorSession, NonFiniteNumbersAreRejectedWithTheirField) {
  const std::string good = sessionToJson(sample());
  const auto rejects = [&](const std::string& from, const std::string& to, const std::string& expected) {
    std::string text = good;
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
    try {
      sessionFromJson(text, "s.json");
      ADD_FAILURE() << "accepted " << to;
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "s.json");
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  rejects("\"demoDim\": 3", "\"demoDim\": 1e300", "\"demoDim\" must be 2 or 3");
  rejects("\"demoDim\": 3", "\"demoDim\": -nan", "malformed number");
  rejects("\"demoDim\": 3", "\"demoDim\": -inf", "malformed number");
  rejects("\"demoDim\": 3", "\"demoDim\": 0x3", "malformed number");
  rejects("\"yaw\": -1.25", "\"yaw\": \"inf\"", "field \"yaw\" must be a number");
  rejects("[0.1, 0.2, 0.3]", "[1e999, 0.2, 0.3]", "number out of range");
  rejects("\"mesh\": \"", "\"mesh\": \"\\u00zz", "4 hexadecimal digits");
  // nu alone may be infinite.
  EXPECT_EQ(sessionFromJson(good, "s.json").params.nu, -std::numeric_limits<double>::infinity());
}

TEST(EditorSession, AnotherVersionOrFormatIsRefusedWithWhatThisBuildReads) {
  const std::string good = sessionToJson(sample());
  const auto messageFor = [](const std::string& text) {
    try {
      sessionFromJson(text, "s.json");
    } catch (const InputError& e) {
      EXPECT_EQ(e.source(), "s.json");
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  std::string newer = good;
  ASSERT_NE(newer.find("\"version\": 3"), std::string::npos);
  newer.replace(newer.find("\"version\": 3"), 12, "\"version\": 4");
  EXPECT_NE(messageFor(newer).find("unsupported session version (this build reads versions 1 to 3)"), std::string::npos)
      << messageFor(newer);
  std::string other = good;
  other.replace(other.find("somicage-session"), 16, "somicage-recent!");
  EXPECT_NE(messageFor(other).find("not a SomiCage session"), std::string::npos) << messageFor(other);
  // Truncated (a crash mid-write of a non-atomic copy): a syntax error with the line, not a crash.
  const std::string truncated = good.substr(0, good.size() / 2);
  EXPECT_NE(messageFor(truncated).find("s.json:"), std::string::npos) << messageFor(truncated);
  EXPECT_NE(messageFor("").find("s.json"), std::string::npos) << messageFor("");
}

TEST(EditorSession, AnInlineCageRoundTripsBitwise) {
  const Session a = inlineCageSample();
  const std::string text = sessionToJson(a);
  EXPECT_NE(text.find("\"restCage\""), std::string::npos);
  const Session b = sessionFromJson(text, "test");
  EXPECT_TRUE(b.cagePath.empty());
  ASSERT_EQ(b.restCage.vertices.rows(), a.restCage.vertices.rows());
  ASSERT_EQ(b.restCage.faces.rows(), a.restCage.faces.rows());
  EXPECT_EQ(b.restCage.vertices, a.restCage.vertices);
  EXPECT_EQ(b.restCage.faces, a.restCage.faces);
  EXPECT_EQ(b.pose, a.pose);
  EXPECT_TRUE(b.cageNotices.empty()) << b.cageNotices.front().text;
  // A cage with a file is named, not copied.
  EXPECT_EQ(sessionToJson(sample()).find("restCage"), std::string::npos);
}

// Versions 1 and 2 have no inline cage: they still load, as before (a cage-less mesh gets the default cage).
TEST(EditorSession, VersionTwoStillLoads) {
  const std::string v2 = replaced(sessionToJson(sample()), "\"version\": 3", "\"version\": 2");
  const Session b = sessionFromJson(v2, "old.json");
  EXPECT_EQ(b.cagePath, sample().cagePath);
  EXPECT_EQ(b.restCage.numVertices(), 0);
  EXPECT_EQ(b.pose, sample().pose);
}

// An older session's compare list that is not a compare view of 2 to 3 panes (none, one method) saves and reads
// back as it was: the fuzz target found such a session saved with a "views" its own reader refused.
TEST(EditorSession, AnOldSessionsShortCompareListSavesAndReadsBack) {
  const std::string views = "\"views\"";
  for (const char* methods : {"[]", "[\"green\"]"}) {
    std::string old = replaced(sessionToJson(sample()), "\"version\": 3", "\"version\": 1");
    ASSERT_NE(old.find(views), std::string::npos);
    const std::size_t from = old.rfind(',', old.find(views)), to = old.find(']', old.find(views));
    old.erase(from, to + 1 - from);  // no "views" (and its comma): the methods come from "compareMethods"
    const std::size_t list = old.find("\"compareMethods\"");
    old.replace(list, old.find(']', list) + 1 - list, std::string("\"compareMethods\": ") + methods);
    const Session a = sessionFromJson(old, "old.json");
    const Session b = sessionFromJson(sessionToJson(a), "saved.json");
    EXPECT_EQ(b.compareViews.size(), std::string(methods) == "[]" ? 0u : 1u) << methods;
    EXPECT_EQ(b.compareViews, a.compareViews) << methods;
  }
}

// An inline cage gets the checks of a cage file: the repair of its orientation (a notice) and the validation (an
// InputError naming the session and "restCage"), after the shape checks of its own.
TEST(EditorSession, AMalformedInlineCageIsRefusedWithWhatIsWrong) {
  const std::string good = sessionToJson(inlineCageSample());
  const std::string face0 = "[0, 11, 5]";  // the icosahedron's first face (12 vertices, 20 faces)
  const auto expectRejected = [](const std::string& text, const std::string& expected) {
    const std::string message = rejection(text);
    EXPECT_NE(message.find(expected), std::string::npos) << message;
    EXPECT_EQ(message.rfind("s.json: ", 0), 0u) << message;
  };
  EXPECT_EQ(rejection(good), "accepted");
  for (const char* index : {"12", "-1", "0.5", "1e300"})
    expectRejected(replaced(good, face0, "[" + std::string(index) + ", 11, 5]"), "vertex indices from 0 to 11");
  expectRejected(replaced(good, face0, "[0, 0, 5]"), "\"restCage\": the cage cannot be used");
  expectRejected(replaced(good, face0, "[0, 11, 5, 1]"), "\"restCage\" faces rows must have 2 or 3 numbers");
  expectRejected(replaced(good, face0, "[0, 11]"), "\"restCage\" faces row 1 has the wrong size");
  expectRejected(replaced(good, "[0, 5, 1]", "[0, 5]"), "\"restCage\" faces row 1 has the wrong size");
  expectRejected(replaced(good, face0, "[0, \"11\", 5]"), "\"restCage\" faces row 0 holds a non-number");
  expectRejected(replaced(good, "\"faces\": [", "\"faces\": [], \"x\": ["), "\"restCage\" needs vertices and faces");
  expectRejected(replaced(good, "\"faces\": [", "\"x\": ["), "missing field \"faces\"");
  expectRejected(replaced(good, "\"restCage\": {", "\"restCage\": 3, \"x\": {"), "\"restCage\" must be an object");
  expectRejected(replaced(good, "\"cage\": \"\"", "\"cage\": \"c.obj\""), "a session holds one or the other");
  expectRejected(replaced(good, "\"pose\": [", "\"pose\": [[0, 0, 0], "), "\"pose\" has 13 rows");
  // Every face but one: a hole, as a cage file with a missing face is refused.
  expectRejected(replaced(good, face0 + ",", ""), "\"restCage\": the cage cannot be used");
}

// A face listed the wrong way round is repaired as in a cage file, and said.
TEST(EditorSession, AnInlineCageIsRepairedLikeACageFile) {
  Session a = inlineCageSample();
  const Eigen::RowVector3i f = a.restCage.faces.row(0);
  a.restCage.faces.row(0) << f[2], f[1], f[0];
  const Session b = sessionFromJson(sessionToJson(a), "s.json");
  EXPECT_EQ(b.restCage.faces, inlineCageSample().restCage.faces);
  ASSERT_EQ(b.cageNotices.size(), 1u);
  EXPECT_EQ(b.cageNotices[0].kind, Notice::Kind::Repair);
  EXPECT_EQ(b.cageNotices[0].source, "s.json");
}

// A Phong session keeps its method's own options (the tetrahedra's file and level), and refuses options its method
// does not have, or that are not text.
TEST(EditorSession, MethodOptionsRoundTripAndUnknownOnesAreRefused) {
  Session a = sample();
  a.method = methods::phong();
  a.params.nu = 0.3;
  a.methodOptions = {{"tets", "meshes/a \"quoted\" cage.mesh"}, {"tet-level", "2"}};
  const std::string text = sessionToJson(a);
  EXPECT_EQ(sessionFromJson(text, "s.json").methodOptions, a.methodOptions);
  EXPECT_TRUE(sessionFromJson(sessionToJson(sample()), "s.json").methodOptions.empty());
  EXPECT_EQ(sessionToJson(sample()).find("methodOptions"), std::string::npos) << "written only when there are some";
  const std::string unknown = rejection(replaced(text, "\"tet-level\"", "\"tet-detail\""));
  EXPECT_NE(unknown.find("\"tet-detail\", which phong does not have (it has tets, tet-level)"), std::string::npos)
      << unknown;
  EXPECT_NE(rejection(replaced(text, "\"2\"", "2")).find("\"tet-level\" must be a text"), std::string::npos);
  a.method = methods::green();  // green has no options of its own
  EXPECT_NE(rejection(sessionToJson(a)).find("which green does not have (it has none)"), std::string::npos);
}

// loadSession resolves the files a session names next to the session (then as given), for every front end alike:
// the mesh, the cage, and FILE options such as Phong's "tets", the views' included; other options stay text.
TEST(EditorSession, FilesAreResolvedNextToTheSession) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(::testing::TempDir()) / "somicage_session_beside";
  fs::create_directories(dir);
  for (const char* name : {"mesh.obj", "cage.obj", "cube.mesh", "fine.mesh"}) std::ofstream(dir / name) << "\n";
  Session s = sample();
  s.meshPath = "mesh.obj";
  s.cagePath = "cage.obj";
  s.method = methods::phong();
  s.params.nu = 0.3;
  s.methodOptions = {{"tets", "cube.mesh"}, {"tet-level", "2"}};
  s.compareViews = viewsOf({methods::phong(), methods::somigliana()});
  s.compareViews[0].options = {{"tets", "fine.mesh"}};
  const fs::path path = dir / "s.json";
  saveSession(path.string(), s);

  const Session loaded = loadSession(path.string());
  EXPECT_EQ(loaded.meshPath, (dir / "mesh.obj").string());
  EXPECT_EQ(loaded.cagePath, (dir / "cage.obj").string());
  EXPECT_EQ(loaded.methodOptions.at("tets"), (dir / "cube.mesh").string());
  EXPECT_EQ(loaded.methodOptions.at("tet-level"), "2") << "not a file: kept as written";
  EXPECT_EQ(loaded.compareViews[0].options.at("tets"), (dir / "fine.mesh").string());

  // A name with no file next to the session stays as written (the editor's working folder then).
  s.meshPath = "elsewhere/mesh.obj";
  saveSession(path.string(), s);
  EXPECT_EQ(loadSession(path.string()).meshPath, "elsewhere/mesh.obj");
  fs::remove_all(dir);
}
