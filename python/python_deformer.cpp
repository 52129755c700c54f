#include "python_deformer.h"

#include "engine.h"
#include "errors.h"
#include "numpy_arrays.h"
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
  const Eigen::MatrixXd placed =
      meshPointsFor(restCage_, restPoints, "points", cage.source, [](const Notice& n) { warn(describeNotice(n)); });

  PythonProgress bridge(progress);
  try {
    py::gil_scoped_release release;
    deformer_ = precompute(chosen, restCage_, placed, options, "points", bridge.callback());
  } catch (const Cancelled&) {
    bridge.rethrowPythonError();  // Ctrl-C or the callback's own exception, when Python stopped it
    throw;
  }
  if (const std::optional<Notice> outside = exteriorPointsNotice(*deformer_, "points")) warn(describeNotice(*outside));
}

Eigen::MatrixXd PythonDeformer::deform(const py::handle& posed, const PythonDeformOptions& options) const {
  const Eigen::MatrixXd posedVertices = inCageDimension(matrixFromArray(posed, "posed", 0), restCage_.dim(), "posed");

  DeformParams params;
  if (options.variant != "global" && options.variant != "local")
    throw InputError("variant", -1, "'" + options.variant + "' is not a choice", "use global or local");
  params.blend = options.blend.value_or(options.variant == "local" ? 1.0 : 0.0);
  params.nu = options.nu;
  params.gamma = options.gamma;
  params.tractionCorrection = options.tractionFix;
  params.corotational = options.corotational;

  py::gil_scoped_release release;  // the checks of deformPoints throw InputError, which needs no GIL
  return deformPoints(*deformer_, restCage_, posedVertices, params, "posed", "points");
}

}  // namespace somicage
