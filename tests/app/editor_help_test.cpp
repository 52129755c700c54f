// `somicage --help` and `-h` with the editor built: the editor's options (what runs without a command) and the
// command line's commands, in one list (before, only the commands; the editor's options needed another option first).
#include "cli_test_support.h"

namespace somicage {
namespace {

using namespace somicage::test;

TEST(CliHelp, HelpListsTheEditorsOptionsAndTheCommands) {
#ifndef SOMICAGE_TEST_EDITOR
  GTEST_SKIP() << "built without the editor: --help lists the commands only (CliHelp.ListsTheCommands)";
#endif
  for (const std::vector<std::string>& args : {std::vector<std::string>{"--help"}, {"-h"}}) {
    const RunResult r = runSomicage(args);
    EXPECT_EQ(r.exitCode, 0) << r;
    for (const char* editorOption : {"--session", "--screenshot", "--make-cage", "--log-actions", "--view"})
      EXPECT_NE(r.out.find(editorOption), std::string::npos) << editorOption << "\n" << r;
    for (const char* command : {"deform", "check", "bench", "cage"})
      EXPECT_NE(r.out.find("  " + std::string(command)), std::string::npos) << command << "\n" << r;
    EXPECT_TRUE(r.err.empty()) << r;
  }
}

}  // namespace
}  // namespace somicage
