// Where a frame's time goes (issue 24, "frames on real meshes"): the deformation, the position uploads, the
// normals, each pane's draw, the UI, the swap. Filled by the frame loop and the Renderer, shown by Help > Frame
// timings and printed by --log-frames, one line per frame, for tests and benchmarks.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace somicage::editor {

struct FrameTimings {
  std::uint64_t frame = 0;     // frames drawn since start
  double totalMs = 0.0;        // from the frame's start to after the swap
  double uiMs = 0.0;           // ImGui: building the windows and rendering their draw data
  double deformMs = 0.0;       // the views' deformation (CPU or another device; in place on OpenGL its CPU part)
  double normalsMs = 0.0;      // vertex normals of the uploaded positions
  double uploadMs = 0.0;       // position / normal / colour uploads (without the normals)
  double measureMs = 0.0;      // the UI thread's part of the quantities (requests, hover readout)
  std::vector<double> drawMs;  // per pane: its mesh, wireframes and cage (finished, when timed)
  double swapMs = 0.0;
  int deforms = 0;    // views deformed this frame
  int uploads = 0;    // views whose positions were uploaded this frame
  int meshDraws = 0;  // mesh draw calls (one per shown pane)
};

// One line, `frame N total_ms=… deform_ms=… deforms=K upload_ms=… uploads=K normals_ms=… measure_ms=… ui_ms=…
// draw_ms=A,B,C mesh_draws=K swap_ms=…`: key=value fields, milliseconds with two decimals.
std::string frameLogLine(const FrameTimings& t);

// Help > Frame timings: the latest frame's breakdown and the mean of the last frames, in a small window.
class FrameTimingsHistory {
 public:
  void add(const FrameTimings& t);
  const FrameTimings& last() const { return last_; }
  // Means over the frames kept (up to 60).
  FrameTimings mean() const;

 private:
  FrameTimings last_;
  std::vector<FrameTimings> recent_;
  std::size_t next_ = 0;
};

void drawFrameTimingsWindow(const FrameTimingsHistory& history, bool* open);

}  // namespace somicage::editor
