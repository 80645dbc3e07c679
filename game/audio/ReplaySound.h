#pragma once
// A replay's sound rendered offline (spindrift replay FILE --headless --audio OUT.wav,
// the audio tests): after each tick the session's sound mixes one tick of samples
// (800 frames at 48 kHz) through OpenAL's loopback device, the replay's recorded or
// scripted camera the listener.
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "audio/LoopbackRender.h"
#include "audio/WavFile.h"
#include "game/audio/SessionSound.h"
#include "game/replay/ReplayReader.h"
#include "game/session/GameSession.h"
#include "game/session/TickDriver.h"

namespace game {

inline constexpr int kFramesPerTick = audio::kSampleRate / sim::kTickRateHz;

// Pins OpenAL's output-changing settings (audio/alsoft-offline.conf under the data
// directory) and opens its loopback device. Throws std::runtime_error saying why not.
class OfflineSound {
public:
    explicit OfflineSound(CameraTrack cameras, SessionSound::ListenerFor listener = audio::listener_for);
    // One tick: the sound models follow the world, then one tick of samples is rendered.
    const std::vector<float>& after_tick(const sim::World& world);
    SessionSound& sound() { return sound_; }

private:
    SessionSound sound_;
    std::unique_ptr<audio::LoopbackRender> render_;
    std::vector<float> tick_;  // interleaved stereo, kFramesPerTick frames
};

struct SoundRenderOptions {
    uint32_t ticks = 0;  // 0: the whole replay
    audio::Volumes volumes;
    SessionSound::ListenerFor listener = audio::listener_for;
};

// Replays `replay` in `session` (a fresh one) for the ticks asked and returns the sound,
// interleaved stereo at 48 kHz.
std::vector<float> render_replay_sound(const Replay& replay, GameSession& session, const SoundRenderOptions& options);

}  // namespace game
