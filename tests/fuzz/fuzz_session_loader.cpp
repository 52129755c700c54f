// libFuzzer target: the session reader (core/engine/session.h, json.h: the editor's, animate's and Python's) on any
// text. Contract: no crash and no sanitizer report; bad input throws InputError; an accepted session has finite numbers
// where the editor needs them, an inline cage is well-formed, and saving it and reading it back gives the same session.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "base/errors.h"
#include "base/json.h"
#include "engine/session.h"

namespace {

using somicage::Session;

void require(bool condition, const char* what) {
  if (condition) return;
  std::fprintf(stderr, "fuzz_session_loader: contract violated: %s\n", what);
  std::abort();
}

// Exact equality; nu may be +-infinity, which compares equal to itself.
bool sameSession(const Session& a, const Session& b) {
  return a.meshPath == b.meshPath && a.cagePath == b.cagePath && a.demoDim == b.demoDim &&
         a.pose.rows() == b.pose.rows() && a.pose.cols() == b.pose.cols() && a.pose == b.pose && a.method == b.method &&
         a.params.blend == b.params.blend && a.params.nu == b.params.nu && a.params.gamma == b.params.gamma &&
         a.params.tractionCorrection == b.params.tractionCorrection && a.params.corotational == b.params.corotational &&
         a.compare == b.compare && a.compareViews == b.compareViews && a.camera.target == b.camera.target &&
         a.camera.distance == b.camera.distance && a.camera.yaw == b.camera.yaw && a.camera.pitch == b.camera.pitch &&
         a.restCage.vertices.rows() == b.restCage.vertices.rows() &&
         a.restCage.vertices.cols() == b.restCage.vertices.cols() && a.restCage.vertices == b.restCage.vertices &&
         a.restCage.faces.rows() == b.restCage.faces.rows() && a.restCage.faces.cols() == b.restCage.faces.cols() &&
         a.restCage.faces == b.restCage.faces;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);

  // The JSON layer alone: whatever it accepts, it writes back as JSON it accepts again.
  try {
    const somicage::JsonValue value = somicage::parseJson(text, "fuzz.json");
    (void)somicage::parseJson(value.dump(2), "dumped.json");
  } catch (const somicage::InputError&) {
  }

  Session session;
  try {
    session = somicage::sessionFromJson(text, "fuzz.session");
  } catch (const somicage::InputError&) {
    return 0;
  }
  require(session.demoDim == 2 || session.demoDim == 3, "demoDim is 2 or 3");
  require(session.pose.allFinite(), "pose coordinates are finite");
  require(session.restCage.numVertices() == 0 ||
              ((session.restCage.faces.array() >= 0).all() &&
               (session.restCage.faces.array() < session.restCage.numVertices()).all() &&
               session.restCage.vertices.allFinite() && session.restCage.faces.cols() == session.restCage.dim()),
          "an inline cage has finite vertices and in-range faces of d corners");
  require(session.camera.target.allFinite() && std::isfinite(session.camera.yaw) &&
              std::isfinite(session.camera.pitch) && std::isfinite(session.camera.distance),
          "camera numbers are finite");

  const Session reread = somicage::sessionFromJson(somicage::sessionToJson(session), "saved.session");
  require(sameSession(session, reread), "a saved session reads back unchanged");
  return 0;
}
