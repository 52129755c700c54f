#include "cli/cli.h"

#include <filesystem>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/errors.h"
#include "cli/arg_parser.h"
#include "cli/commands.h"
#include "cli/interrupt.h"

namespace somicage {

const std::vector<CliCommand>& cliCommands() {
  static const std::vector<CliCommand> commands = {
      {"help", "show this help, or the options of one command",
       [](const std::vector<std::string>& a, const FrameDevices&, CommandLog&) { return runHelpCommand(a); },
       helpUsage},
      {"deform", "deform a mesh (or point set) with a posed cage and write it (OBJ, PLY, GLB)", runDeformCommand,
       deformUsage},
      {"animate", "write a session's keyframed animation as a GLB or an OBJ sequence",
       [](const std::vector<std::string>& a, const FrameDevices&, CommandLog& log) {
         return runAnimateCommand(a, log);
       },
       animateUsage},
      {"analyze", "measure a pose: volume change, det J, distortion and fold-overs of a deformed mesh",
       [](const std::vector<std::string>& a, const FrameDevices&, CommandLog& log) {
         return runAnalyzeCommand(a, log);
       },
       analyzeUsage},
      {"check", "check a cage, and the partition of unity on the points of a mesh",
       [](const std::vector<std::string>& a, const FrameDevices&, CommandLog& log) { return runCheckCommand(a, log); },
       checkUsage},
      {"cage", "make a cage that strictly encloses a mesh, with at most N faces, and write it as OBJ",
       [](const std::vector<std::string>& a, const FrameDevices&, CommandLog& log) { return runCageCommand(a, log); },
       cageUsage},
      {"bench", "time the precompute and the per-frame deformation, and compare with the paper's quadrature",
       runBenchCommand, benchUsage},
  };
  return commands;
}

const CliCommand* findCliCommand(const std::string& name) {
  for (const CliCommand& command : cliCommands()) {
    if (name == command.name) return &command;
  }
  return nullptr;
}

bool isCliCommand(const char* firstArgument) {
  if (!firstArgument) return false;
  const std::string name = firstArgument;
  if (name == "--help" || name == "-h" || findCliCommand(name) != nullptr) return true;
  // A bare word that is not a file is a mistyped command: the CLI answers with "did you mean", where the editor
  // would only say it expected files.
  const bool bareWord = !name.empty() && name[0] != '-' && name.find_first_of("./") == std::string::npos;
  return bareWord && !std::filesystem::exists(name);
}

int runCli(int argc, char** argv, const FrameDevices& devices) {
  if (argc < 2) {
    std::cerr << helpUsage() << "\nsomicage: no command given (run 'somicage help')\n";
    return kExitBadInput;
  }
  std::string name = argv[1];
  if (name == "--help" || name == "-h") name = "help";
  const CliCommand* command = findCliCommand(name);
  if (!command) {
    std::string suggestion;
    for (const CliCommand& candidate : cliCommands()) {
      if (editDistance(name, candidate.name) <= 2) suggestion = std::string("did you mean '") + candidate.name + "'? ";
    }
    std::cerr << "somicage: unknown command '" << name << "' (" << suggestion
              << "run 'somicage help' for the commands)\n";
    return kExitBadInput;
  }

  const std::vector<std::string> args(argv + 2, argv + argc);
  const std::string prefix = std::string("somicage ") + command->name + ": ";
  CommandLog log(std::string("somicage ") + command->name);
  catchInterrupt();
  try {
    return log.exitCode(command->run(args, devices, log));
  } catch (const InputError& e) {
    std::cerr << prefix << e.what() << "\n";
    return kExitBadInput;
  } catch (const Cancelled& e) {
    if (interruptRequested()) {
      std::cerr << prefix << "interrupted (Ctrl-C); no output was written\n";
      return kExitInterrupted;
    }
    std::cerr << prefix << e.what() << "\n";
    return kExitFailure;
  } catch (const std::bad_alloc&) {
    std::cerr << prefix << "out of memory (try a mesh with fewer points)\n";
    return kExitFailure;
  } catch (const std::exception& e) {
    std::cerr << prefix << "internal error: " << e.what() << " (please report this with the command line)\n";
    return kExitFailure;
  }
}

}  // namespace somicage
