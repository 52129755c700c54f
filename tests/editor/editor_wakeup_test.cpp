// A background worker that finishes wakes the frame loop (wakeOnFinish, app_state.h): the loop sleeps in
// glfwWaitEventsTimeout while nothing happens, so a precompute, a measurement, a nu sweep, a generated cage or an
// export that ends without a wake-up stayed undrawn until the mouse moved (issue 24, row 1). Each worker here calls
// the wake-up once per finished request, after its outcome is ready to be taken; the GUI test
// GuiInput.FinishedWorkIsDrawnWithoutMovingTheMouse shows the pictures.
#include <gtest/gtest.h>

#include <atomic>

#include "core/test_shapes.h"
#include "editor_test_support.h"
#include "jobs/background_job.h"
#include "model/app_state.h"
#include "ui/quantity_overlay.h"

using namespace somicage;
using namespace somicage::editor;

namespace {

TEST(EditorWakeup, AJobsOutcomeIsReadyWhenItsWakeUpRuns) {
  BackgroundJob<int> job;
  std::atomic<int> wakes{0};
  std::atomic<bool> readyAtWake{false};
  job.setOnFinished([&] {
    readyAtWake = job.ready();  // the frame loop, woken, must find the outcome
    ++wakes;
  });
  job.start([](JobContext&) { return 42; }, 1);
  waitUntil([&] { return wakes.load() >= 1; });  // the callback runs on the job's thread once the outcome is stored
  EXPECT_EQ(wakes.load(), 1);
  EXPECT_TRUE(readyAtWake.load());
  EXPECT_EQ(job.poll(), std::optional<int>(42));
}

TEST(EditorWakeup, EveryWorkerOfTheStateWakesTheLoopWhenItFinishes) {
  AppState state;
  std::atomic<int> wakes{0};
  wakeOnFinish(state, [&] { ++wakes; });

  openDemoScene(state);  // the precompute worker: load (the scene is shown at once), then precompute
  waitUntil([&] { return wakes.load() >= 2; });
  EXPECT_EQ(wakes.load(), 2) << "precompute: its scene loaded, then its deformers";

  sweepNuNow(state);  // the measure worker: the nu sweep (the panel's button)
  measureViews(state);
  ASSERT_TRUE(state.jobs.measure.busy());
  waitUntil([&] { return wakes.load() >= 3; });
  EXPECT_EQ(wakes.load(), 3) << "nu sweep";
  measureViews(state);
  EXPECT_EQ(state.view.quantities.nuSweep.size(), 25u);

  // File > Make cage...: a generator that returns at once (the real one is tested in editor_cage_maker_test.cpp).
  state.jobs.cageMaker.setGenerator([](const Eigen::MatrixXd&, const Eigen::MatrixXi&, const CageGenerationOptions&,
                                       const std::string&, const ProgressCallback&) {
    GeneratedCage generated;
    generated.cage = test::makeIcosphere(1);
    generated.cage.vertices *= 10.0;
    return generated;
  });
  openCageMaker(state, 80);
  waitThenPoll(state.jobs.cageMaker);
  waitUntil([&] { return wakes.load() >= 4; });
  EXPECT_EQ(wakes.load(), 4) << "cage generation";
  EXPECT_EQ(state.jobs.cageMaker.status(), CageMaker::Status::Ready);

  ASSERT_TRUE(
      state.jobs.exporter.start("nowhere", "done", [](const ProgressCallback&) { return std::vector<std::string>{}; }));
  ASSERT_TRUE(waitForOutcome(state.jobs.exporter).has_value());
  waitUntil([&] { return wakes.load() >= 5; });
  EXPECT_EQ(wakes.load(), 5) << "export";

  loadSessionFile(state, "/nonexistent/session.json");  // File > Open session: the read's outcome is its error
  waitUntil([&] { return wakes.load() >= 6; });
  EXPECT_EQ(wakes.load(), 6) << "session read";
  EXPECT_TRUE(state.jobs.session.ready()) << "woken before its outcome was there";
}

}  // namespace
