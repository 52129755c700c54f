// samePath: one file however its path is spelled, as the editor asks when a session names the scene it shows.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "base/file_util.h"
#include "core/scratch_folder.h"

namespace somicage {
namespace {

namespace fs = std::filesystem;

TEST(SamePath, OneFileSpelledRelativeAbsoluteWithDotsOrThroughALinkIsTheSame) {
  const test::ScratchFolder scratch;
  fs::create_directories(scratch / "models");
  std::ofstream(scratch / "models/bunny.obj") << "v 0 0 0\n";
  fs::create_symlink(scratch / "models", scratch / "link");
  const fs::path before = fs::current_path();
  fs::current_path(scratch / "models");
  EXPECT_TRUE(samePath("bunny.obj", scratch / "models/bunny.obj"));
  EXPECT_TRUE(samePath("./../models/bunny.obj", scratch / "models/bunny.obj"));
  EXPECT_TRUE(samePath(scratch / "link/bunny.obj", "bunny.obj"));
  fs::current_path(before);
}

TEST(SamePath, DifferentFilesAndAMissingPathAreNot) {
  const test::ScratchFolder scratch;
  std::ofstream(scratch / "a.obj") << "v 0 0 0\n";
  std::ofstream(scratch / "b.obj") << "v 0 0 0\n";
  EXPECT_FALSE(samePath(scratch / "a.obj", scratch / "b.obj"));
  EXPECT_FALSE(samePath(scratch / "a.obj", ""));
  EXPECT_FALSE(samePath("", scratch / "a.obj"));
  EXPECT_TRUE(samePath("", ""));
  // Files that do not exist (yet): compared by the absolute path they would have.
  EXPECT_TRUE(samePath(scratch / "new/../c.obj", scratch / "c.obj"));
  EXPECT_FALSE(samePath(scratch / "c.obj", scratch / "d.obj"));
}

}  // namespace
}  // namespace somicage
