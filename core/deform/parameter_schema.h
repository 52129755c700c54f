// The one table of deformation parameters (issue 23): for each, its key and its spelling in every front end (the
// CLI's flag and the spellings kept from before, Python's and Blender's keyword, the session's key, the --view
// key), its label and tooltip, its range, default and infinities, and the methods that read it. The CLI's options,
// help and notes, the editor's command line, labels and view specs, sessions, the editor's measurement key and
// Python's somicage.parameter_schema() read this table; the Python keywords, the .pyi stub and the Blender panel
// are checked against it by tests. Adding a parameter is one row here and its use in a method (docs/engine.md,
// "Adding a parameter").
#pragma once

#include <string>
#include <vector>

#include "deform/deform_params.h"

namespace somicage {

enum class ParameterType {
  Number,  // a double in range (text: "0.3", "inf")
  Switch,  // on or off (text: "on"/"off", JSON true/false); its value is 1 or 0
  Choice,  // one of named values (text: the name); its value is the index
};

// A spelling of the command-line option kept from before (or a shorthand): alone it sets `value` (--local: the
// variant local; --no-traction-fix: off); with value null the flag takes a value in the row's syntax
// (--traction-fix on|off).
struct ParameterAlias {
  const char* flag;
  const char* value;
};

// When a view's label (the editor's panes) shows a parameter its method reads.
enum class LabelShow {
  Always,   // "nu=0.45"; a choice by its name alone: "local"
  WhenSet,  // when not its default or the view's own: "no traction fix", "bulging reference"
  Never,    // another row shows it (blend: the variant "blend 0.50")
};

struct ParameterSpec {
  // "traction-fix": the table's name and --view's key. The CLI's flag is --KEY, or for a switch the bare flag that
  // sets what is not its default (--no-traction-fix, --corotational).
  const char* key;
  ParameterType type;
  std::vector<ParameterAlias> cliAliases;  // other spellings the CLI and the editor accept: {"--local", "local"}
  const char* viewKey;                     // --view's key where it differs from key ("traction"); null: key
  const char* pythonKeyword;               // Deformer.deform's keyword and the Blender property: "traction_fix"
  const char* sessionKey;                  // the session's "params" and "views" key: "tractionCorrection"
  const char* label;                       // short, for labels and messages: "Poisson ratio"
  const char* tooltip;                     // one line for help texts and tooltips
  ParameterRange range;                    // Number: the values accepted
  bool openRange;                          // Number: (min, max) instead of [min, max]
  bool infinities;                         // Number: +-inf accepted besides the range (nu's limits, section 5)
  double defaultValue;                     // Number: the value; Switch: 1 or 0; Choice: the index
  std::vector<ChoiceValue> values;         // Choice: the names, index = value
  DeformParameter parameter;               // the methods that read it (MethodDescriptor::parameters)
  LabelShow labelShow;
  // Its field of DeformParams; null for a row registered outside core, whose value lives in DeformParams::extra.
  double (*get)(const DeformParams& params);
  void (*set)(DeformParams& params, double value);
};

// Every parameter, in the order front ends list and apply them (variant before blend: blend overrides it).
const std::vector<ParameterSpec>& parameterSchema();
const ParameterSpec* findParameter(const std::string& key);

// The key --view uses, the CLI's flag ("--nu", "--no-traction-fix", "--corotational") and the name of the value a
// flag that takes one shows in help texts ("V", "NAME", "on|off").
std::string viewKey(const ParameterSpec& spec);
std::string cliFlag(const ParameterSpec& spec);
std::string cliValueName(const ParameterSpec& spec);

// A command-line flag of a row (the CLI's and the editor's): its own flag or an alias.
struct ParameterFlag {
  const ParameterSpec* spec;
  std::string flag;        // "--nu", "--no-traction-fix", "--local"
  const char* fixedValue;  // the text it sets alone ("off", "local"); null when it takes a value
};
// Every flag, in table order (a row's aliases before its own flag, so the own flag wins when both are given).
std::vector<ParameterFlag> parameterFlags();
// Its line of help: "Poisson ratio: ...: a value in (-1, 0.5), or inf / -inf (default 0)", "same as --variant local".
std::string parameterFlagHelp(const ParameterFlag& flag);

// The row's value in params, and setting it (a Choice's set may set more: the variant sets blend too).
double parameterValue(const ParameterSpec& spec, const DeformParams& params);
void setParameter(const ParameterSpec& spec, DeformParams& params, double value);
// Every row's value, in table order: what the editor compares to see whether measurements are stale.
std::vector<double> parameterValues(const DeformParams& params);

// The value of a text ("0.3", "inf", "on", "local"); throws InputError(source, ...) naming what the row takes. A
// number is not checked against its range here: a method's validateParams does that, with its own words first.
double parseParameter(const ParameterSpec& spec, const std::string& text, const std::string& source);
// The text of a value, as parseParameter reads it back.
std::string parameterText(const ParameterSpec& spec, double value);
// What the row takes, for help texts: "V in (-1, 0.5), or inf / -inf", "on or off", "global, local or stable".
std::string parameterSyntax(const ParameterSpec& spec);
// Throws InputError(spec.key, ...) when the value is out of the row's range (NaN included).
void validateParameter(const ParameterSpec& spec, double value);

// Adds a row for the registration's lifetime (tests, plug-ins): every front end that reads the table shows it.
// Not thread-safe: register before front ends run. Its value lives in DeformParams::extra (get and set null).
class ParameterRegistration {
 public:
  explicit ParameterRegistration(ParameterSpec spec);
  ~ParameterRegistration();
  ParameterRegistration(const ParameterRegistration&) = delete;
  ParameterRegistration& operator=(const ParameterRegistration&) = delete;

 private:
  std::string key_;
};

}  // namespace somicage
