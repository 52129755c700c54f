#include "engine/session.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>

#include "animation/pose_timeline_json.h"
#include "base/errors.h"
#include "base/file_util.h"
#include "base/json.h"
#include "deform/parameter_json.h"

namespace somicage {

std::vector<Method> defaultCompareMethods() {
  const std::vector<Method>& all = allMethods();
  return std::vector<Method>(all.begin(), all.begin() + std::min(all.size(), kMaxCompareViews));
}

namespace {

// A matrix as an array of rows (the pose, the inline cage's vertices and faces).
template <typename Matrix>
JsonValue rows(const Matrix& m) {
  JsonValue out = JsonValue::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    JsonValue row = JsonValue::array();
    for (Eigen::Index c = 0; c < m.cols(); ++c) row.push(JsonValue::number(static_cast<double>(m(i, c))));
    out.push(std::move(row));
  }
  return out;
}

// Only what the view sets itself: an absent parameter follows the shared one.
JsonValue viewToJson(const ViewSpec& view) {
  JsonValue out = JsonValue::object();
  out.set("method", JsonValue::string(methodName(view.method)));
  for (const auto& [key, value] : view.own) {
    const ParameterSpec& spec = *findParameter(key);
    out.set(spec.sessionKey, parameterJson(spec, value));
  }
  if (!view.options.empty()) {
    JsonValue options = JsonValue::object();
    for (const auto& [key, value] : view.options) options.set(key, JsonValue::string(value));
    out.set("options", std::move(options));
  }
  return out;
}

JsonValue vec3(const Eigen::Vector3d& v) {
  JsonValue a = JsonValue::array();
  for (int i = 0; i < 3; ++i) a.push(JsonValue::number(v[i]));
  return a;
}

struct Reader {
  const std::string& source;

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source, -1, what, "fix the session file, or save it again from the editor");
  }
  const JsonValue& get(const JsonValue& obj, const std::string& key) const {
    const JsonValue* v = obj.find(key);
    if (!v) fail("missing field \"" + key + "\"");
    return *v;
  }
  double number(const JsonValue& obj, const std::string& key) const {
    const JsonValue& v = get(obj, key);
    if (!v.isNumber()) fail("field \"" + key + "\" must be a number");
    return v.asNumber();
  }
  bool boolean(const JsonValue& obj, const std::string& key) const {
    const JsonValue& v = get(obj, key);
    if (v.type() != JsonValue::Type::Bool) fail("field \"" + key + "\" must be true or false");
    return v.asBool();
  }
  std::string string(const JsonValue& obj, const std::string& key) const {
    const JsonValue& v = get(obj, key);
    if (!v.isString()) fail("field \"" + key + "\" must be a string");
    return v.asString();
  }
  Method method(const std::string& name) const {
    try {
      return parseMethod(name);
    } catch (const InputError&) {
      fail("unknown method \"" + name + "\" (expected " + methodNameList() + ")");
    }
  }
  // {"KEY": "VALUE", ...}: options of `method` (MethodDescriptor::options), as text; their values are checked where
  // they are used (the precompute: a tets file's errors name the file and line).
  MethodOptions methodOptions(const JsonValue& v, Method method) const {
    if (!v.isObject()) fail("\"methodOptions\" must be an object of texts, e.g. {\"tet-level\": \"2\"}");
    MethodOptions options;
    for (const auto& [key, value] : v.members()) {
      std::string known;
      bool found = false;
      for (const MethodOptionSpec& o : method->options) {
        known += (known.empty() ? "" : ", ") + std::string(o.key);
        found = found || key == o.key;
      }
      if (!found)
        fail("\"methodOptions\" has \"" + key + "\", which " + methodName(method) + " does not have (" +
             (known.empty() ? std::string("it has none") : "it has " + known) + ")");
      if (!value.isString()) fail("\"methodOptions\" \"" + key + "\" must be a text");
      options[key] = value.asString();
    }
    return options;
  }
  // An array of rows of 2 or 3 numbers each, all of the first row's length; may be empty (0 by 0).
  Eigen::MatrixXd rows(const JsonValue& v, const std::string& name) const {
    if (!v.isArray()) fail(name + " must be an array of rows");
    if (v.items().empty()) return Eigen::MatrixXd();
    const std::size_t cols = v.items()[0].items().size();
    if (cols != 2 && cols != 3) fail(name + " rows must have 2 or 3 numbers");
    Eigen::MatrixXd out(static_cast<Eigen::Index>(v.items().size()), static_cast<Eigen::Index>(cols));
    for (std::size_t i = 0; i < v.items().size(); ++i) {
      const JsonValue& row = v.items()[i];
      if (!row.isArray() || row.items().size() != cols)
        fail(name + " row " + std::to_string(i) + " has the wrong size");
      for (std::size_t c = 0; c < cols; ++c) {
        if (!row.items()[c].isNumber()) fail(name + " row " + std::to_string(i) + " holds a non-number");
        out(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(c)) = row.items()[c].asNumber();
      }
    }
    return out;
  }
  // The inline cage: its shape here, then everything a cage file gets (prepareCage: repair, validation, warnings).
  Cage cage(const JsonValue& v, const Session& s, std::vector<Notice>& notices) const {
    if (!v.isObject()) fail("\"restCage\" must be an object with \"vertices\" and \"faces\"");
    if (!s.cagePath.empty()) fail("\"restCage\" and a \"cage\" file: a session holds one or the other");
    Cage cage;
    cage.vertices = rows(get(v, "vertices"), "\"restCage\" vertices");
    const Eigen::MatrixXd faces = rows(get(v, "faces"), "\"restCage\" faces");
    if (cage.numVertices() == 0 || faces.rows() == 0) fail("\"restCage\" needs vertices and faces");
    if (faces.cols() != cage.dim())
      fail("\"restCage\" faces must have " + std::to_string(cage.dim()) + " vertex indices each, as its vertices " +
           std::to_string(cage.dim()) + " coordinates");
    if (s.meshPath.empty() && cage.dim() != s.demoDim)
      fail("the demo's \"restCage\" must have \"demoDim\" coordinates per vertex");
    // Checked as doubles, before the cast: a huge or fractional index has no int.
    if (!(faces.array() >= 0).all() || !(faces.array() < cage.numVertices()).all() ||
        !(faces.array() == faces.array().floor()).all())
      fail("\"restCage\" faces must hold vertex indices from 0 to " + std::to_string(cage.numVertices() - 1));
    cage.faces = faces.cast<int>();
    try {
      return prepareCage(std::move(cage), source, [&](const Notice& n) { notices.push_back(n); });
    } catch (const InputError& e) {
      fail("\"restCage\": " + e.problem());
    }
  }
  // "views" entry i: {"method", and optionally its own parameters by their session keys (parameter_schema.h: "nu",
  // "variant", "tractionCorrection", "bulging", ...) and "options" (the method's own, as text: {"tet-level": "2"});
  // nothing else.
  ViewSpec view(const JsonValue& v, std::size_t i) const {
    const std::string where = "\"views\" entry " + std::to_string(i);
    if (!v.isObject()) fail(where + " must be an object with \"method\"");
    const auto isParameter = [](const std::string& key) {
      for (const ParameterSpec& spec : parameterSchema())
        if (key == spec.sessionKey) return true;
      return false;
    };
    for (const auto& [key, value] : v.members())
      if (key != "method" && key != "options" && !isParameter(key)) {
        std::string keys = "method";
        for (const ParameterSpec& spec : parameterSchema()) keys += std::string(", ") + spec.sessionKey;
        fail(where + " has an unknown field \"" + key + "\" (expected " + keys + ", options)");
      }
    const JsonValue* name = v.find("method");
    if (!name || !name->isString()) fail(where + " needs \"method\": a method name");
    ViewSpec view{method(name->asString()), {}, {}};
    try {
      for (const ParameterSpec& spec : parameterSchema())
        if (const std::optional<double> value = readParameterJson(v, spec, source)) view.own[spec.key] = *value;
      if (const JsonValue* options = v.find("options")) {
        if (!options->isObject()) fail("field \"options\" must be an object of texts");
        for (const auto& [key, value] : options->members()) {
          if (!value.isString()) fail("field \"options\" must hold texts: \"" + key + "\" is not one");
          view.options[key] = value.asString();
        }
      }
      validateViewSpec(view, source);
    } catch (const InputError& e) {
      fail(where + ": " + e.problem());
    }
    return view;
  }
  Eigen::Vector3d vec3(const JsonValue& obj, const std::string& key) const {
    const JsonValue& v = get(obj, key);
    if (!v.isArray() || v.items().size() != 3) fail("field \"" + key + "\" must be an array of 3 numbers");
    Eigen::Vector3d out;
    for (int i = 0; i < 3; ++i) {
      if (!v.items()[static_cast<std::size_t>(i)].isNumber()) fail("field \"" + key + "\" must hold numbers");
      out[i] = v.items()[static_cast<std::size_t>(i)].asNumber();
    }
    return out;
  }
};

}  // namespace

std::string sessionToJson(const Session& s) {
  JsonValue root = JsonValue::object();
  root.set("format", JsonValue::string("somicage-session"));
  root.set("version", JsonValue::number(3));
  root.set("mesh", JsonValue::string(s.meshPath));
  root.set("cage", JsonValue::string(s.cagePath));
  root.set("demoDim", JsonValue::number(s.demoDim));
  if (s.restCage.numVertices() > 0) {
    JsonValue cage = JsonValue::object();
    cage.set("vertices", rows(s.restCage.vertices));
    cage.set("faces", rows(s.restCage.faces));
    root.set("restCage", std::move(cage));
  }
  root.set("pose", rows(s.pose));
  root.set("method", JsonValue::string(methodName(s.method)));
  if (!s.methodOptions.empty()) {
    JsonValue options = JsonValue::object();
    for (const auto& [key, value] : s.methodOptions) options.set(key, JsonValue::string(value));
    root.set("methodOptions", std::move(options));
  }
  JsonValue params = JsonValue::object();
  writeParameters(s.params, params);
  root.set("params", std::move(params));
  root.set("compare", JsonValue::boolean(s.compare));
  JsonValue methods = JsonValue::array(), views = JsonValue::array();
  for (const ViewSpec& view : s.compareViews) {
    methods.push(JsonValue::string(methodName(view.method)));
    views.push(viewToJson(view));
  }
  root.set("compareMethods", std::move(methods));
  // "views" holds a compare view's 2 to kMaxCompareViews panes. The other lists an older session may hold (no
  // method, one) stay in "compareMethods" alone, so they read back as they were instead of failing "views"' check.
  if (s.compareViews.size() >= 2 && s.compareViews.size() <= kMaxCompareViews) root.set("views", std::move(views));
  JsonValue camera = JsonValue::object();
  camera.set("target", vec3(s.camera.target));
  camera.set("distance", JsonValue::number(s.camera.distance));
  camera.set("yaw", JsonValue::number(s.camera.yaw));
  camera.set("pitch", JsonValue::number(s.camera.pitch));
  root.set("camera", std::move(camera));
  root.set("poses", poseLibraryToJson(s.poses));
  root.set("timeline", timelineToJson(s.timeline));
  return root.dump(2);
}

Session sessionFromJson(const std::string& text, const std::string& source) {
  const JsonValue root = parseJson(text, source);
  const Reader r{source};
  if (!root.isObject()) r.fail("a session file must hold a JSON object");
  if (r.string(root, "format") != "somicage-session") r.fail("not a SomiCage session (\"format\" differs)");
  const double version = r.number(root, "version");
  if (version != 1 && version != 2 && version != 3)
    r.fail("unsupported session version (this build reads versions 1 to 3)");
  Session s;
  s.meshPath = r.string(root, "mesh");
  s.cagePath = r.string(root, "cage");
  // What only the editor's view needs (the demo's dimension, the pose on screen, the compare view, the camera) may
  // be left out of a session written by hand for `somicage animate`: the defaults of a new session then.
  if (root.find("demoDim")) {
    const double demoDim = r.number(root, "demoDim");  // compared before the cast: a huge value does not fit an int
    if (demoDim != 2 && demoDim != 3) r.fail("\"demoDim\" must be 2 or 3");
    s.demoDim = static_cast<int>(demoDim);
  }
  if (const JsonValue* pose = root.find("pose")) s.pose = r.rows(*pose, "\"pose\"");
  if (version >= 3) {
    if (const JsonValue* cage = root.find("restCage")) s.restCage = r.cage(*cage, s, s.cageNotices);
  }
  if (s.restCage.numVertices() > 0 && s.pose.size() > 0 &&
      (s.pose.rows() != s.restCage.numVertices() || s.pose.cols() != s.restCage.dim()))
    r.fail("\"pose\" has " + std::to_string(s.pose.rows()) + " rows but \"restCage\" " +
           std::to_string(s.restCage.numVertices()) + " vertices of " + std::to_string(s.restCage.dim()) +
           " coordinates");
  s.method = r.method(r.string(root, "method"));
  if (const JsonValue* options = root.find("methodOptions")) s.methodOptions = r.methodOptions(*options, s.method);
  const JsonValue& params = r.get(root, "params");
  if (!params.isObject()) r.fail("\"params\" must be an object");
  // Every parameter by its session key; one absent (a session saved before it existed) keeps its default.
  try {
    readParameters(params, s.params, source);
  } catch (const InputError& e) {
    r.fail(e.problem());
  }
  try {
    validateDeformParams(s.params);
  } catch (const InputError& e) {
    r.fail(std::string("bad parameters: ") + e.what());
  }
  if (root.find("compare")) s.compare = r.boolean(root, "compare");
  if (const JsonValue* views = root.find("views")) {
    s.compareViews.clear();
    if (!views->isArray() || views->items().size() < 2 || views->items().size() > kMaxCompareViews)
      r.fail("\"views\" must be an array of 2 to " + std::to_string(kMaxCompareViews) + " views");
    for (std::size_t i = 0; i < views->items().size(); ++i) s.compareViews.push_back(r.view(views->items()[i], i));
  } else if (const JsonValue* list = root.find("compareMethods")) {  // before "views": the shared parameters
    const JsonValue& methods = *list;
    if (!methods.isArray()) r.fail("\"compareMethods\" must be an array of method names");
    s.compareViews.clear();
    for (const JsonValue& m : methods.items()) {
      if (!m.isString()) r.fail("\"compareMethods\" must hold strings");
      s.compareViews.push_back(ViewSpec{r.method(m.asString()), {}, {}});
    }
  }
  if (const JsonValue* cameraField = root.find("camera")) {
    const JsonValue& camera = *cameraField;
    s.camera.target = r.vec3(camera, "target");
    s.camera.distance = r.number(camera, "distance");
    s.camera.yaw = r.number(camera, "yaw");
    s.camera.pitch = r.number(camera, "pitch");
    if (!(s.camera.distance > 0) || !std::isfinite(s.camera.distance)) r.fail("camera \"distance\" must be positive");
  }
  if (const JsonValue* poses = root.find("poses")) s.poses = poseLibraryFromJson(*poses, source);
  if (const JsonValue* timeline = root.find("timeline")) s.timeline = timelineFromJson(*timeline, source);
  return s;
}

void saveSession(const std::string& path, const Session& session) { writeFileAtomic(path, sessionToJson(session)); }

namespace {

// A file the session at sessionPath names: a relative name is looked up next to the session first, then as given
// (the editor saves names as it opened them, relative to its working folder).
std::string resolveSessionPath(const std::string& sessionPath, const std::string& name) {
  const std::filesystem::path file(name);
  if (name.empty() || file.is_absolute()) return name;
  const std::filesystem::path beside = std::filesystem::path(sessionPath).parent_path() / file;
  std::error_code error;
  return std::filesystem::exists(beside, error) ? beside.string() : name;
}

// The method's options whose value is a file name (MethodOptionSpec::value "FILE", e.g. Phong's "tets").
void resolveFileOptions(const std::string& sessionPath, Method method, MethodOptions& options) {
  for (const MethodOptionSpec& spec : method->options) {
    const auto option = options.find(spec.key);
    if (option != options.end() && std::string_view(spec.value) == "FILE")
      option->second = resolveSessionPath(sessionPath, option->second);
  }
}

}  // namespace

// The session's files are resolved here, once, so that the editor, `animate` and Python open the same ones.
Session loadSession(const std::string& path) {
  Session session = sessionFromJson(readTextFile(path), path);
  session.meshPath = resolveSessionPath(path, session.meshPath);
  session.cagePath = resolveSessionPath(path, session.cagePath);
  resolveFileOptions(path, session.method, session.methodOptions);
  for (ViewSpec& view : session.compareViews) resolveFileOptions(path, view.method, view.options);
  return session;
}

}  // namespace somicage
