#include "interaction/drop.h"

#include <array>
#include <cctype>
#include <fstream>
#include <optional>

namespace somicage::editor {

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string fileName(const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

bool contains(const std::string& s, const char* word) { return s.find(word) != std::string::npos; }

enum class Mark { Mesh, Cage, Posed };

Mark markOf(const std::string& path) {
  const std::string name = lower(fileName(path));
  if (contains(name, "pose") || contains(name, "deformed")) return Mark::Posed;  // "pose" covers "posed"
  if (contains(name, "cage")) return Mark::Cage;
  return Mark::Mesh;
}

const char* kWhatToDrop =
    "drop a mesh and its cage (2 .obj files), a mesh, its cage and a posed cage (3 .obj files), one posed cage for "
    "the current cage (1 .obj file with as many vertices), or one session .json";

}  // namespace

std::string lowerExtension(const std::string& path) {
  const std::string name = fileName(path);
  const std::size_t dot = name.find_last_of('.');
  return dot == std::string::npos ? std::string() : lower(name.substr(dot));
}

DropPlan planDrop(const std::vector<std::string>& paths, int currentCageVertices, int singleObjVertices) {
  DropPlan plan;
  if (paths.empty()) {
    plan.message = std::string("nothing was dropped: ") + kWhatToDrop;
    return plan;
  }
  std::vector<std::string> objs, jsons, others;
  for (const std::string& p : paths) {
    const std::string ext = lowerExtension(p);
    (ext == ".obj" ? objs : ext == ".json" ? jsons : others).push_back(p);
  }
  if (!others.empty()) {
    plan.message = "cannot open " + fileName(others.front()) + " (only .obj and session .json files): " + kWhatToDrop;
    return plan;
  }
  if (!jsons.empty()) {
    if (paths.size() == 1) {
      plan.kind = DropPlan::Kind::Session;
      plan.session = jsons.front();
    } else {
      plan.message = "drop a session .json on its own, not with other files";
    }
    return plan;
  }
  if (objs.size() == 1) {
    if (currentCageVertices > 0 && singleObjVertices == currentCageVertices) {
      plan.kind = DropPlan::Kind::Pose;
      plan.posed = objs.front();
      return plan;
    }
    plan.message = "one .obj file (" + fileName(objs.front()) + ") was dropped";
    if (currentCageVertices > 0 && singleObjVertices >= 0) {
      plan.message += singleObjVertices > currentCageVertices
                          ? ", with more vertices than the current cage (" + std::to_string(currentCageVertices) + ")"
                          : ", with " + std::to_string(singleObjVertices) + " vertices, but the current cage has " +
                                std::to_string(currentCageVertices);
    }
    plan.message += std::string(": ") + kWhatToDrop;
    return plan;
  }
  if (objs.size() > 3) {
    plan.message = std::to_string(objs.size()) + " .obj files were dropped: " + kWhatToDrop;
    return plan;
  }

  // ---- assign roles: names first, then the order given ----
  const std::size_t n = objs.size();
  constexpr int kMesh = 0, kCage = 1, kPosed = 2;
  std::array<std::optional<std::size_t>, 3> role;  // file index per role
  std::vector<bool> used(n, false);
  // The role whose name mark is unique among the files still free takes that file.
  auto claimUnique = [&](int r, auto matches) {
    if (role[r]) return;
    std::optional<std::size_t> found;
    for (std::size_t i = 0; i < n; ++i) {
      if (used[i] || !matches(markOf(objs[i]))) continue;
      if (found) return;  // not unique
      found = i;
    }
    if (found) {
      role[r] = found;
      used[*found] = true;
    }
  };
  for (int pass = 0; pass < 2; ++pass) {  // a second pass can settle a role the first one freed up
    if (n == 3) claimUnique(kPosed, [](Mark m) { return m == Mark::Posed; });
    claimUnique(kMesh, [](Mark m) { return m == Mark::Mesh; });
    // Two files: a "posed" name is still a cage (there is no rest cage to pose otherwise).
    claimUnique(kCage, [n](Mark m) { return m == Mark::Cage || (n == 2 && m == Mark::Posed); });
  }
  std::size_t next = 0;
  for (std::size_t r = 0; r < n; ++r) {
    if (role[r]) continue;
    while (used[next]) ++next;
    role[r] = next;
    used[next] = true;
  }
  plan.kind = DropPlan::Kind::Scene;
  plan.mesh = objs[*role[kMesh]];
  plan.cage = objs[*role[kCage]];
  if (n == 3) plan.posed = objs[*role[kPosed]];
  return plan;
}

int countObjVertices(const std::string& path, int limit) {
  std::ifstream in(path);
  if (!in) return -1;
  int count = 0;
  std::string line;
  while (std::getline(in, line)) {
    std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line[i] != 'v' || i + 1 >= line.size()) continue;
    if (line[i + 1] != ' ' && line[i + 1] != '\t') continue;  // vt, vn, vp
    if (++count > limit) return count;
  }
  return count;
}

}  // namespace somicage::editor
