// The input queue (event_queue.h) and the frame pacing (frame_pacing.h), without a window. The queue is checked
// by feeding its frames to a consumer that, like ImGui 1.86, keeps only each key's state per frame and sees a
// press when the state goes from up to down between frames.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <map>

#include "frame_pacing.h"
#include "interaction/event_queue.h"

using namespace somicage::editor;

namespace {

// A per-frame key-state consumer: counts the presses it can see, in the order seen.
struct StatePerFrame {
  std::map<int, bool> down, before;
  std::vector<int> presses;
  void frame(const std::vector<InputEvent>& events) {
    for (const InputEvent& e : events) {
      if (e.type == InputEvent::Type::Key) down[e.code] = e.action != GLFW_RELEASE;
    }
    for (const auto& [key, isDown] : down) {
      if (isDown && !before[key]) presses.push_back(key);
    }
    before = down;
  }
};

void tap(InputEventQueue& q, int key, int mods = 0) {
  q.push(InputEvent::key(key, 0, GLFW_PRESS, mods));
  q.push(InputEvent::key(key, 0, GLFW_RELEASE, mods));
}

}  // namespace

TEST(EditorEventQueue, PressAndReleaseInsideOneFrameActOnce) {
  InputEventQueue q;
  tap(q, GLFW_KEY_G);
  StatePerFrame consumer;
  // Without the queue's split the consumer sees nothing: press and release cancel out inside one frame.
  {
    StatePerFrame naive;
    naive.frame({InputEvent::key(GLFW_KEY_G, 0, GLFW_PRESS, 0), InputEvent::key(GLFW_KEY_G, 0, GLFW_RELEASE, 0)});
    EXPECT_TRUE(naive.presses.empty());
  }
  int frames = 0;
  while (!q.empty()) {
    consumer.frame(q.takeFrame());
    ++frames;
  }
  EXPECT_EQ(frames, 2);
  EXPECT_EQ(consumer.presses, (std::vector<int>{GLFW_KEY_G}));
}

TEST(EditorEventQueue, EightTapsBetweenTwoFramesAllActInOrder) {
  InputEventQueue q;
  const std::vector<int> typed{GLFW_KEY_F, GLFW_KEY_A, GLFW_KEY_F, GLFW_KEY_F,
                               GLFW_KEY_G, GLFW_KEY_F, GLFW_KEY_A, GLFW_KEY_F};
  for (int k : typed) tap(q, k);
  StatePerFrame consumer;
  while (!q.empty()) consumer.frame(q.takeFrame());
  EXPECT_EQ(consumer.presses, typed);
}

TEST(EditorEventQueue, ChordsStayTogetherAndOtherEventsKeepTheirPlace) {
  InputEventQueue q;
  // Ctrl+Z as `xdotool key ctrl+z` sends it: Ctrl down, Z down, Ctrl up, Z up (the modifier goes first).
  q.push(InputEvent::key(GLFW_KEY_LEFT_CONTROL, 0, GLFW_PRESS, 0));
  q.push(InputEvent::key(GLFW_KEY_Z, 0, GLFW_PRESS, GLFW_MOD_CONTROL));
  q.push(InputEvent::character('z'));
  q.push(InputEvent::key(GLFW_KEY_LEFT_CONTROL, 0, GLFW_RELEASE, GLFW_MOD_CONTROL));
  q.push(InputEvent::key(GLFW_KEY_Z, 0, GLFW_RELEASE, 0));
  q.push(InputEvent::mouseButton(0, GLFW_PRESS, 0));
  q.push(InputEvent::scroll(0, 1));
  q.push(InputEvent::mouseButton(0, GLFW_RELEASE, 0));
  const std::vector<InputEvent> first = q.takeFrame();
  ASSERT_EQ(first.size(), 3u);  // Ctrl and Z down together (Z is seen with Ctrl held), with the character
  EXPECT_EQ(first[0].code, GLFW_KEY_LEFT_CONTROL);
  EXPECT_EQ(first[1].code, GLFW_KEY_Z);
  EXPECT_EQ(first[2].type, InputEvent::Type::Char);
  const std::vector<InputEvent> second = q.takeFrame();
  ASSERT_EQ(second.size(), 4u);  // the releases, then the click's press and the scroll
  EXPECT_EQ(second[0].code, GLFW_KEY_LEFT_CONTROL);
  EXPECT_EQ(second[2].type, InputEvent::Type::MouseButton);
  EXPECT_EQ(second[2].action, GLFW_PRESS);
  EXPECT_EQ(second[3].type, InputEvent::Type::Scroll);
  const std::vector<InputEvent> third = q.takeFrame();
  ASSERT_EQ(third.size(), 1u);
  EXPECT_EQ(third[0].action, GLFW_RELEASE);
  EXPECT_TRUE(q.empty());
}

TEST(EditorEventQueue, AChordIsSeenWithItsModifierByAPerFrameConsumer) {
  InputEventQueue q;
  q.push(InputEvent::key(GLFW_KEY_LEFT_CONTROL, 0, GLFW_PRESS, 0));
  q.push(InputEvent::key(GLFW_KEY_S, 0, GLFW_PRESS, GLFW_MOD_CONTROL));
  q.push(InputEvent::key(GLFW_KEY_LEFT_CONTROL, 0, GLFW_RELEASE, GLFW_MOD_CONTROL));
  q.push(InputEvent::key(GLFW_KEY_S, 0, GLFW_RELEASE, 0));
  StatePerFrame consumer;
  bool ctrlHeldWhenSPressed = false;
  while (!q.empty()) {
    consumer.frame(q.takeFrame());
    if (std::find(consumer.presses.begin(), consumer.presses.end(), GLFW_KEY_S) != consumer.presses.end()) {
      ctrlHeldWhenSPressed = consumer.down[GLFW_KEY_LEFT_CONTROL];
      break;
    }
  }
  EXPECT_TRUE(ctrlHeldWhenSPressed);
}

TEST(EditorEventQueue, TypedTextGoesInAtOnceWhileATextFieldHasTheKeyboard) {
  InputEventQueue q;
  for (int k : {GLFW_KEY_A, GLFW_KEY_B, GLFW_KEY_A}) {
    q.push(InputEvent::key(k, 0, GLFW_PRESS, 0));
    q.push(InputEvent::character(static_cast<unsigned>('a' + (k - GLFW_KEY_A))));
    q.push(InputEvent::key(k, 0, GLFW_RELEASE, 0));
  }
  q.push(InputEvent::key(GLFW_KEY_BACKSPACE, 0, GLFW_PRESS, 0));
  q.push(InputEvent::key(GLFW_KEY_BACKSPACE, 0, GLFW_RELEASE, 0));
  const std::vector<InputEvent> first = q.takeFrame(true);
  ASSERT_EQ(first.size(), 10u);  // the three letters and Backspace's press; its release is the next frame's
  EXPECT_EQ(first[7].code, 'a');
  EXPECT_EQ(first.back().code, GLFW_KEY_BACKSPACE);
  EXPECT_EQ(q.takeFrame(true).size(), 1u);
}

// Issue 24, row 6: Ctrl+A after a click into a path field did not select all. While typing, printable keys went in
// without splitting frames, Ctrl+A's too: its press and release fell in one frame and ImGui never saw A down.
TEST(EditorEventQueue, AShortcutWhileTypingIsSeenWithItsModifier) {
  InputEventQueue q;
  q.push(InputEvent::key(GLFW_KEY_LEFT_CONTROL, 0, GLFW_PRESS, 0));
  tap(q, GLFW_KEY_A, GLFW_MOD_CONTROL);
  q.push(InputEvent::key(GLFW_KEY_LEFT_CONTROL, 0, GLFW_RELEASE, GLFW_MOD_CONTROL));
  tap(q, GLFW_KEY_X);  // typed text after it still goes in at once
  q.push(InputEvent::character('x'));
  StatePerFrame consumer;
  bool ctrlHeldWhenAPressed = false;
  int frames = 0;
  while (!q.empty() && frames < 10) {
    ++frames;
    consumer.frame(q.takeFrame(true));
    if (!ctrlHeldWhenAPressed &&
        std::find(consumer.presses.begin(), consumer.presses.end(), GLFW_KEY_A) != consumer.presses.end())
      ctrlHeldWhenAPressed = consumer.down[GLFW_KEY_LEFT_CONTROL];
  }
  EXPECT_TRUE(ctrlHeldWhenAPressed);
  EXPECT_TRUE(q.empty());
}

TEST(EditorFramePacing, DrawsForInputThenSettlesThenSleeps) {
  FramePacer pacer;
  FrameDemand idle;
  int drawn = 0;
  while (pacer.shouldDraw(idle)) ++drawn;  // the start settles
  EXPECT_EQ(drawn, FramePacer::kSettleFrames);
  EXPECT_EQ(pacer.waitSeconds(idle), FramePacer::kIdleSeconds);  // asleep until an event

  FrameDemand input;
  input.input = true;
  EXPECT_TRUE(pacer.shouldDraw(input));
  drawn = 0;
  while (pacer.shouldDraw(idle)) ++drawn;
  EXPECT_EQ(drawn, FramePacer::kSettleFrames - 1);  // a few frames after the input, then none

  FrameDemand busy;
  busy.busy = true;
  EXPECT_TRUE(pacer.shouldDraw(busy));
  EXPECT_EQ(pacer.waitSeconds(busy), FramePacer::kBusySeconds);  // the progress bar at 2 Hz, not a spin
  FrameDemand pending;
  pending.changing = true;
  EXPECT_TRUE(pacer.shouldDraw(pending));
  EXPECT_EQ(pacer.waitSeconds(pending), 0.0);
  FrameDemand queued;
  queued.queued = true;
  EXPECT_EQ(pacer.waitSeconds(queued), 0.0);
}
