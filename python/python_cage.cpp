#include "python_cage.h"

#include <pybind11/stl.h>

#include "cage_repair.h"
#include "cage_validation.h"
#include "engine.h"
#include "errors.h"
#include "numpy_arrays.h"
#include "python_errors.h"

namespace py = pybind11;

namespace somicage {

Cage cageFromArrays(const py::handle& vertices, const py::handle& faces) {
  const Eigen::MatrixXd positions = matrixFromArray(vertices, "vertices", 0);
  const int dim = static_cast<int>(positions.cols());
  if (faces.is_none()) {
    if (dim == 2) return makePolygonCage(positions);
    throw InputError("faces", -1, "a 3D cage needs its triangles", "pass faces as an (m, 3) integer array");
  }
  Cage cage{positions, indicesFromArray(faces, "faces")};
  if (cage.faces.cols() != dim)
    throw InputError("faces", -1,
                     "has " + std::to_string(cage.faces.cols()) + " columns for a " + std::to_string(dim) + "D cage",
                     dim == 3 ? "pass triangles (m, 3); Cage.from_obj triangulates polygons"
                              : "pass edges (m, 2), or faces=None for a vertex loop");
  return cage;
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

py::dict checkCage(const Cage& cage, const std::string& source) {
  const CageReport report = validateCage(cage);
  const CageRepair repair = repairCage(cage);
  const CageReport repaired = repair.fixes.empty() ? report : validateCage(repair.cage);
  py::dict result;
  result["cage"] = source;
  result["dim"] = report.dim;
  result["cage_vertices"] = report.numVertices;
  result["cage_faces"] = report.numFaces;
  result["valid"] = report.valid();
  result["closed"] = report.closed();
  result["manifold"] = report.manifold();
  result["consistently_oriented"] = report.consistentlyOriented();
  result["outward"] = report.outward();
  result["simple"] = report.dim == 2 ? py::object(py::bool_(report.simple())) : py::object(py::none());
  result[report.dim == 3 ? "signed_volume" : "signed_area"] = report.signedVolume;
  result["diameter"] = report.diameter;
  result["components"] = report.components;
  result["problems"] = describeCageProblems(report);
  result["repairs"] = repair.fixes;
  result["usable"] = repaired.valid();
  result["warnings"] = describeCageWarnings(repaired);
  return result;
}

}  // namespace somicage
