// The headless command line: somicage deform | check | bench | help.
#pragma once

#include "deform/frame_evaluator.h"

namespace somicage {

// True when argv[1] names a command-line command (rather than files for the editor).
bool isCliCommand(const char* firstArgument);

// Runs the command in argv[1] with the frame devices the executable offers (frame_evaluator.h: the CLI library
// knows no OpenGL, so main.cpp adds that device when it links the editor's backend); returns the process exit
// code (commands.h: 0 ok, 1 failure, 2 bad input, 3 a warning under --strict, 130 Ctrl-C).
int runCli(int argc, char** argv, const FrameDevices& devices);

}  // namespace somicage
