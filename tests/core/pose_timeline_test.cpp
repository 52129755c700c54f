// Keyframe interpolation against closed forms: at a key the cage is the key's pose; the midpoint of a linear pair
// is the mean; Catmull-Rom passes through every key, reproduces motion that is linear in time exactly (unevenly
// spaced keys included) and is C1 across keys; nu and gamma blend linearly, infinities hold. The pose library's
// rules, playback wrapping and the JSON round trip.
#include "animation/pose_timeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "animation/pose_timeline_json.h"
#include "base/errors.h"

namespace somicage {
namespace {

const DeformParams kBase{};

Eigen::MatrixXd randomPose(unsigned seed) {
  std::srand(seed);
  return Eigen::MatrixXd::Random(8, 3);
}

struct Fixture {
  PoseLibrary library;
  Timeline timeline;
  Fixture(const std::vector<double>& frames, Interpolation interpolation) {
    timeline.interpolation = interpolation;
    for (size_t k = 0; k < frames.size(); ++k) {
      const std::string name = "key " + std::to_string(k);
      library.store(name, randomPose(static_cast<unsigned>(k + 1)));
      timeline.setKey({frames[k], name, std::nullopt, std::nullopt});
    }
  }
  Eigen::MatrixXd at(double frame) const { return evaluateTimeline(timeline, library, frame, kBase, 8, 3).cage; }
  const Eigen::MatrixXd& pose(size_t k) const { return library.find("key " + std::to_string(k))->vertices; }
};

TEST(PoseTimeline, AtEveryKeyTheCageIsTheKeyPose) {
  for (const Interpolation interpolation : {Interpolation::Linear, Interpolation::CatmullRom}) {
    const Fixture f({0, 7, 10, 31}, interpolation);
    for (size_t k = 0; k < 4; ++k) EXPECT_LE((f.at(f.timeline.keys[k].frame) - f.pose(k)).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_EQ(f.at(-5), f.pose(0)) << "before the first key, the first key holds";
    EXPECT_EQ(f.at(99), f.pose(3)) << "after the last key, the last key holds";
  }
}

TEST(PoseTimeline, LinearMidpointIsTheMean) {
  const Fixture f({4, 12}, Interpolation::Linear);
  EXPECT_LE((f.at(8) - 0.5 * (f.pose(0) + f.pose(1))).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LE((f.at(6) - (0.75 * f.pose(0) + 0.25 * f.pose(1))).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(PoseTimeline, CatmullRomReproducesMotionLinearInTimeOnUnevenKeys) {
  PoseLibrary library;
  Timeline timeline;
  const Eigen::MatrixXd a = randomPose(11), b = randomPose(12);
  const std::vector<double> frames = {0, 3, 11, 12, 30};
  for (size_t k = 0; k < frames.size(); ++k) {
    library.store("k" + std::to_string(k), a + frames[k] * b);
    timeline.setKey({frames[k], "k" + std::to_string(k), std::nullopt, std::nullopt});
  }
  for (double t = 0; t <= 30; t += 0.37) {
    const Eigen::MatrixXd cage = evaluateTimeline(timeline, library, t, kBase, 8, 3).cage;
    EXPECT_LE((cage - (a + t * b)).cwiseAbs().maxCoeff(), 1e-12) << "t = " << t;
  }
}

TEST(PoseTimeline, CatmullRomIsSmoothAcrossKeys) {
  const Fixture f({0, 5, 13, 20}, Interpolation::CatmullRom);
  const double h = 1e-6;
  for (const double key : {5.0, 13.0}) {
    const Eigen::MatrixXd left = (f.at(key) - f.at(key - h)) / h, right = (f.at(key + h) - f.at(key)) / h;
    EXPECT_LE((left - right).cwiseAbs().maxCoeff(), 1e-4) << "frame " << key;
  }
}

TEST(PoseTimeline, ParametersBlendLinearlyAndInfinityHolds) {
  Fixture f({0, 10, 20}, Interpolation::CatmullRom);
  f.timeline.keys[0].nu = 0.1;
  f.timeline.keys[1].nu = 0.4;
  f.timeline.keys[1].gamma = 2.0;
  f.timeline.keys[2].nu = std::numeric_limits<double>::infinity();
  DeformParams base;
  base.gamma = 1.0;
  const FrameState quarter = evaluateTimeline(f.timeline, f.library, 2.5, base, 8, 3);
  EXPECT_NEAR(quarter.params.nu, 0.175, 1e-15);
  EXPECT_EQ(quarter.params.gamma, 2.0) << "the keys without gamma take key 1's";
  f.timeline.keys[1].gamma.reset();
  EXPECT_EQ(evaluateTimeline(f.timeline, f.library, 2.5, base, 8, 3).params.gamma, 1.0) << "no key sets it: base";
  EXPECT_EQ(evaluateTimeline(f.timeline, f.library, 15, base, 8, 3).params.nu, 0.4);
  EXPECT_TRUE(std::isinf(evaluateTimeline(f.timeline, f.library, 20, base, 8, 3).params.nu));
}

TEST(PoseTimeline, MissingOrMisshapenPosesAreNamed) {
  Fixture f({0, 10}, Interpolation::Linear);
  EXPECT_THROW(evaluateTimeline(f.timeline, f.library, 5, kBase, 9, 3), InputError);
  f.library.remove("key 1");
  try {
    evaluateTimeline(f.timeline, f.library, 5, kBase, 8, 3);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"key 1\""), std::string::npos) << e.what();
  }
  EXPECT_THROW(evaluateTimeline(Timeline{}, f.library, 0, kBase, 8, 3), InputError);
}

TEST(PoseLibrary, StoreRenameDelete) {
  PoseLibrary library;
  library.store("a", Eigen::MatrixXd::Zero(2, 3));
  library.store("b", Eigen::MatrixXd::Ones(2, 3));
  library.store("a", Eigen::MatrixXd::Constant(2, 3, 5));  // replaces, keeps the order
  ASSERT_EQ(library.poses().size(), 2u);
  EXPECT_EQ(library.poses()[0].vertices(0, 0), 5);
  EXPECT_THROW(library.rename("a", "b"), InputError);
  EXPECT_THROW(library.rename("zz", "c"), InputError);
  EXPECT_THROW(library.store("", Eigen::MatrixXd::Zero(2, 3)), InputError);
  library.rename("a", "c");
  EXPECT_EQ(library.poses()[0].name, "c");
  EXPECT_EQ(library.freshName(), "pose 1");
  library.remove("c");
  EXPECT_EQ(library.poses().size(), 1u);
  EXPECT_EQ(library.find("c"), nullptr);
}

TEST(Timeline, KeysStaySortedOnePerFrame) {
  Timeline timeline;
  timeline.setKey({10, "a", std::nullopt, std::nullopt});
  timeline.setKey({2, "b", std::nullopt, std::nullopt});
  timeline.setKey({10, "c", std::nullopt, std::nullopt});
  ASSERT_EQ(timeline.keys.size(), 2u);
  EXPECT_EQ(timeline.keys[0].pose, "b");
  EXPECT_EQ(timeline.keys[1].pose, "c");
}

TEST(Timeline, PlaybackWrapsWhenLoopingAndStopsOtherwise) {
  Timeline timeline;
  timeline.firstFrame = 10;
  timeline.lastFrame = 19;  // 10 frames
  timeline.fps = 5;
  EXPECT_DOUBLE_EQ(playbackFrame(timeline, 10, 1.0), 15);
  EXPECT_DOUBLE_EQ(playbackFrame(timeline, 10, 2.0), 10) << "10 frames at 5 fps: back at the start after 2 s";
  EXPECT_DOUBLE_EQ(playbackFrame(timeline, 12, 2.2), 13);
  timeline.loop = false;
  EXPECT_DOUBLE_EQ(playbackFrame(timeline, 10, 100), 19);
}

TEST(PoseTimelineJson, RoundTripKeepsEverything) {
  Fixture f({0, 6.5, 12}, Interpolation::Linear);
  f.timeline.keys[1].nu = -std::numeric_limits<double>::infinity();
  f.timeline.keys[2].gamma = 0.5;
  f.timeline.fps = 30;
  f.timeline.loop = false;
  const PoseLibrary library = poseLibraryFromJson(parseJson(poseLibraryToJson(f.library).dump(), "t"), "t");
  const Timeline timeline = timelineFromJson(parseJson(timelineToJson(f.timeline).dump(), "t"), "t");
  ASSERT_EQ(library.poses().size(), 3u);
  for (size_t k = 0; k < 3; ++k) EXPECT_EQ(library.poses()[k].vertices, f.library.poses()[k].vertices);
  ASSERT_EQ(timeline.keys.size(), 3u);
  EXPECT_EQ(timeline.keys[1].frame, 6.5);
  EXPECT_EQ(timeline.keys[1].nu, f.timeline.keys[1].nu);
  EXPECT_FALSE(timeline.keys[0].nu.has_value());
  EXPECT_EQ(timeline.keys[2].gamma, 0.5);
  EXPECT_EQ(timeline.interpolation, Interpolation::Linear);
  EXPECT_EQ(timeline.fps, 30);
  EXPECT_FALSE(timeline.loop);
  EXPECT_THROW(timelineFromJson(parseJson(R"({"fps": 0})", "t"), "t"), InputError);
}

}  // namespace
}  // namespace somicage
