#pragma once
// A replay rendered offline into a video (spindrift replay FILE --video OUT.mp4, the
// video bench): the replay's ticks stepped from the first, and from the range's start
// each frame rendered headless at the video's size and encoded with the sound of its
// ticks. Needs a current GL context (HeadlessContext).
#include <cstdint>
#include <functional>

#include "game/audio/ReplaySound.h"
#include "game/capture/VideoEncoder.h"
#include "game/replay/ReplayReader.h"
#include "game/session/GameSession.h"

namespace game {

// The stretch of the replay a video shows: replay time [from, to) in ticks. Frame k is
// shown from tick from + k * ticks_per_frame() and shows the world after the tick that
// starts then (as play draws the world after each tick's step); the sound track is the
// sound of every tick in the range, as long as the video.
struct VideoRange {
    uint32_t from = 0, to = 0;
    int fps = 60;  // divides the tick rate

    uint32_t ticks_per_frame() const { return uint32_t(sim::kTickRateHz / fps); }
    uint32_t frames() const { return to > from ? (to - from) / ticks_per_frame() : 0; }
    // The tick whose world frame k shows (world.tick() after it).
    uint32_t frame_tick(uint32_t k) const { return from + k * ticks_per_frame() + 1; }
    // The last tick stepped: the range's end rounded down to whole frames.
    uint32_t end_tick() const { return from + frames() * ticks_per_frame(); }
};

// Wall-clock seconds spent in each part of an export.
struct VideoExportTimes {
    double sim = 0, sound = 0, render = 0, encode = 0, total = 0;
};

// Steps `session` (fresh) with `replay`'s inputs up to range.end_tick() and encodes
// range.frames() frames into `encoder` (opened at the size to render), and, when `sound`
// is given, the sound of the range's ticks. `on_frame(k)` after each frame k is encoded.
// Throws VideoError.
VideoExportTimes export_replay_video(const Replay& replay, GameSession& session, VideoEncoder& encoder,
                                     const VideoFormat& format, const VideoRange& range, OfflineSound* sound,
                                     const std::function<void(uint32_t frames_done)>& on_frame = {});

}  // namespace game
