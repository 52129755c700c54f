// What a command says on stderr besides its errors, and what that does to its exit code (issue 22). Every notice
// (engine.h: a repair made, a warning about the input) and every warning a command finds itself goes through one
// CommandLog, so one place knows whether a run was clean: under --strict a run that would exit 0 exits 3
// (kExitWarnings) instead, after its output is written (runCli applies exitCode to what the command returned).
// --quiet silences the progress and memory-estimate lines and the closing summary; notes, warnings and errors
// still print.
#pragma once

#include <string>
#include <vector>

#include "cli/arg_parser.h"
#include "cli/progress_reporter.h"
#include "engine/engine.h"

namespace somicage {

// options, then --quiet and --strict: the options of the commands scripts run (deform, analyze, animate, check,
// cage).
std::vector<OptionSpec> withScriptOptions(std::vector<OptionSpec> options);

class CommandLog {
 public:
  explicit CommandLog(std::string command);  // "somicage deform", the prefix of notes and status lines

  // Reads --quiet and --strict, when the command declares them (withScriptOptions).
  void configure(const ArgParser& args);
  bool quiet() const { return quiet_; }

  // Prints "somicage: note: SOURCE: TEXT" (a repair) or "somicage: warning: ..." and counts it.
  void notice(const Notice& notice);
  // notice(), as a sink for the engine facade. The log must outlive the calls.
  NoticeSink sink();
  // Counts `count` warnings the command's own report (stdout) already lists, without printing them again.
  void listed(int count);
  int warnings() const { return warnings_; }

  // "COMMAND: note: TEXT": information that leaves the result as asked (an option the method ignores, data the
  // output format cannot carry); not a warning.
  void note(const std::string& text) const;
  // "COMMAND: TEXT": the estimate before a long precompute, the closing summary; silenced by --quiet.
  void status(const std::string& text) const;
  // A progress reporter for a long step; silent under --quiet.
  ProgressReporter progress(std::string label) const;

  // code, or kExitWarnings when --strict was given, a warning was counted and code is kExitOk.
  int exitCode(int code) const;

 private:
  std::string command_;
  bool quiet_ = false, strict_ = false;
  int warnings_ = 0;
};

}  // namespace somicage
