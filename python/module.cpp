// The Python module `somicage` (imported through the package python/somicage): the engine's cage loading, checks,
// precompute and deformation over NumPy arrays, with the command line's checks and error messages. The binding
// layer converts and forwards; what a cage is, how it is repaired and deformed lives in core/.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <variant>

#include "base/cpu_dispatch.h"
#include "base/errors.h"
#include "deform/parameter_schema.h"
#include "io/mesh_formats.h"
#include "numpy_arrays.h"
#include "python_cage.h"
#include "python_deformer.h"
#include "python_errors.h"
#include "python_session.h"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace somicage {

namespace {

// Paths come as str or any os.PathLike (pathlib.Path); messages name them as given.
std::string pathText(const fs::path& path) { return path.string(); }

// save_obj writes OBJ text whatever the name says: a name that promises another format is refused before writing.
void requireObjExtension(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".obj")
    throw InputError(path, -1,
                     extension.empty() ? "has no extension, and save_obj writes OBJ text"
                                       : "has the extension " + extension + ", but save_obj writes OBJ text",
                     "name the file .obj");
}

// The engine's parameter ranges (core/deform/deformer.h) by Deformer.deform keyword: the editor's and the CLI's too.
py::dict parameterRanges() {
  py::dict ranges;
  for (const ParameterSpec& spec : parameterSchema())
    if (spec.type == ParameterType::Number) ranges[spec.pythonKeyword] = py::make_tuple(spec.range.min, spec.range.max);
  ranges["threads"] = py::make_tuple(0, kMaxThreads);
  return ranges;
}

// The parameter table (core/deform/parameter_schema.h), one dict per row: what the Blender add-on builds its panel from
// and what the tests compare the keywords, the stub and the add-on with.
py::list parameterSchemaInfo() {
  py::list list;
  for (const ParameterSpec& spec : parameterSchema()) {
    const char* types[] = {"number", "switch", "choice"};
    py::list values;
    for (const ChoiceValue& value : spec.values)
      if (value.description) values.append(py::make_tuple(value.name, value.description));
    std::vector<std::string> methods;
    for (Method m : allMethods())
      if (readsParameter(m, spec.parameter)) methods.emplace_back(m->name);
    py::dict row;
    row["key"] = spec.key;
    row["type"] = types[static_cast<int>(spec.type)];
    row["keyword"] = spec.pythonKeyword;
    row["session_key"] = spec.sessionKey;
    row["view_key"] = viewKey(spec);
    row["cli_flag"] = cliFlag(spec);
    row["label"] = spec.label;
    row["tooltip"] = spec.tooltip;
    row["range"] = py::make_tuple(spec.range.min, spec.range.max);
    row["open_range"] = spec.openRange;
    row["infinities"] = spec.infinities;
    if (spec.type == ParameterType::Number) row["default"] = spec.defaultValue;
    if (spec.type == ParameterType::Switch) row["default"] = spec.defaultValue != 0;
    if (spec.type == ParameterType::Choice) row["default"] = parameterText(spec, spec.defaultValue);
    row["values"] = values;
    row["methods"] = methods;
    list.append(row);
  }
  return list;
}

// A method's descriptor as a dict: what front ends list (Blender's method menu, its tooltips, which settings apply).
py::dict methodInfo(Method method) {
  std::vector<std::string> parameters;
  for (const ParameterSpec& spec : parameterSchema())
    if (readsParameter(method, spec.parameter)) parameters.emplace_back(spec.pythonKeyword);
  py::dict info;
  info["name"] = method->name;
  info["display_name"] = method->displayName;
  info["description"] = method->description;
  info["parameters"] = parameters;
  std::vector<std::string> options;  // its own precompute options as Deformer keywords: "tets", "tet_level"
  for (const MethodOptionSpec& option : method->options) {
    std::string keyword = option.key;
    std::replace(keyword.begin(), keyword.end(), '-', '_');
    options.push_back(keyword);
  }
  info["options"] = options;
  return info;
}

// The choice parameters (deform_choices.h) as a list of dicts, for front ends that build menus from them
// (Blender): name, description, and values as (name, description) pairs, the default first.
py::list choiceInfo() {
  py::list list;
  for (const ChoiceParameter& choice : choiceParameters()) {
    py::list values;
    for (const ChoiceValue& value : choice.values) values.append(py::make_tuple(value.name, value.description));
    py::dict entry;
    entry["name"] = choice.name;
    entry["description"] = choice.description;
    entry["values"] = values;
    list.append(entry);
  }
  return list;
}

void defineCage(py::module_& module) {
  py::class_<PythonCage>(module, "Cage",
                         "A cage as `somicage deform` uses it: face orientation repaired, validated, warned about.")
      .def(py::init([](const ArrayArgument& vertices, const std::optional<ArrayArgument>& faces) {
             return makeUsableCage(cageFromArrays(vertices, faces), "Cage(vertices, faces)");
           }),
           py::arg("vertices"), py::arg("faces") = py::none(),
           "vertices (V, 3) with triangles faces (F, 3), counter-clockwise seen from outside; or a 2D polygon: "
           "vertices (V, 2) with edges (F, 2), or faces=None for a counter-clockwise vertex loop. Any real dtype "
           "(float16 ... float64, integers) for vertices, any integer dtype for faces, any memory order; empty, "
           "non-finite or out-of-range input raises somicage.InputError naming the argument.")
      .def_static(
          "from_obj",
          [](const fs::path& path, bool weld) {
            return makeUsableCage(loadCage(pathText(path), ReadOptions{weld}), pathText(path));
          },
          py::arg("path"), py::kw_only(), py::arg("weld") = false,
          "A cage from a mesh file of any format `somicage deform` reads (OBJ, PLY, OFF, STL, glTF/GLB, FBX): a "
          "closed triangle (or polygon) mesh, or a 2D polygon when every z is 0. weld joins vertices at equal "
          "positions (STL and FBX have none shared).")
      .def_property_readonly(
          "vertices", [](const PythonCage& cage) -> const Eigen::MatrixXd& { return cage.cage.vertices; },
          "(V, d) float64, read-only view (no copy)")
      .def_property_readonly(
          "faces", [](const PythonCage& cage) -> const Eigen::MatrixXi& { return cage.cage.faces; },
          "(F, d) int32, read-only view (no copy): triangles (3D) or edges (2D)")
      .def_property_readonly("dim", [](const PythonCage& cage) { return cage.cage.dim(); })
      .def_property_readonly("num_vertices", [](const PythonCage& cage) { return cage.cage.numVertices(); })
      .def_property_readonly("num_faces", [](const PythonCage& cage) { return cage.cage.numFaces(); })
      .def_readonly("source", &PythonCage::source, "the file, or 'Cage(vertices, faces)'")
      .def_readonly("repairs", &PythonCage::repairs, "the face flips applied on load, one sentence each")
      .def_readonly("warnings", &PythonCage::warnings, "what makes the cage deform poorly (3D self-intersections)")
      .def("__repr__", [](const PythonCage& cage) {
        return "<somicage.Cage " + std::to_string(cage.cage.dim()) + "D, " + std::to_string(cage.cage.numVertices()) +
               " vertices, " + std::to_string(cage.cage.numFaces()) + (cage.cage.dim() == 3 ? " triangles" : " edges") +
               ", from " + cage.source + ">";
      });
}

// Deformer.deform's docstring, with the engine's ranges (kept for the module's lifetime: pybind11 keeps the pointer).
const std::string& deformDoc() {
  static const std::string doc =
      "The deformed points (P, d) float64 (Fortran order, no copy) for the cage's vertices moved to posed (V, d). "
      "nu: Poisson ratio in " +
      rangeText(kNuRange, true) + " or +-inf; gamma in " + rangeText(kGammaRange) +
      ": bulging; variant: global, local, affine or stable; blend in " + rangeText(kBlendRange) +
      " overrides variant (somicage.parameter_ranges() has them all); traction_fix: Eq. 15; corotational: bem "
      "only, removes the best-fit rotation before the linear-elastic solve; bulging: solid-angle (the paper's text), "
      "reference (the authors' code: gamma squared), swept-volume or polygon (solid-angle per flat polygon); normals: "
      "area or angle. Green and mvc ignore "
      "all but posed; bem reads nu and corotational.";
  return doc;
}

void defineDeformer(py::module_& module) {
  py::class_<PythonDeformer>(module, "Deformer",
                             "Precomputed coordinates of points in a rest cage (GIL released, progress, cancel).")
      .def(py::init<const PythonCage&, const ArrayArgument&, const std::string&, int, bool, const ProgressArgument&,
                    const std::string&, std::optional<int>>(),
           py::arg("cage"), py::arg("points"), py::arg("method") = "somigliana", py::kw_only(), py::arg("threads") = 0,
           py::arg("float_storage") = false, py::arg("progress") = py::none(), py::arg("tets") = "",
           py::arg("tet_level") = py::none(),
           "points (P, d) (a 2D cage also takes (P, 3) and uses x, y); method: one of somicage.methods(); "
           "threads: 0 = all cores, for the precompute and every deform; float_storage: store the coordinates in "
           "float (half the memory, ~1e-7 relative error); progress(fraction) -> False cancels (somicage.Cancelled); "
           "Ctrl-C raises KeyboardInterrupt; tets: a MEDIT .mesh tetrahedral mesh of the cage for method='phong' "
           "(default: the cage coned from its centroid, when it is star-shaped from it, else tetrahedralized); "
           "tet_level: 0 (TetGen, about the cage's vertices) to 4 (CGAL Mesh_3, finer), the tetrahedralization's "
           "detail for method='phong' (the CLI's --tet-level; default 1 where the cage is not star-shaped).")
      .def(
          "deform",
          [](const PythonDeformer& deformer, const ArrayArgument& posed, double nu, double gamma,
             const std::string& variant, std::optional<double> blend, bool tractionFix, bool corotational,
             const std::string& bulging, const std::string& normals) {
            return deformer.deform(posed, {nu, gamma, variant, blend, tractionFix, corotational, {bulging, normals}});
          },
          py::arg("posed"), py::kw_only(), py::arg("nu") = 0.0, py::arg("gamma") = 0.0, py::arg("variant") = "global",
          py::arg("blend") = py::none(), py::arg("traction_fix") = true, py::arg("corotational") = false,
          py::arg("bulging") = "solid-angle", py::arg("normals") = "area", deformDoc().c_str())
      .def(
          "analyze",
          [](const PythonDeformer& deformer, const ArrayArgument& posed, const std::vector<std::vector<int>>& faces,
             double nu, double gamma, const std::string& variant, std::optional<double> blend, bool tractionFix,
             bool corotational, const std::optional<std::tuple<double, double, int>>& nuSweep,
             const ProgressArgument& progress, const std::string& bulging, const std::string& normals,
             std::optional<bool> seams) {
            return deformer.analyze(posed, faces,
                                    {nu, gamma, variant, blend, tractionFix, corotational, {bulging, normals}}, nuSweep,
                                    progress, seams);
          },
          py::arg("posed"), py::arg("faces") = std::vector<std::vector<int>>{}, py::kw_only(), py::arg("nu") = 0.0,
          py::arg("gamma") = 0.0, py::arg("variant") = "global", py::arg("blend") = py::none(),
          py::arg("traction_fix") = true, py::arg("corotational") = false, py::arg("nu_sweep") = py::none(),
          py::arg("progress") = py::none(),
          py::arg("bulging") = "solid-angle", py::arg("normals") = "area", py::arg("seams") = py::none(),
          "The numbers of `somicage analyze --json` for the cage's vertices moved to posed, as a dict with its keys: "
          "volume change of the mesh faces (0-based index lists over the points; None when open, "
          "volume_change_capped then), det J, conformal distortion and area ratio quantiles, fold-overs; "
          "nu_sweep=(from, to, count) adds the sweep; seams=True adds seam_jump (as analyze --seams; phong: "
          "unless seams=False), over the Deformer's tetrahedra (tets=, else the cage's star). The exact J is integrated on the first call (GIL released) "
          "and kept; progress(fraction) as for Deformer (0 to 1 for that integration, then for the sweep): False "
          "cancels (somicage.Cancelled), Ctrl-C raises KeyboardInterrupt.")
      .def_property_readonly("method", [](const PythonDeformer& d) { return methodName(d.engine().method()); })
      .def_property_readonly("dim", &PythonDeformer::dim)
      .def_property_readonly("num_points", [](const PythonDeformer& d) { return d.engine().numPoints(); })
      .def_property_readonly("exterior_count",
                             [](const PythonDeformer& d) { return d.engine().diagnostics().exteriorCount(); })
      .def_property_readonly(
          "winding", [](const PythonDeformer& d) -> const Eigen::VectorXd& { return d.engine().diagnostics().winding; },
          "(P,) generalised winding number of each point w.r.t. the rest cage (somigliana, green); read-only view")
      .def_property_readonly(
          "unity_residual",
          [](const PythonDeformer& d) -> const Eigen::VectorXd& { return d.engine().diagnostics().unityResidual; },
          "(P,) somigliana: max |sum_i T_i - I| (Eq. 9), meaningful inside the cage; empty for other methods")
      .def_property_readonly("coordinate_bytes",
                             [](const PythonDeformer& d) { return d.engine().frameCoordinates().bytes(); })
      .def_property_readonly(
          "gradient_integrations", [](const PythonDeformer& d) { return d.engine().gradientIntegrations(); },
          "how often analyze integrated the exact J: 1 after any number of calls (kept with the coordinates; "
          "docs/engine.md, \"The gradients' cache\"), 0 before the first");
}

}  // namespace
}  // namespace somicage

PYBIND11_MODULE(_somicage, module) {
  using namespace somicage;
  module.doc() =
      "Cage deformation with Somigliana coordinates and the other methods of somicage.methods() (SomiCage's "
      "engine).";
  module.attr("__version__") = SOMICAGE_VERSION;
  module.attr("cpu_kernels") = dispatchedKernelTarget();
  registerErrors(module);
  defineCage(module);
  defineDeformer(module);

  module.def(
      "methods",
      [] {
        std::vector<std::string> names;
        for (Method method : allMethods()) names.push_back(methodName(method));
        return names;
      },
      "The method names Deformer takes (the engine's registry, core/deform/method.h).");
  module.def(
      "method_info",
      [] {
        py::list info;
        for (Method method : allMethods()) info.append(methodInfo(method));
        return info;
      },
      "One dict per method, in the order of methods(): name, display_name, description, parameters (the "
      "keyword arguments of Deformer.deform it reads; it ignores the others) and options (the keyword arguments "
      "of Deformer it reads: phong's tets and tet_level).");
  module.def("choice_info", &choiceInfo,
             "One dict per keyword of Deformer.deform that takes a name (bulging, normals): name, description and "
             "values, a list of (name, description) with the default first.");
  module.def(
      "parameter_ranges", [] { return parameterRanges(); },
      "{keyword: (min, max)} of Deformer.deform's numbers and Deformer's threads, from the engine's one list "
      "(core/deform/deformer.h) that the command line and the editor check too: nu in the open interval (or +-inf), "
      "gamma, blend and threads in the closed one.");
  module.def("parameter_schema", &parameterSchemaInfo,
             "The engine's table of deformation parameters (core/deform/parameter_schema.h), one dict per parameter: "
             "key, "
             "type (number, switch, choice), keyword (Deformer.deform's), session_key, view_key, cli_flag, label, "
             "tooltip, range, open_range, infinities, default, values ((name, description) of a choice) and methods "
             "(those that read it).");
  module.def(
      "load_mesh",
      [](const fs::path& path, bool weld) {
        PolygonMesh mesh = loadAnyMesh(pathText(path), ReadOptions{weld});
        return py::make_tuple(std::move(mesh.vertices), std::move(mesh.faces));
      },
      py::arg("path"), py::kw_only(), py::arg("weld") = false,
      "(vertices (V, 3) float64, faces: list of 0-based index lists) of a mesh file of any format `somicage "
      "deform` reads; weld joins vertices at equal positions.");
  module.def(
      "save_obj",
      [](const fs::path& path, const ArrayArgument& vertices, const std::vector<std::vector<int>>& faces) {
        requireObjExtension(pathText(path));
        PolygonMesh topology;
        topology.faces = faces;
        saveObj(pathText(path), matrixFromArray(vertices.object, "vertices", 0), topology);
      },
      py::arg("path"), py::arg("vertices"), py::arg("faces") = std::vector<std::vector<int>>{},
      "Writes vertices (V, 3) or (V, 2) and faces (0-based index lists) with 17 significant digits, atomically, "
      "as `somicage deform` writes its output. The path must end in .obj.");
  module.def(
      "load_posed",
      [](const fs::path& path, const PythonCage& cage, bool weld) {
        return loadPosedVertices(pathText(path), cage.cage, ReadOptions{weld});
      },
      py::arg("path"), py::arg("cage"), py::kw_only(), py::arg("weld") = false,
      "The vertices (V, d) of a posed cage file of any readable format, checked against the rest cage.");
  module.def("load_session", &loadSessionForPython, py::arg("path"),
             "An editor session (File > Save session), read as the editor and `somicage animate` read it: a dict "
             "with source, mesh and cage_path (resolved next to the session), cage (a Cage: the session's inline "
             "cage or its cage file; None for a demo), method, params (Deformer.deform's keywords), pose (the "
             "posed cage, or None at rest), poses (name: vertices), timeline (fps, first, last, loop, "
             "interpolation, keys) and frames: one (posed cage, params) per whole frame of the timeline's range, "
             "as the editor plays it (empty without keys).");
  module.def(
      "check",
      [](const std::variant<fs::path, ArrayArgument>& cage, const std::optional<ArrayArgument>& faces) {
        if (const fs::path* path = std::get_if<fs::path>(&cage))
          return checkReport(loadCage(pathText(*path)), pathText(*path));
        return checkReport(cageFromArrays(std::get<ArrayArgument>(cage), faces), "Cage(vertices, faces)");
      },
      py::arg("cage"), py::arg("faces") = py::none(),
      "Validity of a cage as given (an OBJ path, or vertices and faces), the repairs deform would apply and its "
      "warnings: the cage keys of `somicage check --json`, with the same values.");
}
