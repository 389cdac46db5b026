// Frames for tessellation data (frame_pacing.h): a completed level is drawn at once and until it is
// uploaded; the faces of a level in progress at most every 33 ms; nothing new, no frame.
#include "frame_pacing.h"

#include <gtest/gtest.h>

namespace cetview {
namespace {

using std::chrono::milliseconds;

TEST(FramePacing, FacesOfALevelInProgressAreDrawnAtMostEvery33Ms) {
  FramePacing pacing;
  const auto t0 = FramePacing::Clock::now();
  pacing.drawn(t0, -1, false);
  int frames = 0;
  // Faces of level 0 arrive every millisecond for 200 ms.
  for (int ms = 1; ms <= 200; ++ms) {
    const auto now = t0 + milliseconds(ms);
    if (pacing.due(now, -1, true, true)) {
      ++frames;
      pacing.drawn(now, -1, false);
    }
  }
  EXPECT_EQ(frames, 6);  // at 33, 66, ..., 198 ms
}

TEST(FramePacing, ACompletedLevelIsDrawnAtOnceAndUntilItIsUploaded) {
  FramePacing pacing;
  const auto t0 = FramePacing::Clock::now();
  pacing.drawn(t0, -1, false);
  const auto t1 = t0 + milliseconds(1);
  EXPECT_TRUE(pacing.due(t1, 0, true, true));  // level 0 complete 1 ms after the last frame
  pacing.drawn(t1, 0, true);                   // its upload spans frames (the byte budget)
  EXPECT_TRUE(pacing.due(t1 + milliseconds(1), 0, true, true));
  pacing.drawn(t1 + milliseconds(1), 0, false);  // all of it on the GPU
  // Then level 1's faces, paced again.
  EXPECT_FALSE(pacing.due(t1 + milliseconds(2), 0, true, true));
  EXPECT_TRUE(pacing.due(t1 + milliseconds(40), 0, true, true));
}

TEST(FramePacing, NothingNewNoFrame) {
  FramePacing pacing;
  const auto t0 = FramePacing::Clock::now();
  pacing.drawn(t0, 3, false);
  EXPECT_FALSE(pacing.due(t0 + milliseconds(1000), 3, false, false));
  // A new model: its first faces wait for level 0 (or 33 ms), and its level 0 is due even if it
  // is numbered like a level shown before.
  pacing.reset(t0 + milliseconds(1000));
  EXPECT_FALSE(pacing.due(t0 + milliseconds(1001), -1, true, true));
  EXPECT_TRUE(pacing.due(t0 + milliseconds(1002), 0, true, true));
  EXPECT_TRUE(pacing.due(t0 + milliseconds(1040), -1, true, true));
}

}  // namespace
}  // namespace cetview
