// The commands of the headless command line. Each lives in its own command_NAME.cpp and is listed once in
// cliCommands() (cli.cpp); they share the option parser (arg_parser.h) and the helpers below.
#pragma once

#include <string>
#include <vector>

#include "cli/command_log.h"
#include "deform/frame_evaluator.h"

namespace somicage {

struct CliCommand {
  const char* name;
  const char* summary;  // one line for `somicage help`
  // The arguments after the command name, the frame devices the executable offers and the log its notices,
  // notes, progress and status lines go through; the exit code (before CommandLog::exitCode).
  int (*run)(const std::vector<std::string>& args, const FrameDevices& devices, CommandLog& log);
  std::string (*usage)();  // the full help text
};

// Every command, in the order `somicage help` lists them.
const std::vector<CliCommand>& cliCommands();
const CliCommand* findCliCommand(const std::string& name);

// Exit codes.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;        // the command ran and the answer is "no" (check: the cage has problems)
constexpr int kExitBadInput = 2;       // the input (files, options) is not usable
constexpr int kExitWarnings = 3;       // --strict: the command did its work, but printed a warning (command_log.h)
constexpr int kExitInterrupted = 130;  // Ctrl-C stopped it (128 + SIGINT, as shells report it; interrupt.h)

int runHelpCommand(const std::vector<std::string>& args);
std::string helpUsage();
int runDeformCommand(const std::vector<std::string>& args, const FrameDevices& devices, CommandLog& log);
std::string deformUsage();
int runAnimateCommand(const std::vector<std::string>& args, CommandLog& log);
std::string animateUsage();
int runCheckCommand(const std::vector<std::string>& args, CommandLog& log);
std::string checkUsage();
int runCageCommand(const std::vector<std::string>& args, CommandLog& log);
std::string cageUsage();
int runBenchCommand(const std::vector<std::string>& args, const FrameDevices& devices, CommandLog& log);
std::string benchUsage();
int runAnalyzeCommand(const std::vector<std::string>& args, CommandLog& log);
std::string analyzeUsage();

}  // namespace somicage
