// somicage help [COMMAND]
#include <iostream>
#include <sstream>

#include "base/errors.h"
#include "cli/commands.h"

namespace somicage {

std::string helpUsage() {
  std::ostringstream out;
  out << "somicage: cage-based deformation with Somigliana coordinates\n\n"
      << "usage: somicage COMMAND [OPTIONS]\n"
      << "       somicage [FILE...]      the interactive editor, in builds that have it\n\n"
      << "commands:\n";
  for (const CliCommand& command : cliCommands()) {
    std::string name = command.name;
    name.resize(8, ' ');
    out << "  " << name << command.summary << "\n";
  }
  out << "\nRun 'somicage help COMMAND' or 'somicage COMMAND --help' for the options of a command.\n"
      << "Exit status: 0 success, 1 the command failed or found problems, 2 bad input (options or files),\n"
      << "3 with --strict: done, but a warning was printed (points outside the cage, a repaired cage, ...),\n"
      << "130 stopped by Ctrl-C (nothing written).\n";
  return out.str();
}

int runHelpCommand(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    std::cout << helpUsage();
    return kExitOk;
  }
  if (args.size() > 1) throw InputError(args[1], -1, "unexpected argument", "write 'somicage help COMMAND'");
  const CliCommand* command = findCliCommand(args[0]);
  if (!command) throw InputError(args[0], -1, "is not a command", "run 'somicage help' for the list");
  std::cout << command->usage();
  return kExitOk;
}

}  // namespace somicage
