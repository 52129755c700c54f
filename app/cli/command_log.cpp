#include "cli/command_log.h"

#include <iostream>

#include "cli/commands.h"

namespace somicage {

std::vector<OptionSpec> withScriptOptions(std::vector<OptionSpec> options) {
  options.push_back(
      {"--quiet", "", "no progress, memory estimate or summary lines on stderr (notes and warnings still print)"});
  options.push_back(
      {"--strict", "", "exit 3 instead of 0 after a warning (points outside the cage, a repaired cage, ...)"});
  return options;
}

CommandLog::CommandLog(std::string command) : command_(std::move(command)) {}

void CommandLog::configure(const ArgParser& args) {
  quiet_ = args.declares("--quiet") && args.has("--quiet");
  strict_ = args.declares("--strict") && args.has("--strict");
}

void CommandLog::notice(const Notice& notice) {
  std::cerr << "somicage: " << describeNotice(notice) << "\n";
  ++warnings_;
}

NoticeSink CommandLog::sink() {
  return [this](const Notice& n) { notice(n); };
}

void CommandLog::listed(int count) { warnings_ += count; }

void CommandLog::note(const std::string& text) const { std::cerr << command_ << ": note: " << text << "\n"; }

void CommandLog::status(const std::string& text) const {
  if (!quiet_) std::cerr << command_ << ": " << text << "\n";
}

ProgressReporter CommandLog::progress(std::string label) const { return ProgressReporter(std::move(label), quiet_); }

int CommandLog::exitCode(int code) const { return strict_ && warnings_ > 0 && code == kExitOk ? kExitWarnings : code; }

}  // namespace somicage
