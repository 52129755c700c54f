// The headless command line: somicage deform | check | bench | help.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

#include "deformer.h"

namespace somicage {

// Median per-frame milliseconds of a deformer on the GPU, or NaN with the reason in `why`. The CLI library knows
// no OpenGL: an executable that links the editor's GPU backend installs it (main.cpp), and `somicage bench` uses
// it when present.
using GpuFrameTimer = std::function<double(const CageDeformer& deformer, const Eigen::MatrixXd& posedVertices,
                                           const DeformParams& params, int frames, std::string& why)>;
void setGpuFrameTimer(GpuFrameTimer timer);
const GpuFrameTimer& gpuFrameTimer();

// True when argv[1] names a command-line command (rather than files for the editor).
bool isCliCommand(const char* firstArgument);

// Runs the command in argv[1]; returns the process exit code (0 ok, 1 failure, 2 bad input).
int runCli(int argc, char** argv);

}  // namespace somicage
