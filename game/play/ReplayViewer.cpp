#include "game/play/ReplayViewer.h"

#include <imgui.h>

#include <GLFW/glfw3.h>

#include <iostream>

#include "game/cli/ExitCode.h"
#include "game/cli/Progress.h"
#include "game/play/TimelineBar.h"
#include "game/replay/ReplayFormat.h"
#include "sim/player/Player.h"

namespace game {

namespace {
// How long after a marker the timeline still names it.
constexpr uint64_t kMarkerNamedForTicks = 2 * uint64_t(sim::kTickRateHz);
}  // namespace

ReplayViewer::ReplayViewer(const Replay& replay, sim::World& world, TickDriver& ticks, const Screen& screen,
                           ViewerOptions options)
    : replay_(replay),
      world_(world),
      screen_(screen),
      options_(std::move(options)),
      keyframes_(replay.header.level_hash),
      seeker_(replay.inputs, world, keyframes_),
      transport_(seeker_, markers_),
      checker_(replay) {
    // The scan: every tick once, for the markers the timeline shows, the keyframes every
    // seek starts from and the hashes (all of them checked before anything is drawn).
    Progress progress("scanning the replay", replay.inputs.size(), "ticks");
    while (seeker_.step()) {
        markers_.after_tick(world_);
        checked(world_);
        progress.update(world_.tick());
    }
    progress.finish();
    seeker_.seek(0);
    if (divergence_) transport_.toggle_pause();  // a desync: look before playing

    ticks.listen([this](const sim::World& w, sim::TickInput applied) {
        if (!handed_over_) {
            seeker_.after_step();
            checked(w);
            return;
        }
        if (!recording_) return;
        take_over_->append(applied, w);
        if (take_over_->ticks() >= kMaxReplayTicks) {
            finish();  // the format's limit: keep playing, stop recording
            std::cout << "recording stopped at the " << kMaxReplayTicks << "-tick limit" << std::endl;
        }
    });
}

void ReplayViewer::checked(const sim::World& world) {
    if (divergence_) return;
    if ((divergence_ = checker_.after_step(world))) std::cout << "DESYNC at " << divergence_->message << std::endl;
}

bool ReplayViewer::key(int glfw_key) {
    if (handed_over_) return false;
    const bool shift = screen_.key_down(GLFW_KEY_LEFT_SHIFT) || screen_.key_down(GLFW_KEY_RIGHT_SHIFT);
    const std::optional<ViewerKeyAction> action = viewer_action_for_key(glfw_key, shift);
    if (!action) return false;
    act(*action);
    return true;
}

void ReplayViewer::act(const ViewerKeyAction& a) {
    const sim::World& w = world_;
    const uint64_t tick_before = w.tick(), generation_before = w.restore_generation();
    const bool paused_before = transport_.paused();
    switch (a.action) {
        case ViewerAction::TogglePause: transport_.toggle_pause(); break;
        case ViewerAction::StepBack: transport_.step_back(); break;
        case ViewerAction::StepForward: transport_.step_forward(); break;
        case ViewerAction::JumpBack: transport_.jump_seconds(-kViewerJumpSeconds); break;
        case ViewerAction::JumpForward: transport_.jump_seconds(kViewerJumpSeconds); break;
        case ViewerAction::Slower: transport_.slower(); break;
        case ViewerAction::Faster: transport_.faster(); break;
        case ViewerAction::PreviousMarker: transport_.previous_marker(); break;
        case ViewerAction::NextMarker: transport_.next_marker(); break;
        case ViewerAction::Start: transport_.seek_to(0); break;
        case ViewerAction::End: transport_.seek_to(seeker_.ticks()); break;
        case ViewerAction::NextCamera: camera_.next_mode(last_view_, last_vehicle_); break;
        case ViewerAction::Camera: camera_.set_mode(a.camera, last_view_, last_vehicle_); break;
        case ViewerAction::ToggleHud: hud_shown_ = !hud_shown_; break;
        case ViewerAction::TakeOver: take_over(); break;
    }
    if (w.tick() != tick_before || w.restore_generation() != generation_before || transport_.paused() != paused_before)
        jumped_ = true;
}

bool ReplayViewer::settle() {
    if (seek_wanted_ && !handed_over_) {
        if (*seek_wanted_ != world_.tick() || !transport_.paused()) {
            transport_.seek_to(*seek_wanted_);
            jumped_ = true;
        }
    }
    seek_wanted_.reset();
    const bool jumped = jumped_;
    jumped_ = false;
    return jumped;
}

bool ReplayViewer::still() const {
    return !handed_over_ && transport_.paused() && !seek_wanted_ && !camera_moving_ && !jumped_;
}

int ReplayViewer::ticks_due(double dt_s) { return handed_over_ ? 0 : transport_.ticks_due(dt_s); }

// Paused, the world is drawn as it is at its tick.
double ReplayViewer::alpha() const { return transport_.paused() ? 1.0 : transport_.alpha(); }

std::optional<sim::TickInput> ReplayViewer::next_input() const {
    if (handed_over_ || world_.tick() >= replay_.inputs.size()) return std::nullopt;
    return replay_.inputs[size_t(world_.tick())];
}

void ReplayViewer::view(effects::FramePoses& poses) {
    const bool in_car = world_.get<sim::Player>().vehicle() == sim::Vehicle::Car;
    const sim::Pose& vehicle = in_car ? poses.car : poses.boat;
    poses.camera = camera_.view(poses.camera, vehicle, in_car);
    last_view_ = poses.camera;
    last_vehicle_ = vehicle.position;
}

void ReplayViewer::draw(Screen::Size) {
    const auto now = std::chrono::steady_clock::now();
    const float dt_s = std::min(0.1f, std::chrono::duration<float>(now - last_draw_).count());
    last_draw_ = now;
    covered_bottom_px_ = 0.0f;

    // The free and orbit cameras: held keys move them, a drag outside the UI turns them.
    ViewerCameraInput in;
    const auto held = [this](int key) { return screen_.key_down(key) ? 1.0f : 0.0f; };
    in.move = {held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
               held(GLFW_KEY_W) - held(GLFW_KEY_S)};
    in.fast = screen_.key_down(GLFW_KEY_LEFT_SHIFT) || screen_.key_down(GLFW_KEY_RIGHT_SHIFT);
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.WantCaptureMouse) {
        if (io.MouseDown[ImGuiMouseButton_Left] || io.MouseDown[ImGuiMouseButton_Right])
            in.look_px = {io.MouseDelta.x, io.MouseDelta.y};
        in.zoom_steps = io.MouseWheel;
    }
    camera_moving_ = !handed_over_ && (in.move != glm::vec3(0.0f) || io.MouseDown[ImGuiMouseButton_Left] ||
                                       io.MouseDown[ImGuiMouseButton_Right] || in.zoom_steps != 0.0f);
    if (handed_over_) return;  // the keys and the mouse drive now
    camera_.control(in, dt_s);
    if (!hud_shown_) return;
    TimelineState state;
    state.tick = world_.tick();
    state.ticks = seeker_.ticks();
    state.markers = &markers_.markers();
    state.speed = transport_.speed();
    state.paused = transport_.paused();
    state.camera = viewer_camera_name(camera_.mode());
    if (auto m = markers_.previous_before(state.tick + 1); m && state.tick - m->tick < kMarkerNamedForTicks)
        state.note = m->label;
    const TimelineDrawn drawn = draw_timeline(state);
    if (drawn.seek) seek_wanted_ = drawn.seek;
    covered_bottom_px_ = drawn.covered_px;
}

std::string ReplayViewer::status() const {
    std::string s;
    if (divergence_) s += "DESYNC at tick " + std::to_string(divergence_->tick) + "  ";
    if (handed_over_) {
        s += "taken over at tick " + std::to_string(taken_at_);
        if (recording_) s += ", recording to " + options_.record->string();
    }
    return s;
}

void ReplayViewer::take_over() {
    if (handed_over_) return;
    const uint64_t tick = world_.tick();
    if (options_.record) {
        try {
            take_over_.emplace(*options_.record, replay_, tick, world_.level(), options_.threads);
        } catch (const std::exception& e) {
            // The viewer goes on: the player can still watch, the exit code says it failed.
            std::cerr << "error: cannot take over at tick " << tick << ": " << e.what() << std::endl;
            take_over_failed_ = true;
            return;
        }
        recording_ = true;
    }
    handed_over_ = true;
    taken_at_ = tick;
    camera_.set_mode(ViewerCameraMode::Recorded, last_view_, last_vehicle_);  // the player's camera, C switching it
    std::cout << "taken over at tick " << tick << " (" << replay_clock(tick) << ")"
              << (recording_ ? ", recording to " + take_over_->path().string() : std::string()) << std::endl;
}

void ReplayViewer::finish() {
    if (!recording_) return;
    recording_ = false;
    take_over_->finish();
    std::cout << "recorded " << take_over_->ticks() << " ticks (" << taken_at_ << " of the replay's, "
              << take_over_->ticks() - taken_at_ << " played) to " << take_over_->path().string() << std::endl;
}

int watch_replay(const Replay& replay, GameSession& session, Screen& screen, LoopOptions loop,
                 const ViewerOptions& options) {
    TickDriver ticks(*session.world);
    ReplayViewer viewer(replay, *session.world, ticks, screen, options);
    if (LiveSound* sound = loop.sound) ticks.listen([sound](const sim::World& w, sim::TickInput) { sound->after_tick(w); });
    PlayLoop play(session, screen, std::move(loop));
    LoopHooks hooks;
    hooks.ticks = &ticks;
    hooks.viewer = &viewer;
    hooks.next_input = [&] { return viewer.next_input(); };
    hooks.status = [&] { return viewer.status(); };
    hooks.recording = [&] { return viewer.recording(); };
    play.run(hooks);
    viewer.finish();
    std::cout << "watched up to tick " << (viewer.handed_over() ? viewer.taken_at() : session.world->tick()) << " of "
              << replay.inputs.size() << ", " << viewer.hashes_checked() << " hash checks"
              << (viewer.divergence() ? ", DESYNC at " + viewer.divergence()->message : std::string()) << std::endl;
    if (options.record && !viewer.handed_over() && !viewer.take_over_failed())
        std::cout << "no take over (T): nothing recorded to " << options.record->string() << std::endl;
    if (viewer.divergence()) return kExitCheckFailed;
    return viewer.take_over_failed() ? kExitIo : kExitOk;
}

}  // namespace game
