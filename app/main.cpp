// somicage: the editor when started without a command, the headless command line otherwise.
#include <cstring>
#include <string>

#include "cli/cli.h"
#ifdef SOMICAGE_HAVE_EDITOR
#include "editor/editor.h"
#include "gpu_benchmark.h"
#endif

int main(int argc, char** argv) {
#ifdef SOMICAGE_HAVE_EDITOR
  // `somicage bench` times the GPU frame too when this executable has the OpenGL backend.
  somicage::setGpuFrameTimer([](const somicage::CageDeformer& deformer, const Eigen::MatrixXd& posed,
                                const somicage::DeformParams& params, int frames, std::string& why) {
    return somicage::render::timeGpuDeformMs(deformer, posed, params, frames, &why);
  });
#endif
  if (argc > 1 && somicage::isCliCommand(argv[1])) return somicage::runCli(argc, argv);
#ifdef SOMICAGE_HAVE_EDITOR
  return somicage::runEditor(argc, argv);
#else
  return somicage::runCli(argc, argv);  // built without the editor: the CLI explains the commands
#endif
}
