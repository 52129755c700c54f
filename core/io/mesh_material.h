// Surface materials of a mesh file, as far as the GLB writer carries them: a base colour with opacity and a
// base-colour texture. OBJ meshes get them from the .mtl libraries their `mtllib` lines name (read when a GLB is
// written, so a broken .mtl never stops an OBJ export); meshes read through assimp (glTF, FBX, ...) bring them from
// the file (MeshDocument::materials), an image embedded in the file included.
//
// From a .mtl: `Kd r g b` (the colour, used as glTF's baseColorFactor as Blender's OBJ importer uses it: no colour
// space conversion), `d a` or `Tr t` (opacity a = 1 - t; `d` wins when both appear), `map_Kd [options] FILE`
// (options such as -s u v w are skipped; FILE resolves next to the .mtl). Everything else is ignored.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace somicage {

struct MeshMaterial {
  std::string name;
  Eigen::Vector4d baseColor{1.0, 1.0, 1.0, 1.0};  // r, g, b, opacity in [0, 1]
  std::string texturePath;                        // the base-colour texture's file (resolved), "" when none or embedded
  std::string textureBytes;  // an image embedded in the mesh file (PNG or JPEG bytes), "" when none
};

// Parses the text of a .mtl file; source names it in errors and resolves texture paths. Throws InputError (file,
// line, what) for a colour or opacity that is not a number in [0, 1] and a map_Kd without a file name.
std::vector<MeshMaterial> parseMtl(const std::string& text, const std::string& source);

// "image/png", "image/jpeg", or "" when the bytes are neither (the two formats glTF carries).
std::string imageMimeType(const std::string& bytes);

}  // namespace somicage
