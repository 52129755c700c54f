// The headless command line: somicage deform | check | bench | help.
#pragma once

namespace somicage {

// True when argv[1] names a command-line command (rather than files for the editor).
bool isCliCommand(const char* firstArgument);

// Runs the command in argv[1]; returns the process exit code (0 ok, 1 failure, 2 bad input).
int runCli(int argc, char** argv);

}  // namespace somicage
