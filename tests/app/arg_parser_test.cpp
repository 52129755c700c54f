// The option parser of the command line, in-process.
#include "cli/arg_parser.h"

#include <gtest/gtest.h>

#include <cmath>

#include "base/errors.h"

namespace somicage {
namespace {

ArgParser parser() {
  return ArgParser("somicage test", {{"--file", "F", "a file", true},
                                     {"--x", "X", "a number"},
                                     {"--n", "N", "an integer"},
                                     {"--flag", "", "a flag"},
                                     {"--mode", "M", "a choice"}});
}

std::string errorOf(const std::vector<std::string>& args) {
  try {
    ArgParser p = parser();
    p.parse(args);
    p.number("--x", 0);
    p.integer("--n", 0, 1, 8);
    p.choice("--mode", {"a", "b"}, "a");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CliArgParser, ReadsValuesFlagsAndDefaults) {
  ArgParser p = parser();
  p.parse({"--file", "a.obj", "--x=-2.5e-3", "--flag", "--n", "8"});
  EXPECT_EQ(p.text("--file"), "a.obj");
  EXPECT_EQ(p.number("--x", 0), -2.5e-3);
  EXPECT_EQ(p.integer("--n", 1, 1, 8), 8);
  EXPECT_TRUE(p.has("--flag"));
  EXPECT_FALSE(p.has("--mode"));
  EXPECT_EQ(p.choice("--mode", {"a", "b"}, "b"), "b");
  EXPECT_FALSE(p.helpRequested());
}

TEST(CliArgParser, Infinity) {
  for (const char* text : {"inf", "+inf", "Infinity", "-inf", "-INF"}) {
    ArgParser p = parser();
    p.parse({"--file", "f", "--x", text});
    const double value = p.numberOrInfinity("--x", 0);
    EXPECT_TRUE(std::isinf(value)) << text;
    EXPECT_EQ(value < 0, text[0] == '-') << text;
    EXPECT_THROW(p.number("--x", 0), InputError) << "plain numbers are finite";
  }
  ArgParser p = parser();
  p.parse({"--file", "f", "--x", "nan"});
  EXPECT_THROW(p.numberOrInfinity("--x", 0), InputError);
}

TEST(CliArgParser, HelpSkipsRequiredOptions) {
  ArgParser p = parser();
  p.parse({"--help"});
  EXPECT_TRUE(p.helpRequested());
  EXPECT_NE(p.optionHelp().find("--file F"), std::string::npos);
  EXPECT_NE(p.optionHelp().find("(required)"), std::string::npos);
}

TEST(CliArgParser, ErrorsNameTheOptionAndTheFix) {
  EXPECT_EQ(errorOf({"--x", "1"}), "--file: is missing (this command needs --file F; see 'somicage test --help')");
  EXPECT_EQ(errorOf({"--file", "f", "--fag"}),
            "--fag: unknown option (did you mean --flag?; see 'somicage test --help')");
  EXPECT_EQ(errorOf({"--file", "f", "--zzzzzz"}), "--zzzzzz: unknown option (see 'somicage test --help')");
  EXPECT_EQ(errorOf({"--file", "f", "--x", "1,5"}),
            "--x: '1,5' is not a number (give a decimal number such as 0.25; see 'somicage test --help')");
  EXPECT_NE(errorOf({"--file", "f", "--n", "9"}).find("--n: 9 is out of range (give an integer in [1, 8]"),
            std::string::npos);
  EXPECT_NE(errorOf({"--file", "f", "--n", "99999999999999999999"}).find("--n: '99999999999999999999' is not a whole"),
            std::string::npos);
  EXPECT_NE(errorOf({"--file", "f", "--mode", "c"}).find("--mode: 'c' is not a choice (use a or b"), std::string::npos);
  EXPECT_NE(errorOf({"--file", "f", "--file", "g"}).find("--file: is given twice"), std::string::npos);
  EXPECT_NE(errorOf({"--file", "--x", "1"}).find("--file: needs a value"), std::string::npos);
  EXPECT_NE(errorOf({"--file="}).find("--file: has an empty value"), std::string::npos);
  EXPECT_NE(errorOf({"-x"}).find("-x: unexpected argument (options start with --"), std::string::npos);
  EXPECT_NE(errorOf({"--"}).find("--: unexpected argument"), std::string::npos);
}

TEST(CliArgParser, EditDistance) {
  EXPECT_EQ(editDistance("", ""), 0);
  EXPECT_EQ(editDistance("--nu", "--nuu"), 1);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3);
}

}  // namespace
}  // namespace somicage
