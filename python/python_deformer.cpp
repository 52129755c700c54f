#include "python_deformer.h"

#include <algorithm>

#include "base/errors.h"
#include "deform/deform_choices.h"
#include "deform/parameter_schema.h"
#include "engine/engine.h"
#include "numpy_arrays.h"
#include "python_errors.h"
#include "python_progress.h"
#include "tetrahedralization/cage_tetrahedralization.h"

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

DeformParams deformParams(const PythonDeformOptions& options) {
  DeformParams params;
  const ParameterSpec& variant = *findParameter("variant");  // "blend" too: what load_session gives for 0 < blend < 1
  setParameter(variant, params, parseParameter(variant, options.variant, "variant"));
  if (options.blend) params.blend = *options.blend;
  params.nu = options.nu;
  params.gamma = options.gamma;
  params.tractionCorrection = options.tractionFix;
  params.corotational = options.corotational;
  const std::vector<ChoiceParameter>& choices = choiceParameters();
  for (std::size_t k = 0; k < options.choices.size() && k < choices.size(); ++k)
    choices[k].set(params, parseChoice(choices[k], options.choices[k], choices[k].name));
  return params;
}

// A method option as the engine names it ("--tet-level", the command line's) as Deformer's keyword ("tet_level").
std::string keywordOf(const std::string& source) {
  if (source.rfind("--", 0) != 0) return source;
  std::string keyword = source.substr(2);
  std::replace(keyword.begin(), keyword.end(), '-', '_');
  return keyword;
}

// A number of analyze --json; None where the command prints null: the volumes of an open mesh.
py::object numberOrNone(bool defined, double value) { return defined ? py::object(py::float_(value)) : py::none(); }

py::dict namedNumbers(const NamedNumbers& numbers) {
  py::dict object;
  for (const auto& [name, value] : numbers) object[name.c_str()] = value;
  return object;
}

// A 2D cage deforms x, y: like `somicage deform`, (n, 3) points or poses give their first two columns.
Eigen::MatrixXd inCageDimension(Eigen::MatrixXd matrix, int dim, const std::string& name) {
  if (matrix.cols() < dim) throw InputError(name, -1, "has 2 columns for a 3D cage", "pass an array of shape (n, 3)");
  if (matrix.cols() > dim) return matrix.leftCols(dim);
  return matrix;
}

}  // namespace

PythonDeformer::PythonDeformer(const PythonCage& cage, const ArrayArgument& points, const std::string& method,
                               int threads, bool floatStorage, const ProgressArgument& progress, const std::string& tets,
                               std::optional<int> tetLevel)
    : restCage_(cage.cage) {
  const Method chosen = methodArgument(method);
  const int dim = restCage_.dim();
  const Eigen::MatrixXd restPoints = inCageDimension(matrixFromArray(points.object, "points", 0), dim, "points");
  if (threads < 0 || threads > kMaxThreads)
    throw InputError("threads", -1, "is " + std::to_string(threads),
                     "use 0 (all cores) to " + std::to_string(kMaxThreads));
  PrecomputeOptions options;
  options.threads = threads;
  options.integration.threads = threads;
  options.floatStorage = floatStorage;
  if (!tets.empty()) options.methodOptions["tets"] = tets;
  if (tetLevel) options.methodOptions["tet-level"] = std::to_string(*tetLevel);
  options.volumeMesher = tetrahedralizeCageWithOptions;
  points_ =
      meshPointsFor(restCage_, restPoints, "points", cage.source, [](const Notice& n) { warn(describeNotice(n)); });

  try {
    prepareVolumeMesh(chosen, restCage_, options, [](const Notice& n) { warn(describeNotice(n)); });
  } catch (const InputError& e) {  // the keyword, not the command line's option
    throw InputError(keywordOf(e.source()), e.line(), e.problem(), e.hint());
  }
  options_ = options;
  PythonProgress bridge(progress);
  try {
    py::gil_scoped_release release;
    deformer_ = precompute(chosen, restCage_, points_, options, "points", bridge.callback());
  } catch (const Cancelled&) {
    bridge.rethrowPythonError();  // Ctrl-C or the callback's own exception, when Python stopped it
    throw;
  }
  if (const std::optional<Notice> outside = exteriorPointsNotice(*deformer_, "points")) warn(describeNotice(*outside));
}

Eigen::MatrixXd PythonDeformer::posedVertices(const ArrayArgument& posed) const {
  return inCageDimension(matrixFromArray(posed.object, "posed", 0), restCage_.dim(), "posed");
}

Eigen::MatrixXd PythonDeformer::deform(const ArrayArgument& posed, const PythonDeformOptions& options) const {
  const Eigen::MatrixXd pose = posedVertices(posed);
  const DeformParams params = deformParams(options);
  py::gil_scoped_release release;  // the checks of deformPoints throw InputError, which needs no GIL
  return deformPoints(*deformer_, restCage_, pose, params, "posed", "points");
}

py::dict PythonDeformer::analyze(const ArrayArgument& posed, const std::vector<std::vector<int>>& faces,
                                 const PythonDeformOptions& options,
                                 const std::optional<std::tuple<double, double, int>>& nuSweep,
                                 const ProgressArgument& progress, std::optional<bool> seams) const {
  const Eigen::MatrixXd pose = posedVertices(posed);
  const DeformParams params = deformParams(options);
  std::vector<double> nus;
  if (nuSweep) {
    try {
      nus = nuSweepValues(std::get<0>(*nuSweep), std::get<1>(*nuSweep), std::get<2>(*nuSweep));
    } catch (const InputError& e) {  // the engine names the option (--nu-sweep); here it is the keyword
      throw InputError("nu_sweep", -1, e.problem(), e.hint());
    }
  }
  PoseAnalysis a;
  PythonProgress bridge(progress);
  try {
    py::gil_scoped_release release;
    // kept with the coordinates (CageDeformer::gradients): the next call, at any pose or parameters, reuses them
    const std::shared_ptr<const DeformationGradients> gradients = deformer_->gradients(points_, bridge.callback());
    std::unique_ptr<SeamJumpEvaluator> seamJumps;
    if (seams.value_or(measuresSeamsByDefault(deformer_->method()))) {
      try {
        seamJumps = prepareSeamJumps(*deformer_, restCage_, points_, faces, options_, "faces", bridge.callback());
      } catch (const InputError& e) {  // the keyword, not the command line's option
        throw InputError(keywordOf(e.source()), e.line(), e.problem(), e.hint());
      }
    }
    a = analyzePose(*deformer_, *gradients, restCage_, points_, faces, pose, params, nus, "posed", "faces",
                    bridge.callback(), seamJumps.get());
  } catch (const Cancelled&) {
    bridge.rethrowPythonError();  // Ctrl-C or the callback's own exception, when Python stopped it
    throw;
  }
  const EnclosedMeasure& volume = a.fields.volume;
  py::dict result;  // the keys and order of `somicage analyze --json` (app/cli/command_analyze.cpp)
  const Method method = deformer_->method();
  result["method"] = methodName(method);
  if (readsParameter(method, kParamBlend)) {
    result["variant"] = variantName(params);
    result["blend"] = params.blend;
  }
  if (readsParameter(method, kParamGamma)) result["gamma"] = params.gamma;
  for (const ChoiceParameter& choice : choiceParameters())
    if (readsParameter(method, choice.parameter))
      result[choice.name] = choice.values[static_cast<std::size_t>(choice.get(params))].name;
  result["dimension"] = restCage_.dim();
  result["vertices"] = points_.rows();
  result["closed"] = volume.closed;
  result["volume_rest"] = numberOrNone(volume.closed, volume.rest);
  result["volume_deformed"] = numberOrNone(volume.closed, volume.deformed);
  result["volume_change"] = numberOrNone(volume.closed, volume.change());
  if (!volume.closed) result["volume_change_capped"] = volume.change();
  result["jacobian_det"] = namedNumbers(a.jacobianDet);
  result["conformal_distortion"] = namedNumbers(a.conformalDistortion);
  result["foldover_vertices"] = a.fields.points.foldovers;
  result["area_ratio"] = namedNumbers(a.areaRatio);
  if (!a.seamJump.empty()) result["seam_jump"] = namedNumbers(a.seamJump);
  result["outside_points"] = a.fields.points.undefined;
  if (nuSweep) {
    py::list sweep;
    for (const NuSweepEntry& e : a.nuSweep) {
      py::dict entry;
      entry["nu"] = e.nu;
      entry[volume.closed ? "volume_change" : "volume_change_capped"] = e.volumeChange;
      entry["foldover_vertices"] = e.foldovers;
      sweep.append(entry);
    }
    result["nu_sweep"] = sweep;
  }
  return result;
}

}  // namespace somicage
