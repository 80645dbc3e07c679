#include "game/capture/VideoExport.h"

#include <chrono>

#include "effects/Renderer.h"
#include "game/capture/FrameCapture.h"
#include "game/replay/CameraTrack.h"
#include "game/session/TickDriver.h"

namespace game {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since) { return std::chrono::duration<double>(Clock::now() - since).count(); }

}  // namespace

VideoExportTimes export_replay_video(const Replay& replay, GameSession& session, VideoEncoder& encoder,
                                     const VideoFormat& format, const VideoRange& range, OfflineSound* sound,
                                     const std::function<void(uint32_t)>& on_frame) {
    const auto start = Clock::now();
    VideoExportTimes times;
    sim::World& world = *session.world;
    // Headless frames as the replay command renders them: the high preset, a render
    // scale of 1, the moving things as of the tick, the replay's cameras.
    effects::Renderer renderer(session.level.scene, world);
    FrameCapture capture(format.width, format.height);
    const CameraTrack cameras(replay.header.camera_shots, replay.header.tick_rate_hz);
    TickDriver driver(world);
    uint32_t frames_done = 0;
    for (uint32_t i = 0; i < range.end_tick(); ++i) {
        auto t = Clock::now();
        driver.step(replay.inputs[i]);
        times.sim += seconds(t);
        const uint32_t tick = uint32_t(world.tick());
        // The sound models follow every tick, before the range too: an engine already
        // running when the video starts sounds like it.
        if (sound) {
            t = Clock::now();
            const std::vector<float>& samples = sound->after_tick(world);
            times.sound += seconds(t);
            if (tick > range.from) {
                t = Clock::now();
                encoder.add_sound(samples.data(), kFramesPerTick);
                times.encode += seconds(t);
            }
        }
        if (tick <= range.from || (tick - range.from - 1) % range.ticks_per_frame() != 0) continue;

        t = Clock::now();
        effects::FramePoses poses = effects::capture_poses(world);
        poses.camera = cameras.view_at(tick, poses.camera);
        renderer.render(world, capture.output(), poses);
        const ImageRGBA8 image = capture.read();
        times.render += seconds(t);
        t = Clock::now();
        encoder.add_frame(image);
        times.encode += seconds(t);
        ++frames_done;
        if (on_frame) on_frame(frames_done);
    }
    const auto t = Clock::now();
    encoder.finish();
    times.encode += seconds(t);
    times.total = seconds(start);
    return times;
}

}  // namespace game
