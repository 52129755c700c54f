#include "io/mesh_material.h"

#include <algorithm>
#include <filesystem>
#include <string_view>

#include "base/errors.h"
#include "base/file_util.h"
#include "io/obj_io.h"

namespace somicage {

namespace {

namespace fs = std::filesystem;

double unitNumber(std::string_view token, const std::string& source, long line, const char* what) {
  double value = 0.0;
  if (parseObjNumber(token, value) != ObjNumberStatus::Ok || !(value >= 0.0 && value <= 1.0)) {
    throw InputError(source, line, "'" + std::string(token) + "' is not a " + what + " in [0, 1]",
                     "write e.g. `Kd 0.8 0.5 0.4` and `d 1` with decimal numbers");
  }
  return value;
}

// How many arguments each map option takes (-o, -s, -t take one to three numbers).
int optionArguments(std::string_view option) {
  if (option == "-mm") return 2;
  if (option == "-o" || option == "-s" || option == "-t") return 3;
  return 1;  // -blendu -blendv -cc -clamp -texres -boost -bm -imfchan
}

bool isNumber(std::string_view token) {
  double value = 0.0;
  return parseObjNumber(token, value) != ObjNumberStatus::NotANumber;
}

// The file of a `map_Kd [options] FILE` line (FILE may contain blanks), resolved next to the .mtl.
std::string textureFile(const std::vector<std::string_view>& tokens, const std::string& source, long line) {
  size_t k = 1;
  while (k < tokens.size() && tokens[k].size() > 1 && tokens[k][0] == '-' && !isNumber(tokens[k])) {
    const int arguments = optionArguments(tokens[k]);
    ++k;
    for (int a = 0; a < arguments && k < tokens.size() && (a == 0 || isNumber(tokens[k])); ++a) ++k;
  }
  std::string name;
  for (; k < tokens.size(); ++k) name += (name.empty() ? "" : " ") + std::string(tokens[k]);
  if (name.empty()) throw InputError(source, line, "map_Kd names no file", "write `map_Kd texture.png`");
  std::replace(name.begin(), name.end(), '\\', '/');  // written on Windows
  const fs::path file(name);
  return file.is_absolute() ? name : (fs::path(source).parent_path() / file).string();
}

}  // namespace

std::vector<MeshMaterial> parseMtl(const std::string& text, const std::string& source) {
  std::vector<MeshMaterial> materials;
  LineCursor lines(text);  // LF, CRLF or a lone CR, as OBJ files
  std::string_view raw;
  bool opacityFromD = false;
  while (lines.next(raw)) {
    const long lineNumber = lines.lineNumber();
    const std::vector<std::string_view> tokens = splitTokens(raw);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    const std::string_view keyword = tokens[0];
    if (keyword == "newmtl") {
      materials.emplace_back();
      materials.back().name = tokens.size() > 1 ? std::string(tokens[1]) : std::string();
      opacityFromD = false;
      continue;
    }
    if (keyword != "Kd" && keyword != "d" && keyword != "Tr" && keyword != "map_Kd") continue;
    if (materials.empty()) {
      throw InputError(source, lineNumber, "'" + std::string(keyword) + "' comes before any `newmtl`",
                       "start each material with `newmtl NAME`");
    }
    MeshMaterial& material = materials.back();
    if (keyword == "map_Kd") {
      material.texturePath = textureFile(tokens, source, lineNumber);
      continue;
    }
    const size_t first = keyword == "d" && tokens.size() > 2 && tokens[1] == "-halo" ? 2 : 1;
    const size_t count = keyword == "Kd" ? 3 : 1;
    if (tokens.size() < first + count) {
      throw InputError(
          source, lineNumber,
          "'" + std::string(keyword) + "' needs " + std::to_string(count) + (count == 1 ? " number" : " numbers"),
          "write e.g. `Kd 0.8 0.5 0.4` or `d 0.5`");
    }
    if (keyword == "Kd") {
      for (size_t c = 0; c < 3; ++c)
        material.baseColor[static_cast<Eigen::Index>(c)] =
            unitNumber(tokens[first + c], source, lineNumber, "colour component");
    } else if (keyword == "d") {
      material.baseColor[3] = unitNumber(tokens[first], source, lineNumber, "opacity");
      opacityFromD = true;
    } else if (!opacityFromD) {
      material.baseColor[3] = 1.0 - unitNumber(tokens[first], source, lineNumber, "transparency");
    }
  }
  return materials;
}


std::string imageMimeType(const std::string& bytes) {
  if (bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) return "image/png";
  if (bytes.compare(0, 3, "\xFF\xD8\xFF") == 0) return "image/jpeg";
  return "";
}

}  // namespace somicage
