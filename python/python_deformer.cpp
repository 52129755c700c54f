#include "python_deformer.h"

#include "errors.h"
#include "memory_estimate.h"
#include "mesh_placement.h"
#include "numpy_arrays.h"
#include "obj_io.h"
#include "python_errors.h"
#include "python_progress.h"

namespace py = pybind11;

namespace somicage {

namespace {

// The engine names the command-line option ("--method"); here it is the keyword argument.
Method methodArgument(const std::string& name) {
  try {
    return parseMethod(name);
  } catch (const InputError& e) {
    throw InputError("method", -1, e.problem(), e.hint());
  }
}

// A 2D cage deforms x, y: like `somicage deform`, (n, 3) points or poses give their first two columns.
Eigen::MatrixXd inCageDimension(Eigen::MatrixXd matrix, int dim, const std::string& name) {
  if (matrix.cols() < dim) throw InputError(name, -1, "has 2 columns for a 3D cage", "pass an array of shape (n, 3)");
  if (matrix.cols() > dim) return matrix.leftCols(dim);
  return matrix;
}

}  // namespace

PythonDeformer::PythonDeformer(const PythonCage& cage, const py::handle& points, const std::string& method, int threads,
                               bool floatStorage, const py::object& progress)
    : restCage_(cage.cage) {
  const Method chosen = methodArgument(method);
  const int dim = restCage_.dim();
  const Eigen::MatrixXd restPoints = inCageDimension(matrixFromArray(points, "points", 0), dim, "points");
  if (threads < 0) throw InputError("threads", -1, "is " + std::to_string(threads), "use 0 (all cores) or more");
  PrecomputeOptions options;
  options.threads = threads;
  options.integration.threads = threads;
  options.floatStorage = floatStorage;
  const MemoryEstimate estimate =
      estimatePrecomputeMemory(chosen, dim, restCage_.numVertices(), restCage_.numFaces(),
                               static_cast<std::size_t>(restPoints.rows()), floatStorage, threads);
  requireMemory(estimate, availableMemoryBytes(), "points", memoryHint(!floatStorage));
  if (const auto placement = describeMeshPlacement(measureMeshPlacement(restCage_, restPoints), "points", cage.source))
    warn(*placement);

  PythonProgress bridge(progress);
  try {
    py::gil_scoped_release release;
    deformer_ = makeDeformer(chosen, restCage_, restPoints, options, bridge.callback());
  } catch (const Cancelled&) {
    bridge.rethrowPythonError();  // Ctrl-C or the callback's own exception, when Python stopped it
    throw;
  }
  const int exterior = deformer_->diagnostics().exteriorCount();
  if (exterior > 0)
    warn(std::to_string(exterior) + " of " + std::to_string(restPoints.rows()) +
         " points lie outside the cage (or on it); they follow the cage's best-fit similarity, blended smoothly "
         "into the deformation inside (docs/engine.md, \"Points outside the cage\")");
}

Eigen::MatrixXd PythonDeformer::deform(const py::handle& posed, const PythonDeformOptions& options) const {
  const int dim = restCage_.dim();
  PolygonMesh pose;  // through posedVerticesFromMesh: the command line's check and message for the vertex count
  const Eigen::MatrixXd given = inCageDimension(matrixFromArray(posed, "posed", 0), dim, "posed");
  pose.vertices = Eigen::MatrixXd::Zero(given.rows(), 3);
  pose.vertices.leftCols(dim) = given;
  const Eigen::MatrixXd posedVertices = posedVerticesFromMesh(pose, restCage_, "posed");

  DeformParams params;
  if (options.variant != "global" && options.variant != "local")
    throw InputError("variant", -1, "'" + options.variant + "' is not a choice", "use global or local");
  params.blend = options.blend.value_or(options.variant == "local" ? 1.0 : 0.0);
  params.nu = options.nu;
  params.gamma = options.gamma;
  params.tractionCorrection = options.tractionFix;
  params.corotational = options.corotational;
  validateDeformParams(params);

  py::gil_scoped_release release;
  return deformer_->deform(posedVertices, params);
}

}  // namespace somicage
