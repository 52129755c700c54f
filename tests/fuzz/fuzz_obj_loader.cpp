// libFuzzer target: the OBJ loaders (core/io/obj_io.h) on arbitrary bytes, as `somicage deform` and the editor read
// them: parse (loadMesh), turn into a cage (loadCage), read as a pose (loadPosedVertices); and the same bytes as a
// MEDIT volume mesh (core/geometry/medit_io.h, --tets), checked against the unit cube's cage (volume_mesh.h).
// Contract: no crash and no sanitizer report; bad input throws InputError; what is accepted is well formed
// (finite coordinates, indices in range).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "base/errors.h"
#include "geometry/medit_io.h"
#include "io/obj_io.h"

namespace {

void require(bool condition, const char* what) {
  if (condition) return;
  std::fprintf(stderr, "fuzz_obj_loader: contract violated: %s\n", what);
  std::abort();
}

bool indicesInRange(const std::vector<std::vector<int>>& elements, int vertexCount) {
  for (const std::vector<int>& element : elements) {
    for (int v : element) {
      if (v < 0 || v >= vertexCount) return false;
    }
  }
  return true;
}

// A unit square: a rest cage whose vertex count a fuzzed pose rarely matches (the mismatch error path).
somicage::Cage squareCage() {
  Eigen::MatrixXd loop(4, 2);
  loop << 0, 0, 1, 0, 1, 1, 0, 1;
  return somicage::makePolygonCage(loop);
}

// The cube [0, 1]^3: the cage a fuzzed volume mesh is checked against (the seeds in tests/fuzz/corpus/medit).
somicage::Cage cubeCage() {
  somicage::Cage cube;
  cube.vertices.resize(8, 3);
  for (int i = 0; i < 8; ++i) cube.vertices.row(i) << (i & 1), (i & 2) >> 1, (i & 4) >> 2;
  cube.faces.resize(12, 3);
  cube.faces << 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7,
      5;
  return cube;
}

void checkMedit(const std::string& text) {
  somicage::MeditMesh read;
  try {
    read = somicage::parseMedit(text, "fuzz.mesh");
  } catch (const somicage::InputError&) {
    return;
  }
  const somicage::VolumeMesh& mesh = read.mesh;
  require(mesh.vertices.allFinite(), "a parsed volume mesh has finite coordinates");
  require(mesh.simplices.cols() == mesh.dim() + 1, "a simplex has d + 1 vertices");
  require(mesh.simplices.minCoeff() >= 0 && mesh.simplices.maxCoeff() < mesh.numVertices(), "indices are in range");
  require(read.source.simplexLines.size() == static_cast<std::size_t>(mesh.numSimplices()), "each simplex has a line");
  somicage::VolumeMesh checked = mesh;
  try {
    somicage::checkVolumeMesh(checked, cubeCage(), read.source);
  } catch (const somicage::InputError&) {
    return;
  }
  for (int s = 0; s < checked.numSimplices(); ++s)
    require(somicage::signedSimplexMeasure(checked, s) > 0, "an accepted volume mesh is positively oriented");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string source = "fuzz.obj";
  checkMedit(text);

  somicage::PolygonMesh mesh;
  try {
    mesh = somicage::parseObj(text, source);
  } catch (const somicage::InputError&) {
    return 0;
  }
  require(mesh.vertices.cols() == 3, "a parsed mesh has 3 coordinates per vertex");
  require(mesh.vertices.allFinite(), "a parsed mesh has finite coordinates");
  require(indicesInRange(mesh.faces, mesh.numVertices()), "face indices are in range");
  require(indicesInRange(mesh.lines, mesh.numVertices()), "line indices are in range");

  try {
    (void)somicage::posedVerticesFromMesh(mesh, squareCage(), source);
  } catch (const somicage::InputError&) {
  }

  somicage::Cage cage;
  try {
    cage = somicage::cageFromMesh(mesh, source);
  } catch (const somicage::InputError&) {
    return 0;
  }
  require(cage.dim() == 2 || cage.dim() == 3, "a cage is 2D or 3D");
  require(cage.faces.cols() == cage.dim(), "a cage's faces have d corners");
  require(cage.faces.size() == 0 || (cage.faces.minCoeff() >= 0 && cage.faces.maxCoeff() < cage.numVertices()),
          "cage face indices are in range");

  const Eigen::MatrixXd pose = somicage::posedVerticesFromMesh(mesh, cage, source);
  require(pose.rows() == cage.numVertices() && pose.cols() == cage.dim(), "a cage is its own pose");
  return 0;
}
