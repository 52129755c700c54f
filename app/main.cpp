// somicage: the editor when started without a command, the headless command line otherwise.
#include <cstring>
#include <string>

#include "cli/cli.h"
#include "cuda/cuda_backend.h"
#ifdef SOMICAGE_HAVE_EDITOR
#include "editor/editor.h"
#include "gl_frame_evaluator.h"
#endif

int main(int argc, char** argv) {
  // The frame devices of this executable: `somicage deform --device`, `somicage bench` and the editor use them.
  somicage::FrameDevices devices = {somicage::cpuFrameDevice()};
#ifdef SOMICAGE_HAVE_EDITOR
  devices.push_back(somicage::render::openGlFrameDevice());
#endif
  devices.push_back(somicage::cudaFrameDevice());
  if (argc > 1 && somicage::isCliCommand(argv[1])) return somicage::runCli(argc, argv, devices);
#ifdef SOMICAGE_HAVE_EDITOR
  return somicage::runEditor(argc, argv, devices);
#else
  return somicage::runCli(argc, argv, devices);  // built without the editor: the CLI explains the commands
#endif
}
