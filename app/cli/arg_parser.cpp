#include "cli/arg_parser.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "base/errors.h"

namespace somicage {

int editDistance(const std::string& a, const std::string& b) {
  std::vector<int> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (size_t j = 1; j <= b.size(); ++j) {
      const int above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

namespace {

bool parseDouble(std::string text, double& value) {
  if (!text.empty() && text[0] == '+') text.erase(0, 1);
  if (text.empty() || text[0] == '+') return false;
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  return result.ec == std::errc() && result.ptr == end;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

ArgParser::ArgParser(std::string command, std::vector<OptionSpec> options)
    : command_(std::move(command)), options_(std::move(options)) {}

const OptionSpec* ArgParser::find(const std::string& name) const {
  for (const OptionSpec& option : options_) {
    if (option.name == name) return &option;
  }
  return nullptr;
}

void ArgParser::fail(const std::string& source, const std::string& what, const std::string& hint) const {
  throw InputError(source, -1, what, hint + (hint.empty() ? "" : "; ") + "see '" + command_ + " --help'");
}

void ArgParser::parse(const std::vector<std::string>& args) {
  for (size_t k = 0; k < args.size(); ++k) {
    const std::string& arg = args[k];
    if (arg == "--help" || arg == "-h") {
      help_ = true;
      continue;
    }
    if (arg.rfind("--", 0) != 0 || arg.size() == 2) {
      fail(arg, "unexpected argument",
           arg.rfind("-", 0) == 0 ? "options start with --" : "files are given with options, e.g. --mesh FILE");
    }
    const size_t equals = arg.find('=');
    const std::string name = arg.substr(0, equals);
    const OptionSpec* option = find(name);
    if (!option) {
      std::string best;
      int bestDistance = 4;
      for (const OptionSpec& candidate : options_) {
        const int distance = editDistance(name, candidate.name);
        if (distance < bestDistance) bestDistance = distance, best = candidate.name;
      }
      fail(name, "unknown option", best.empty() ? "" : "did you mean " + best + "?");
    }
    if (values_.count(name)) fail(name, "is given twice", "give each option once");
    if (option->valueName.empty()) {
      if (equals != std::string::npos) fail(name, "takes no value", "write just " + name);
      values_[name] = "";
      continue;
    }
    std::string value;
    if (equals != std::string::npos) {
      value = arg.substr(equals + 1);
    } else if (k + 1 < args.size() && args[k + 1].rfind("--", 0) != 0) {
      value = args[++k];
    } else {
      fail(name, "needs a value", "write " + name + " " + option->valueName);
    }
    if (value.empty()) fail(name, "has an empty value", "write " + name + " " + option->valueName);
    values_[name] = value;
  }
  if (help_) return;
  for (const OptionSpec& option : options_) {
    if (option.required && !values_.count(option.name)) {
      fail(option.name, "is missing", "this command needs " + option.name + " " + option.valueName);
    }
  }
}

bool ArgParser::has(const std::string& name) const {
  SOMICAGE_ASSERT(find(name), "option " + name + " is declared");
  return values_.count(name) > 0;
}

std::string ArgParser::text(const std::string& name, const std::string& fallback) const {
  return has(name) ? values_.at(name) : fallback;
}

double ArgParser::number(const std::string& name, double fallback) const {
  if (!has(name)) return fallback;
  const std::string& text = values_.at(name);
  double value = 0.0;
  if (!parseDouble(text, value) || !std::isfinite(value)) {
    fail(name, "'" + text + "' is not a number", "give a decimal number such as 0.25");
  }
  return value;
}

double ArgParser::numberOrInfinity(const std::string& name, double fallback) const {
  if (!has(name)) return fallback;
  const std::string text = lower(values_.at(name));
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (text == "inf" || text == "+inf" || text == "infinity" || text == "+infinity") return kInf;
  if (text == "-inf" || text == "-infinity") return -kInf;
  double value = 0.0;
  if (!parseDouble(text, value) || std::isnan(value)) {
    fail(name, "'" + values_.at(name) + "' is not a number", "give a decimal number, inf or -inf");
  }
  return value;
}

int ArgParser::integer(const std::string& name, int fallback, int min, int max) const {
  if (!has(name)) return fallback;
  const std::string& text = values_.at(name);
  long long value = 0;
  const char* end = text.data() + text.size();
  const auto result = std::from_chars(text.data(), end, value);
  const std::string range = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (result.ec != std::errc() || result.ptr != end) {
    fail(name, "'" + text + "' is not a whole number", "give an integer in " + range);
  }
  if (value < min || value > max) fail(name, text + " is out of range", "give an integer in " + range);
  return static_cast<int>(value);
}

std::string ArgParser::choice(const std::string& name, const std::vector<std::string>& choices,
                              const std::string& fallback) const {
  if (!has(name)) return fallback;
  const std::string& value = values_.at(name);
  if (std::find(choices.begin(), choices.end(), value) != choices.end()) return value;
  std::string list;
  for (size_t k = 0; k < choices.size(); ++k) list += (k ? (k + 1 == choices.size() ? " or " : ", ") : "") + choices[k];
  fail(name, "'" + value + "' is not a choice", "use " + list);
}

std::string ArgParser::optionHelp() const {
  size_t width = 0;
  for (const OptionSpec& option : options_) {
    width = std::max(width, option.name.size() + (option.valueName.empty() ? 0 : option.valueName.size() + 1));
  }
  std::ostringstream out;
  for (const OptionSpec& option : options_) {
    std::string left = option.name + (option.valueName.empty() ? "" : " " + option.valueName);
    left.resize(width, ' ');
    out << "  " << left << "  " << option.help << (option.required ? " (required)" : "") << "\n";
  }
  return out.str();
}

}  // namespace somicage
