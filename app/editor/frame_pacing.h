// When the editor draws: only for input, a running precompute, playback or a pending deformation; otherwise it
// sleeps in glfwWaitEventsTimeout (idle is idle: no core kept busy redrawing an unchanged picture). After input
// it draws a few more frames, since ImGui settles hover and click states one frame late (a radio button that
// showed the old choice until the mouse moved). Pure logic, no GLFW.
#pragma once

namespace somicage::editor {

struct FrameDemand {
  bool input = false;     // events arrived since the last frame (keys, mouse, resize, focus, ...)
  bool queued = false;    // input events still wait in the queue (event_queue.h)
  bool busy = false;      // the precompute worker runs: its progress bar moves
  bool changing = false;  // a deformation, screenshot or playback frame is pending
};

class FramePacer {
 public:
  static constexpr int kSettleFrames = 3;
  // Progress-bar refresh while a job runs: 2 Hz, since each frame also draws the scene, which on a software renderer
  // costs 0.1-0.7 s of the cores the job computes on for FIREHYDRANT (llvmpipe, loaded); input still draws at once.
  static constexpr double kBusySeconds = 1.0 / 2.0;
  static constexpr double kIdleSeconds = 1.0;         // wake-ups for the autosave clock, nothing drawn

  // Whether to draw a frame now.
  bool shouldDraw(const FrameDemand& demand);
  // How long to wait for events before the next decision: 0 = do not wait (draw again at once).
  double waitSeconds(const FrameDemand& demand) const;

 private:
  int settle_ = kSettleFrames;  // the first frames after start settle too
};

}  // namespace somicage::editor
