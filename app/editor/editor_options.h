// The editor's command line: somicage [MESH CAGE [POSED]] [options]. Pure, no GL.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "deform/frame_evaluator.h"
#include "deform/method.h"
#include "engine/view_spec.h"
#include "geometry/volume_mesh.h"
#include "model/view_quantity.h"

namespace somicage::editor {

struct EditorOptions {
  std::string meshPath, cagePath, posedPath;  // empty mesh and cage: the built-in demo
  std::string sessionPath;                    // --session FILE
  int demoDim = 3;                            // --demo 2d|3d|fig8
  bool demoFig8 = false;                      // --demo fig8: the paper's Fig. 8 (fig8_demo.h)
  std::optional<Method> method;               // --method
  // The parameter options (parameter_schema.h: --nu, --variant, --local, --no-traction-fix, ...): key -> value,
  // the last given of a parameter's flags; applied in the table's order (variant before blend).
  std::map<std::string, double> parameters;
  // The methods' own options (MethodDescriptor::options: --tets FILE, --tet-level N) for the single view, as the
  // CLI's deform takes them; checked when given (MethodOptionSpec::check).
  MethodOptions methodOptions;
  std::vector<ViewSpec> views;                // --compare a,b[,c] or --view SPEC (2 or 3); empty = one view
  std::string screenshotPath;                 // --screenshot: render one frame, write the PNG, exit
  int width = 1600, height = 900;             // --size WxH
  bool flatShading = false;                   // --flat: faceted shading
  bool hideUi = false;                        // --hide-ui: only the viewports (for clean screenshots)
  std::optional<std::string> device;          // --device NAME (frame_device_evaluators.h); default: opengl on a
                                              // hardware GPU, else cpu
  bool restoreAutosave = false;               // --restore-autosave: restore a crashed session without asking
  int frameDelayMs = 0;                       // --frame-delay MS: testing, every frame MS slower (low frame rates)
  bool logFrames = false;                     // --log-frames: print each frame's time breakdown (frame_timings.h)
  bool logActions = false;                    // --log-actions: print each keyboard command to stdout as it runs
  bool hideCage = false;                      // --hide-cage: the mesh only (screenshots of a quantity)
  bool showTets = false;                      // --show-tets: the tetrahedral wireframe of volume-mesh views
  bool nuPlot = false;                        // --nu-plot: sweep nu once the scene is ready (the panel's plot)
  int makeCageFaces = 0;                      // --make-cage N: open File > Make cage with N faces (screenshots)
  std::optional<std::string> exportDialog;    // --export-dialog FILE: open File > Export animation (screenshots)
  ShowSettings show;                          // --show detj|...|field:VERTEX, per view (view_quantity.h)
  std::optional<ColorRange> range;            // --range MIN:MAX: a fixed range for the shown quantities
  int showFieldVertex = -1;                   // --show field:VERTEX: the cage vertex selected for the field
  bool help = false;                          // -h / --help
};

// args excludes the program name. Throws InputError naming the option on a bad value or unknown option.
EditorOptions parseEditorArgs(const std::vector<std::string>& args);
// Throws InputError("--device") listing the offered devices when --device names none of them.
void checkDeviceOption(const EditorOptions& options, const FrameDevices& devices);

std::string editorUsage();

}  // namespace somicage::editor
