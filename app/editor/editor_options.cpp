#include "editor_options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "base/errors.h"
#include "base/parse_number.h"
#include "deform/deform_params.h"
#include "deform/parameter_schema.h"
#include "engine/session.h"  // kMaxCompareViews
#include "generation/cage_generation.h"
#include "model/view_quantity.h"

namespace somicage::editor {

namespace {

// The parameter flag (parameter_schema.h) a is, or none.
std::optional<ParameterFlag> findParameterFlag(const std::string& a) {
  for (const ParameterFlag& f : parameterFlags())
    if (a == f.flag) return f;
  return std::nullopt;
}

// The method option (MethodDescriptor::options) that the flag a ("--tet-level") names, or none.
const MethodOptionSpec* findMethodOption(const std::string& a) {
  for (const MethodOptionFlag& f : methodOptionFlags())
    if (a == f.flag) return f.spec;
  return nullptr;
}

// An option and its help on one line, aligned as the CLI's help aligns them.
std::string usageLine(std::string option, const std::string& help) {
  option.resize(std::max<std::size_t>(option.size() + 1, 28), ' ');
  return option + help + "\n";
}

// "  --nu V                    Poisson ratio: ... (default 0)" per flag of the table, as the CLI's help has them.
std::string parametersUsage() {
  std::string text;
  for (const ParameterFlag& f : parameterFlags())
    text += usageLine("  " + f.flag + (f.fixedValue ? "" : " " + cliValueName(*f.spec)), parameterFlagHelp(f));
  return text;
}

// "  --tets FILE               a MEDIT .mesh ...; phong only" per method option, as the CLI's help has them.
std::string methodOptionsUsage() {
  std::string text;
  for (const MethodOptionFlag& f : methodOptionFlags()) text += usageLine("  " + f.flag + " " + f.spec->value, f.help);
  return text;
}

}  // namespace

EditorOptions parseEditorArgs(const std::vector<std::string>& args) {
  EditorOptions o;
  std::vector<std::string> positional;
  bool compareGiven = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw InputError(a, -1, "missing value", "see somicage --help");
      return args[++i];
    };
    if (a == "-h" || a == "--help") {
      o.help = true;
    } else if (a == "--method") {
      o.method = parseMethod(value());
    } else if (const std::optional<ParameterFlag> f = findParameterFlag(a)) {
      o.parameters[f->spec->key] = parseParameter(*f->spec, f->fixedValue ? f->fixedValue : value(), a);
    } else if (const MethodOptionSpec* option = findMethodOption(a)) {
      const std::string& v = value();
      if (option->check) {
        try {
          option->check(v);
        } catch (const InputError& e) {
          throw InputError(a, -1, e.problem(), e.hint());
        }
      }
      o.methodOptions[option->key] = v;
    } else if (a == "--compare") {
      if (compareGiven || !o.views.empty())
        throw InputError(a, -1, "given twice, or with --view", "use --compare a,b or --view SPEC (repeated), not both");
      compareGiven = true;
      const std::string list = value();
      std::vector<Method> methods;
      std::size_t start = 0;
      while (start <= list.size()) {
        const std::size_t comma = list.find(',', start);
        const std::string name = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        try {
          methods.push_back(parseMethod(name));
        } catch (const InputError&) {
          throw InputError(a, -1, "unknown method '" + name + "'", "use a comma list of " + methodNameList());
        }
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
      if (methods.size() < 2 || methods.size() > kMaxCompareViews)
        throw InputError(a, -1, "compare needs 2 or 3 methods", "e.g. --compare somigliana,green,mvc");
      o.views = viewsOf(methods);
    } else if (a == "--view") {
      if (compareGiven) throw InputError(a, -1, "given with --compare", "use --view SPEC (repeated) or --compare a,b");
      if (o.views.size() == kMaxCompareViews)
        throw InputError(a, -1, "at most " + std::to_string(kMaxCompareViews) + " views", "give --view 2 or 3 times");
      o.views.push_back(parseViewSpec(value(), a));
    } else if (a == "--screenshot") {
      o.screenshotPath = value();
    } else if (a == "--session") {
      o.sessionPath = value();
    } else if (a == "--demo") {
      const std::string& v = value();
      if (v != "2d" && v != "3d" && v != "fig8")
        throw InputError(a, -1, "expected 2d, 3d or fig8, got '" + v + "'", "--demo 2d");
      o.demoDim = v == "2d" ? 2 : 3;
      o.demoFig8 = v == "fig8";
    } else if (a == "--size") {
      const std::string& v = value();
      const std::size_t x = v.find('x');
      int w = 0, h = 0;
      if (x != std::string::npos) {
        w = std::atoi(v.substr(0, x).c_str());
        h = std::atoi(v.substr(x + 1).c_str());
      }
      if (w < 64 || h < 64 || w > 16384 || h > 16384)
        throw InputError(a, -1, "expected WIDTHxHEIGHT between 64 and 16384, got '" + v + "'", "--size 1600x900");
      o.width = w;
      o.height = h;
    } else if (a == "--hide-ui") {
      o.hideUi = true;
    } else if (a == "--restore-autosave") {
      o.restoreAutosave = true;
    } else if (a == "--frame-delay") {
      const std::string& v = value();
      const double ms = parseNumber(v, a);
      if (!(ms >= 0 && ms <= 10000))
        throw InputError(a, -1, "expected milliseconds in [0, 10000], got '" + v + "'", "--frame-delay 150");
      o.frameDelayMs = static_cast<int>(ms);
    } else if (a == "--log-actions") {
      o.logActions = true;
    } else if (a == "--log-frames") {
      o.logFrames = true;
    } else if (a == "--nu-plot") {
      o.nuPlot = true;
    } else if (a == "--hide-cage") {
      o.hideCage = true;
    } else if (a == "--show-tets") {
      o.showTets = true;
    } else if (a == "--make-cage") {
      const std::string& v = value();
      const double faces = parseNumber(v, a);
      if (!(faces >= CageGenerationOptions::kMinFaces && faces <= 2000 && faces == std::floor(faces)))
        throw InputError(a, -1, "expected a face count in [12, 2000], got '" + v + "'", "--make-cage 200");
      o.makeCageFaces = static_cast<int>(faces);
    } else if (a == "--export-dialog") {
      o.exportDialog = value();
    } else if (a == "--show") {
      o.show = parseShow(value(), a, o.showFieldVertex);
    } else if (a == "--range") {
      const std::string& v = value();
      const std::size_t colon = v.find(':');
      if (colon == std::string::npos) throw InputError(a, -1, "expected MIN:MAX, got '" + v + "'", "--range 0.5:2");
      o.range = ColorRange{parseNumber(v.substr(0, colon), a), parseNumber(v.substr(colon + 1), a)};
    } else if (a == "--flat") {
      o.flatShading = true;
    } else if (a == "--device") {
      o.device = value();  // checked against the executable's devices by checkDeviceOption
    } else if (a.size() > 1 && a[0] == '-') {
      throw InputError(a, -1, "unknown option", "see somicage --help");
    } else {
      positional.push_back(a);
    }
  }
  if (positional.size() > 3) {
    throw InputError("command line", -1,
                     "expected MESH [CAGE [POSED]], got " + std::to_string(positional.size()) + " files",
                     "give no files for the demo, a mesh (a cage is made for it), or a mesh and its cage (and "
                     "optionally a posed cage)");
  }
  if (!positional.empty()) o.meshPath = positional[0];
  if (positional.size() >= 2) o.cagePath = positional[1];
  if (positional.size() == 3) o.posedPath = positional[2];
  {  // the engine's ranges (parameter_schema.h), named as options
    DeformParams p;
    for (const ParameterSpec& spec : parameterSchema())
      if (const auto it = o.parameters.find(spec.key); it != o.parameters.end()) setParameter(spec, p, it->second);
    try {
      validateDeformParams(p);
    } catch (const InputError& e) {
      const ParameterSpec* spec = findParameter(e.source());
      throw InputError(spec ? cliFlag(*spec) : "--" + e.source(), -1, e.problem(), e.hint());
    }
  }
  for (const ViewShow& view : o.show.views) {  // the typed range must suit every shown quantity's scale
    const QuantityDescriptor& d = quantityDescriptor(view.quantity);
    const std::string problem = o.range && view.quantity > 0 ? rangeProblem(*o.range, d.scale) : "";
    if (!problem.empty())
      throw InputError("--range", -1, std::string(problem) + " (for " + d.id + ")",
                       "e.g. --range 0.5:2 for det J, --range 0:0.05 for a difference");
  }
  if (o.views.size() == 1)
    throw InputError("--view", -1, "one view given: the compare view shows 2 or 3",
                     "give --view twice, e.g. --view somigliana:nu=0 --view somigliana:nu=0.45 (one view: --method, "
                     "--nu)");
  return o;
}

void checkDeviceOption(const EditorOptions& options, const FrameDevices& devices) {
  if (options.device) frameDeviceOption(devices, *options.device);
}

std::string editorUsage() {
  return "usage: somicage [MESH.obj [CAGE.obj [POSED.obj]]] [options]   (no cage: one is made, see 'somicage cage')\n"
         "       somicage deform|check|bench|help ...   (command line tools, see 'somicage help')\n"
         "\n"
         "With no files the built-in demo opens.\n"
         "  --demo 2d|3d|fig8         which demo (default 3d; fig8: the paper's Fig. 8, Phong's creases beside\n"
         "                            Somigliana local nu = 0)\n"
         "  --session FILE.json       open a saved session\n"
         "  --method NAME             " +
         methodNameList() + " (default " + methodName(Method()) + ")\n" + parametersUsage() + methodOptionsUsage() +
         "  --compare a,b[,c]         side-by-side views, e.g. somigliana,bem,green\n"
         "  --view METHOD[:KEY=VALUE]...\n"
         "                            KEY: " +
         viewKeyList() +
         ", or a method's own option\n"
         "                            one side-by-side view with its own parameters (the others follow --nu\n"
         "                            etc.); give it 2 or 3 times, e.g. --view somigliana:nu=0\n"
         "                            --view somigliana:nu=0.45 (paper Fig. 3), or --view somigliana\n"
         "                            --view somigliana:bulging=reference (the bulging conventions side by side);\n"
         "                            a method's own options too, e.g. --view phong:tet-level=2 (each such view\n"
         "                            precomputes its own)\n"
         "  --screenshot OUT.png      render one frame, write it and exit (works under xvfb-run)\n"
         "  --size WxH                window size (default 1600x900)\n"
         "  --hide-ui                 viewports only, no panels\n"
         "  --flat                    faceted shading instead of smooth\n"
         "  --nu-plot                 with --screenshot: sweep nu first, so the panel shows the plot of volume\n"
         "                            change against nu (in the window: the Sweep nu button)\n"
         "  --hide-cage               do not draw the cage (it can be turned on in the panel)\n"
         "  --show-tets               draw the posed tetrahedra of Phong views as a wireframe (View menu)\n"
         "  --make-cage N             with --screenshot: File > Make cage... with N faces, shown once generated\n"
         "  --export-dialog FILE      with --screenshot: File > Export animation... open, FILE in its file field\n"
         "  --show detj|distortion|foldover|area|difference|field:VERTEX[,...]\n"
         "                            colour the meshes by a quantity of the pose: det J (diverging, log scale,\n"
         "                            centred at 1), conformal distortion (viridis), fold-overs (det J <= 0,\n"
         "                            magenta), the triangles' area ratio (per vertex: geometric mean, log scale),\n"
         "                            the distance to another view (cage diameters) or the coordinate field\n"
         "                            of cage vertex VERTEX (|T_i n_i|; Somigliana, BEM); a comma list gives\n"
         "                            each view its own, e.g. detj,detj,difference\n"
         "  --range MIN:MAX           a fixed colour range for the shown quantities (default: automatic, shared\n"
         "                            by the views); a ratio's range must have MIN < 1 < MAX\n"
         "  --restore-autosave        after a crash, restore the autosaved session without asking\n"
         "  --device cpu|opengl|cuda  where every frame is deformed: the CPU (OpenMP), an OpenGL 4.3 compute\n"
         "                            shader writing the vertex buffers, or CUDA (default: opengl on a hardware\n"
         "                            GPU, cpu otherwise; an unusable device says why and the CPU deforms)\n"
         "  --frame-delay MS          testing: make every frame MS slower (tries input at low frame rates)\n"
         "  --log-actions             print each keyboard command, undo step and dialog to stdout (testing)\n"
         "  --log-frames              print each frame's time breakdown to stdout, one line per frame (deform,\n"
         "                            upload, normals, each pane's draw, UI; benchmarks and tests)\n"
         "  -h, --help                this list\n"
         "\n"
         "In the editor: F1 lists the shortcuts. Ctrl+S saves the session, Ctrl+Z / Ctrl+Shift+Z undo / redo,\n"
         "Edit > Undo History jumps to any step.\n";
}

}  // namespace somicage::editor
