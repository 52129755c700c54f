// somicage: the editor when started without a command, the headless command line otherwise.
#include <cstdio>
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
#ifdef SOMICAGE_HAVE_EDITOR
  // `somicage --help` lists both: the editor's options (what runs without a command), then the commands.
  if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    const int rc = somicage::runEditor(argc, argv, devices);
    std::fputs("\n", stdout);
    std::fflush(stdout);
    return rc != 0 ? rc : somicage::runCli(argc, argv, devices);
  }
#endif
  if (argc > 1 && somicage::isCliCommand(argv[1])) return somicage::runCli(argc, argv, devices);
#ifdef SOMICAGE_HAVE_EDITOR
  return somicage::runEditor(argc, argv, devices);
#else
  return somicage::runCli(argc, argv, devices);  // built without the editor: the CLI explains the commands
#endif
}
