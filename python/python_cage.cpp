#include "python_cage.h"

#include <pybind11/stl.h>

#include <variant>

#include "base/errors.h"
#include "cage/cage_check.h"
#include "engine/engine.h"
#include "numpy_arrays.h"
#include "python_errors.h"

namespace py = pybind11;

namespace somicage {

Cage cageFromArrays(const ArrayArgument& vertices, const std::optional<ArrayArgument>& faces) {
  const Eigen::MatrixXd positions = matrixFromArray(vertices.object, "vertices", 0);
  const int dim = static_cast<int>(positions.cols());
  if (!faces) {
    if (dim == 2) return makePolygonCage(positions);
    throw InputError("faces", -1, "a 3D cage needs its triangles", "pass faces as an (m, 3) integer array");
  }
  return Cage{positions, indicesFromArray(faces->object, "faces", dim, static_cast<int>(positions.rows()))};
}

PythonCage makeUsableCage(Cage cage, std::string source) {
  PythonCage result;
  result.source = std::move(source);
  result.cage = prepareCage(std::move(cage), result.source, [&](const Notice& notice) {
    (notice.kind == Notice::Kind::Repair ? result.repairs : result.warnings).push_back(notice.text);
    warn(describeNotice(notice));
  });
  return result;
}

py::dict checkReport(const Cage& cage, const std::string& source) {
  py::dict result;
  result["cage"] = source;
  for (const auto& [key, value] : cageCheckFields(checkCage(cage)))
    result[key.c_str()] = std::visit([](const auto& v) { return py::cast(v); }, value);
  return result;
}

}  // namespace somicage
