#include "game/play/PlayMode.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <iostream>
#include <stdexcept>

#include "effects/Renderer.h"
#include "effects/gl/DebugOutput.h"
#include "effects/gl/Gl.h"
#include "game/capture/ImageFiles.h"
#include "game/capture/Readback.h"
#include "game/cli/ExitCode.h"
#include "game/play/DebugUi.h"
#include "game/play/KeyboardInput.h"
#include "game/play/Window.h"
#include "game/replay/ReplayCheck.h"
#include "game/replay/ReplayWriter.h"
#include "game/session/ReplayHeaderFor.h"

namespace game {

namespace fs = std::filesystem;

FixedStepClock::FixedStepClock(int tick_rate_hz, int max_ticks_per_frame)
    : rate_hz_(tick_rate_hz), max_ticks_(max_ticks_per_frame) {
    if (tick_rate_hz < 1 || max_ticks_per_frame < 1)
        throw std::invalid_argument("FixedStepClock needs a tick rate and a tick limit of at least 1");
}

int FixedStepClock::advance(std::chrono::nanoseconds elapsed) {
    // More than a second adds nothing the tick limit would not drop; the bound keeps
    // the product far from overflow.
    const int64_t ns = std::clamp<int64_t>(elapsed.count(), 0, kNsPerSecond);
    pending_ += ns * rate_hz_;
    const int64_t due = pending_ / kNsPerSecond;
    const int ticks = int(std::min<int64_t>(due, max_ticks_));
    // Behind by more than the limit: drop the whole ticks left rather than catch up later.
    pending_ = due > max_ticks_ ? pending_ % kNsPerSecond : pending_ - ticks * kNsPerSecond;
    return ticks;
}

fs::path screenshot_path(std::chrono::system_clock::time_point when) {
    const std::time_t seconds = std::chrono::system_clock::to_time_t(when);
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(when.time_since_epoch()).count() % 1000;
    std::tm local{};
    localtime_r(&seconds, &local);
    char name[64];
    std::strftime(name, sizeof name, "spindrift_%Y%m%d-%H%M%S", &local);
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, "-%03d.png", int(ms));
    return fs::path("screenshots") / (std::string(name) + suffix);
}

std::vector<std::string> demo_replay_args(const fs::path& replay, uint32_t ticks, const fs::path& out_dir) {
    constexpr uint32_t kEvery = 30;
    std::string frames;
    for (uint32_t t = kEvery; t <= ticks; t += kEvery) {
        if (!frames.empty()) frames += ',';
        frames += std::to_string(t);
    }
    // A replay shorter than the interval still shows its last frame.
    if (frames.empty()) frames = ticks > 0 ? std::to_string(ticks) : "none";
    return {replay.string(), "--headless", "--frames", frames, "--out", out_dir.string()};
}

namespace {

// What drives a window session: where each tick's input comes from and what happens
// after each tick.
struct TickHooks {
    // The input for the next tick, or nothing once the input has run out.
    std::function<std::optional<sim::TickInput>()> next_input;
    // Called after each tick with the (quantised) input that was applied.
    std::function<void(const sim::World&, sim::TickInput)> after_tick;
    // A line for the HUD (recording state, replay progress, a desync).
    std::function<std::string()> status;
    std::function<bool()> recording;
};

class FpsMeter {
public:
    void frame(std::chrono::steady_clock::time_point now) {
        ++frames_;
        const double span_s = std::chrono::duration<double>(now - since_).count();
        if (span_s >= 0.5) {
            fps_ = frames_ / span_s;
            frames_ = 0;
            since_ = now;
        }
    }
    double fps() const { return fps_; }

private:
    std::chrono::steady_clock::time_point since_ = std::chrono::steady_clock::now();
    int frames_ = 0;
    double fps_ = 0.0;
};

// The window, the renderer on it and the UI, and the fixed-step loop that runs them.
class PlayLoop {
public:
    PlayLoop(GameSession& session, const std::string& title)
        : session_(session),
          window_(Window::Options{1280, 720, title, true}),
          renderer_(session.level.scene, *session.world),
          ui_(window_.handle()) {}

    // The keyboard's controls now; none while an ImGui text field has the keys.
    sim::TickInput keyboard_input() {
        if (ui_.wants_keyboard()) return {};
        return input_from_keys([this](int key) { return window_.key_down(key); });
    }

    void run(const TickHooks& hooks);

private:
    void on_key_press(int key);
    void draw_frame(const TickHooks& hooks, Window::Size size);
    void take_screenshot(Window::Size size);

    GameSession& session_;
    Window window_;
    effects::gl::DebugOutput debug_output_;  // driver errors to stderr while the context lives
    effects::Renderer renderer_;
    DebugUi ui_;
    FpsMeter fps_;
    bool paused_ = false;
    bool panel_open_ = false;
    bool screenshot_wanted_ = false;
};

void PlayLoop::run(const TickHooks& hooks) {
    FixedStepClock clock(sim::kTickRateHz);
    sim::World& world = *session_.world;
    bool input_ended = false;
    auto last = std::chrono::steady_clock::now();
    while (!window_.should_close()) {
        Window::Size size = window_.framebuffer_size();
        // A minimised window presents nothing, so vsync no longer paces the loop.
        if (size.width <= 0 || size.height <= 0)
            window_.wait_events(1.0 / sim::kTickRateHz);
        else
            window_.poll_events();
        for (int key : window_.take_key_presses()) on_key_press(key);

        const auto now = std::chrono::steady_clock::now();
        const auto elapsed = std::chrono::duration_cast<std::chrono::nanoseconds>(now - last);
        last = now;
        if (paused_ || input_ended) {
            clock.reset();
        } else {
            for (int n = clock.advance(elapsed); n > 0; --n) {
                std::optional<sim::TickInput> input = hooks.next_input();
                if (!input) {
                    input_ended = true;
                    break;
                }
                const sim::TickInput applied = sim::quantise(*input);
                world.step(applied);
                hooks.after_tick(world, applied);
            }
        }

        size = window_.framebuffer_size();
        if (size.width <= 0 || size.height <= 0) continue;
        draw_frame(hooks, size);
        window_.swap_buffers();
        fps_.frame(std::chrono::steady_clock::now());
    }
}

void PlayLoop::on_key_press(int key) {
    std::optional<UiAction> action = ui_action_for_key(key);
    // Typing into an ImGui field: P and Esc belong to the field.
    if (!action || (ui_.wants_keyboard() && (*action == UiAction::Pause || *action == UiAction::Quit))) return;
    switch (*action) {
        case UiAction::Pause: paused_ = !paused_; break;
        case UiAction::Screenshot: screenshot_wanted_ = true; break;
        case UiAction::ToggleDebugPanel: panel_open_ = !panel_open_; break;
        case UiAction::ToggleProfileTiming:
            renderer_.set_timing(renderer_.timing() == effects::gl::TimingMode::Profile
                                     ? effects::gl::TimingMode::GpuQueries
                                     : effects::gl::TimingMode::Profile);
            break;
        case UiAction::Quit: window_.request_close(); break;
    }
}

void PlayLoop::draw_frame(const TickHooks& hooks, Window::Size size) {
    const sim::World& world = *session_.world;
    renderer_.render(world, effects::RenderOutput{0, size.width, size.height});

    // The UI goes on top of the finished frame in the window's own framebuffer.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, size.width, size.height);
    HudState hud = hud_state(world);
    hud.fps = fps_.fps();
    hud.paused = paused_;
    hud.recording = hooks.recording();
    hud.status = hooks.status();
    hud.passes = renderer_.pass_times();
    ui_.begin_frame();
    ui_.draw_hud(hud);
    if (panel_open_) ui_.draw_debug_panel(renderer_, &panel_open_);
    ui_.end_frame();

    if (screenshot_wanted_) {
        screenshot_wanted_ = false;
        take_screenshot(size);
    }
}

void PlayLoop::take_screenshot(Window::Size size) {
    const fs::path path = screenshot_path(std::chrono::system_clock::now());
    try {
        write_png(path, read_framebuffer_rgba8(0, size.width, size.height));
        std::cout << "screenshot: " << path.string() << std::endl;
    } catch (const std::exception& e) {
        // A full disk should not end the game.
        std::cerr << "screenshot failed: " << e.what() << std::endl;
    }
}

}  // namespace

int play_in_window(GameSession& session, const PlayOptions& options) {
    PlayLoop loop(session, "Spindrift");
    std::optional<ReplayWriter> writer;
    if (options.record) {
        writer.emplace(ReplayWriter::create(*options.record, replay_header_for(session, 480, 270, {})));
        std::cout << "recording to " << writer->partial_path().string() << " (renamed to "
                  << options.record->string() << " at the end)" << std::endl;
    }
    bool recording = writer.has_value();
    TickHooks hooks;
    hooks.next_input = [&]() -> std::optional<sim::TickInput> { return loop.keyboard_input(); };
    hooks.after_tick = [&](const sim::World& world, sim::TickInput applied) {
        if (!recording) return;
        writer->append(applied, world.hash());
        if (writer->ticks() >= kMaxReplayTicks) {
            // The format's limit: keep playing, stop recording.
            writer->finish();
            recording = false;
            std::cout << "recording stopped at the " << kMaxReplayTicks << "-tick limit" << std::endl;
        }
    };
    hooks.status = [] { return std::string(); };
    hooks.recording = [&] { return recording; };
    loop.run(hooks);
    if (recording) writer->finish();
    if (writer)
        std::cout << "recorded " << writer->ticks() << " ticks of level '" << session.world->level().id << "' to "
                  << writer->path().string() << std::endl;
    return kExitOk;
}

int play_replay_in_window(const Replay& replay, GameSession& session) {
    PlayLoop loop(session, "Spindrift - replay");
    ReplayChecker checker(replay);
    std::optional<Divergence> divergence;
    size_t next = 0;
    TickHooks hooks;
    hooks.next_input = [&]() -> std::optional<sim::TickInput> {
        if (next >= replay.inputs.size()) return std::nullopt;
        return replay.inputs[next++];
    };
    hooks.after_tick = [&](const sim::World& world, sim::TickInput) {
        if (divergence) return;
        if ((divergence = checker.after_step(world))) std::cout << "DESYNC at " << divergence->message << std::endl;
    };
    hooks.status = [&] {
        std::string s = "replay " + std::to_string(next) + "/" + std::to_string(replay.inputs.size());
        if (next >= replay.inputs.size()) s += " ended (Esc quits)";
        if (divergence) s += "  DESYNC at tick " + std::to_string(divergence->tick);
        return s;
    };
    hooks.recording = [] { return false; };
    loop.run(hooks);
    std::cout << "replayed " << next << " of " << replay.inputs.size() << " ticks, " << checker.hashes_checked()
              << " hash checks" << (divergence ? ", DESYNC at " + divergence->message : std::string()) << std::endl;
    return divergence ? kExitCheckFailed : kExitOk;
}

}  // namespace game
