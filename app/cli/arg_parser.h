// The command-line options of one command: declared once (name, value, help), parsed from argv, read typed.
// Every problem throws somicage::InputError whose source is the option (e.g. "--nu") and whose hint says
// what to give instead, so that runCli can print one line and exit 2.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace somicage {

struct OptionSpec {
  std::string name;       // "--cage"
  std::string valueName;  // "FILE"; empty for a flag that takes no value
  std::string help;       // one line
  bool required = false;
};

class ArgParser {
 public:
  // command: the full command for messages ("somicage deform").
  ArgParser(std::string command, std::vector<OptionSpec> options);

  // Reads "--name value", "--name=value" and flags; --help and -h are always accepted. Throws InputError on an
  // unknown option (suggesting the closest one), a missing value, a value given to a flag, an option given
  // twice, a stray argument, or (unless help was asked for) a missing required option.
  void parse(const std::vector<std::string>& args);

  bool helpRequested() const { return help_; }
  // Whether the command declares the option at all (has() insists that it does).
  bool declares(const std::string& name) const { return find(name) != nullptr; }
  bool has(const std::string& name) const;

  std::string text(const std::string& name, const std::string& fallback = "") const;
  // A finite decimal number.
  double number(const std::string& name, double fallback) const;
  // A decimal number, or inf / +inf / -inf (also "infinity"); never NaN.
  double numberOrInfinity(const std::string& name, double fallback) const;
  // An integer in [min, max].
  int integer(const std::string& name, int fallback, int min, int max) const;
  // One of the given words.
  std::string choice(const std::string& name, const std::vector<std::string>& choices,
                     const std::string& fallback) const;

  // "  --cage FILE     the rest cage (required)" lines, aligned.
  std::string optionHelp() const;

 private:
  const OptionSpec* find(const std::string& name) const;
  [[noreturn]] void fail(const std::string& source, const std::string& what, const std::string& hint) const;

  std::string command_;
  std::vector<OptionSpec> options_;
  std::map<std::string, std::string> values_;
  bool help_ = false;
};

// Edit distance, for "did you mean" suggestions.
int editDistance(const std::string& a, const std::string& b);

}  // namespace somicage
