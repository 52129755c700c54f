// Ctrl-C during a command. The first SIGINT only asks the running computation to stop: the commands' progress
// reports (progress_reporter.h) answer "stop" from then on, the computation throws Cancelled, and runCli exits with
// kExitInterrupted (130, as a shell reports a process SIGINT ended) after the temporary files and folders are
// removed on the way out, so nothing is left half-written. A second Ctrl-C ends the process at once, as by default.
#pragma once

namespace somicage {

// Installs the handler (once per process; for the command line only, never in the editor or the Python module).
void catchInterrupt();

// Whether Ctrl-C was pressed since catchInterrupt.
bool interruptRequested();

}  // namespace somicage
