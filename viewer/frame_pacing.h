// When new tessellation data calls for a frame (the window and the progressive benchmark). On a CPU
// device a frame of 1280x720 takes a few milliseconds of every core: drawing the faces of a level
// in progress each time some arrive took those cores from the workers making the level. So a
// completed level is drawn at once (and every frame until it is all uploaded), and the faces of a
// level in progress at most every kPartialFrameMs. Frames the user asks for (input, animation,
// panels) are the caller's business and not paced.
#pragma once

#include <chrono>

namespace cetview {

class FramePacing {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds kPartialFrame{33};

  // `completeLevel`: the consumer's complete level; `newData`: records arrived or uploads pending
  // since the last frame; `uploadsPending`: the scene still has uploads to make.
  bool due(Clock::time_point now, int completeLevel, bool newData, bool uploadsPending) const {
    if (completeLevel != drawnLevel_) return true;        // a level to show
    if (uploadingLevel_ && uploadsPending) return true;   // ... still uploading within its budget
    return newData && now - lastFrame_ >= kPartialFrame;  // a level in progress, paced
  }

  // A frame was drawn at `now` showing `completeLevel`; `uploadsPending` after it.
  void drawn(Clock::time_point now, int completeLevel, bool uploadsPending) {
    uploadingLevel_ = uploadsPending && (completeLevel != drawnLevel_ || uploadingLevel_);
    drawnLevel_ = completeLevel;
    lastFrame_ = now;
  }

  // A new model (or stream) starts at `now`: nothing of it has been drawn, and its first faces
  // wait for level 0 or kPartialFrame, whichever comes first.
  void reset(Clock::time_point now) {
    drawnLevel_ = -1;
    uploadingLevel_ = false;
    lastFrame_ = now;
  }

 private:
  int drawnLevel_ = -1;          // the complete level at the last frame (-1: none yet)
  bool uploadingLevel_ = false;  // the last frame showed a newly complete level that was still uploading
  Clock::time_point lastFrame_{};
};

}  // namespace cetview
