#include "game/play/PlayLoop.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <ctime>
#include <iostream>

#include "effects/gl/Gl.h"
#include "game/audio/SettingsVolumes.h"
#include "game/bench/TrivialFill.h"
#include "game/capture/ImageFiles.h"
#include "game/capture/Readback.h"
#include "game/play/FixedStepClock.h"
#include "game/play/GhostHud.h"
#include "game/play/KeyboardInput.h"
#include "game/play/ObjectiveHud.h"
#include "game/play/SoundPanel.h"
#include "game/play/WayfindingHud.h"
#include "game/settings/SettingsFile.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"

namespace game {

namespace fs = std::filesystem;

namespace {
// How long an idle loop sleeps waiting for an event before it looks again.
constexpr double kIdleWaitSeconds = 0.25;
// How long the HUD keeps saying "behind real time" after the spiral cap dropped time.
constexpr auto kBehindShownFor = std::chrono::seconds(1);
// How long the first start's "Esc: menu and controls" stays up (its last second fading).
constexpr auto kHintShownFor = std::chrono::seconds(6);
}  // namespace

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

void PlayLoop::FpsMeter::frame(Clock::time_point now) {
    ++frames_;
    const double span_s = std::chrono::duration<double>(now - since_).count();
    if (span_s >= 0.5) {
        fps_ = frames_ / span_s;
        frames_ = 0;
        since_ = now;
    }
}

PlayLoop::PlayLoop(GameSession& session, Screen& screen, LoopOptions options)
    : session_(session),
      screen_(screen),
      options_(options),
      renderer_(std::in_place, session.level.scene, *session.world),
      ui_(screen.glfw_window()),
      settings_(options.settings) {
    // GL_TIME_ELAPSED queries read ~0 on llvmpipe: measure one pass a frame exactly.
    renderer_->set_timing(effects::gl::TimingMode::Sampled);
    set_quality(options.quality);
    if (options_.sound) options_.sound->set_volumes(mixer_volumes(settings_.volume));
}

void PlayLoop::set_quality(QualityChoice quality) {
    quality_ = quality;
    settings_.quality = quality;
    renderer_->set_quality(preset_of(quality));
    renderer_->set_antialiasing(settings_.fxaa);  // the preset's is off; the player's choice stays
    // Auto draws the scene small: temporal upsampling takes its stairs out.
    renderer_->set_temporal(quality == QualityChoice::Auto);
    resolution_.reset();
    if (quality == QualityChoice::Auto) {
        ResolutionController::Options o;
        o.min_scale = settings_.auto_min_scale;
        o.max_scale = settings_.auto_max_scale;
        o.start_scale = std::clamp(renderer_->render_scale(), o.min_scale, o.max_scale);
        // The budget in this host's fills of the output (a few, about 30 ms in all).
        const Screen::Size size = screen_.size();
        if (size.width > 0 && size.height > 0)
            o.budget_ms = auto_frame_budget_ms(median_ms(trivial_fill_samples(size.width, size.height, 3)));
        resolution_.emplace(o);
        renderer_->set_render_scale(resolution_->scale());
    }
    if (options_.render_scale) {
        resolution_.reset();
        renderer_->set_render_scale(*options_.render_scale);
    }
}

void PlayLoop::run(const LoopHooks& hooks) {
    previous_poses_ = poses_now(*session_.world);
    FixedStepClock clock(sim::kTickRateHz);
    LoopViewer* const viewer = hooks.viewer;
    bool keyboard_drives = !hooks.next_input;
    if (keyboard_drives) queue_start_presses();
    // A replay viewer paces the ticks until the player takes over.
    const auto viewer_paces = [&] { return viewer && !keyboard_drives; };
    // Where the window is once shown (a window manager may place it after it is made).
    std::optional<std::array<int, 4>> placement_at_start;
    bool input_ended = false;
    bool idle_frame_shown = false;
    // The first frame compiles llvmpipe's shader variants: real time, frame times and
    // the resolution controller start after it.
    bool first_frame = true;
    Clock::time_point last_shown{};  // the previous frame, when it was a playing one; else zero
    auto last = Clock::now();
    while (!screen_.should_close()) {
        sim::World& world = *session_.world;  // a restart makes a new one
        const Screen::Size size = screen_.size();
        const bool minimised = size.width <= 0 || size.height <= 0;
        // Paused, minimised, unfocused, or a replay at its end: nothing changes on screen.
        const auto is_idle = [&] {
            return paused_ || menu_.is_open() || minimised || input_ended ||
                   (options_.pause_when_unfocused && !screen_.focused()) ||
                   (viewer_paces() && viewer->still());
        };
        const bool was_idle = is_idle();
        // Idle with its frame shown (or nothing to show): sleep until something happens.
        screen_.handle_events(was_idle && (idle_frame_shown || minimised) ? kIdleWaitSeconds : 0.0);
        for (int key : screen_.take_key_presses()) on_key_press(key, keyboard_drives, viewer);
        if (viewer_paces() && viewer->handed_over()) {
            // A take over: the keyboard drives on from this tick, seen by the player's camera.
            keyboard_drives = true;
            options_.cameras = CameraTrack{};
            input_.clear();
            last = Clock::now();  // the take over's own time (its recording's start) is not played
        }
        if (viewer && viewer->settle()) previous_poses_ = poses_now(world);
        sim::TickInput gamepad;
        const bool gamepad_pressed = read_gamepad(keyboard_drives, gamepad);
        const bool activity = screen_.take_activity() || gamepad_pressed;
        if (ui_.wants_keyboard()) {
            input_.clear();
            input_.set_down({});
        } else {
            sim::TickInput down = input_from_keys(settings_.keys, [this](int key) { return screen_.key_down(key); });
            down.throttle = gamepad.throttle;
            down.brake = gamepad.brake;
            down.steer = gamepad.steer;
            input_.set_down(down);
        }
        const bool idle = is_idle();  // the events may have paused or unfocused it
        if (options_.sound) options_.sound->set_paused(idle);

        const auto now = Clock::now();
        const auto elapsed = std::chrono::duration_cast<std::chrono::nanoseconds>(now - last);
        last = now;
        FrameRecord record;
        if (idle || first_frame) {
            clock.reset();
            input_.clear();
        } else {
            for (sim::Control c : start_presses_) input_.press(c);
            start_presses_.clear();
            const int due = viewer_paces() ? viewer->ticks_due(std::chrono::duration<double>(elapsed).count())
                                         : clock.advance(elapsed);
            for (int n = due; n > 0; --n) {
                std::optional<sim::TickInput> input = keyboard_drives ? input_.next_tick() : hooks.next_input();
                if (!input) {
                    input_ended = true;
                    break;
                }
                previous_poses_ = poses_now(world);
                hooks.ticks->step(*input);
                ++record.ticks;
            }
            record.dropped = clock.dropped();
            if (record.dropped.count() > 0) behind_until_ = now + kBehindShownFor;
        }
        if (input_ended && options_.end_with_input) break;
        if (minimised || (idle && idle_frame_shown && !activity && !screenshot_wanted_)) {
            last_shown = {};
            continue;
        }

        record.render_scale = renderer_->render_scale();
        draw_frame(hooks, screen_.size(), viewer_paces() ? viewer->alpha() : clock.alpha());
        screen_.present();
        const auto shown = Clock::now();
        fps_.frame(shown);
        idle_frame_shown = idle && !menu_.is_open();  // the open menu answers every frame
        if (first_frame) {
            last = shown;
            if (!placement_at_start) placement_at_start = screen_.windowed_placement();
            // A player's run (one with a settings file) shows the hint; a timedemo does not.
            if (options_.settings_file && !settings_.menu_seen && hint_until_ == Clock::time_point{})
                hint_until_ = shown + kHintShownFor;
        }
        if (last_shown != Clock::time_point{} && !idle && !first_frame) {
            record.frame_ms = std::chrono::duration<double, std::milli>(shown - last_shown).count();
            if (resolution_) renderer_->set_render_scale(resolution_->frame(record.frame_ms));
            if (hooks.after_frame) hooks.after_frame(record);
        }
        first_frame = false;
        last_shown = idle ? Clock::time_point{} : shown;
        if (restart_wanted_ && hooks.restart) {
            restart(hooks);
            first_frame = true;
            input_ended = false;
        }
        restart_wanted_ = false;
    }
    // A window moved or resized by the player is where the next start puts it.
    const std::optional<std::array<int, 4>> placement = screen_.windowed_placement();
    if (placement && placement_at_start && placement != placement_at_start) {
        Settings moved = settings_;
        moved.window.x = (*placement)[0];
        moved.window.y = (*placement)[1];
        moved.window.width = (*placement)[2];
        moved.window.height = (*placement)[3];
        change_settings(moved);
    }
}

void PlayLoop::queue_start_presses() {
    start_presses_.clear();
    if (settings_.camera == sim::ViewMode::Driver) start_presses_.push_back(sim::Control::Camera);
    // Each press steps the wipers one mode on from off.
    for (int i = 0; i < int(settings_.wipers); ++i) start_presses_.push_back(sim::Control::Wipers);
}

void PlayLoop::restart(const LoopHooks& hooks) {
    hooks.restart();
    // The effects keep state built up over the course (particles, wet glass): they
    // start again with the world.
    renderer_.reset();
    renderer_.emplace(session_.level.scene, *session_.world);
    renderer_->set_timing(effects::gl::TimingMode::Sampled);
    set_quality(quality_);
    previous_poses_ = poses_now(*session_.world);
    input_.clear();
    paused_ = false;
    queue_start_presses();
}

void PlayLoop::change_settings(const Settings& after) {
    const Settings before = settings_;
    settings_ = after;
    if (after.quality != before.quality || after.auto_min_scale != before.auto_min_scale ||
        after.auto_max_scale != before.auto_max_scale)
        set_quality(after.quality);
    renderer_->set_antialiasing(after.fxaa);
    if (after.vsync != before.vsync) screen_.set_vsync(after.vsync);
    if (after.window.fullscreen != before.window.fullscreen) screen_.set_fullscreen(after.window.fullscreen);
    if (options_.sound && !(after.volume == before.volume)) options_.sound->set_volumes(mixer_volumes(after.volume));
    if (!options_.settings_file) return;
    SettingsFile& file = *options_.settings_file;
    settings_error_.clear();
    if (!file.save(with_changes(file.settings(), before, after), settings_error_))
        std::cerr << "settings: " << settings_error_ << std::endl;
}

void PlayLoop::on_key_press(int key, bool keyboard_drives, LoopViewer* viewer) {
    menu_.tap(key);
    if (menu_.capturing_key()) {
        Settings rebound = settings_;
        menu_.key_pressed(key, rebound);
        change_settings(rebound);
        return;
    }
    if (viewer && !menu_.is_open() && !ui_.wants_keyboard() && viewer->key(key)) return;
    std::optional<UiAction> action = ui_action_for_key(settings_.keys, key);
    if (!action) {
        // Controls pressed while paused are not kept for later.
        std::optional<sim::Control> control = control_for_key(settings_.keys, key);
        if (control && keyboard_drives && !paused_ && !menu_.is_open() && !ui_.wants_keyboard())
            input_.press(*control);
        return;
    }
    // Typing into an ImGui field: P and Esc belong to the field.
    if (ui_.wants_keyboard() && (*action == UiAction::Pause || *action == UiAction::Menu)) return;
    on_ui_action(*action);
}

bool PlayLoop::read_gamepad(bool keyboard_drives, sim::TickInput& axes) {
    GLFWgamepadstate now{};
    // Unplugged: every button up and the axes at rest.
    const bool connected = screen_.read_gamepad(&now);
    if (!connected) now = GLFWgamepadstate{};
    const GamepadPresses presses = gamepad_presses(gamepad_before_, now);
    gamepad_before_ = now;
    axes = connected && keyboard_drives ? gamepad_axes(now) : sim::TickInput{};
    for (UiAction action : presses.actions) on_ui_action(action);
    for (sim::Control control : presses.controls)
        if (keyboard_drives && !paused_ && !menu_.is_open() && !ui_.wants_keyboard()) input_.press(control);
    return !presses.actions.empty() || !presses.controls.empty();
}

void PlayLoop::on_ui_action(UiAction action) {
    switch (action) {
        case UiAction::Menu:
            if (menu_.is_open()) {
                menu_.close();
            } else {
                menu_.open();
                if (!settings_.menu_seen) {
                    Settings seen = settings_;
                    seen.menu_seen = true;
                    change_settings(seen);
                }
            }
            break;
        case UiAction::Pause: paused_ = !paused_; break;
        case UiAction::Screenshot: screenshot_wanted_ = true; break;
        case UiAction::ToggleDebugPanel: panel_open_ = !panel_open_; break;
        case UiAction::ToggleProfileTiming:
            renderer_->set_timing(renderer_->timing() == effects::gl::TimingMode::Profile
                                     ? effects::gl::TimingMode::Sampled
                                     : effects::gl::TimingMode::Profile);
            break;
        case UiAction::ToggleAntialiasing: {
            Settings toggled = settings_;
            toggled.fxaa = !toggled.fxaa;
            change_settings(toggled);
            break;
        }
        case UiAction::Fullscreen: {
            Settings toggled = settings_;
            toggled.window.fullscreen = !screen_.fullscreen();
            change_settings(toggled);
            break;
        }
        case UiAction::ToggleMute:
            if (options_.sound) options_.sound->toggle_mute();
            break;
    }
}

void PlayLoop::draw_frame(const LoopHooks& hooks, Screen::Size size, double alpha) {
    const sim::World& world = *session_.world;
    // `alpha` is how far real time is past the world's last tick, in ticks [0, 1): what
    // moves is drawn that far between its last two ticks, so motion is smooth at any
    // frame rate (and a tick behind: the price of never guessing ahead).
    const effects::FramePoses now = poses_now(world);
    effects::FramePoses poses = effects::interpolate(previous_poses_, now, float(alpha));
    // A scripted cut is a jump, not a move: no frame sweeps between the two views.
    if (world.tick() > 0 && options_.cameras.cuts_between(world.tick() - 1, world.tick())) poses.camera = now.camera;
    if (hooks.viewer) hooks.viewer->view(poses);
    const bool hud_shown = !hooks.viewer || hooks.viewer->hud_shown();
    if (options_.ghost) poses.ghost = options_.ghost->pose_between(float(alpha));
    renderer_->render(world, effects::RenderOutput{screen_.framebuffer(), size.width, size.height}, poses);

    // The UI goes on top of the finished frame at the output's size.
    glBindFramebuffer(GL_FRAMEBUFFER, screen_.framebuffer());
    glViewport(0, 0, size.width, size.height);
    HudState hud = hud_state(world);
    hud.fps = fps_.fps();
    hud.paused = paused_;
    hud.unfocused = options_.pause_when_unfocused && !screen_.focused();
    hud.behind = Clock::now() < behind_until_;
    hud.recording = hooks.recording();
    hud.status = hooks.status();
    hud.quality = quality_choice_name(quality_);
    hud.render_scale = renderer_->render_scale();
    hud.render_width = renderer_->targets().width();
    hud.render_height = renderer_->targets().height();
    ui_.begin_frame(size.width, size.height);
    if (hud_shown) {
        ui_.draw_hud(hud);
        draw_objective_hud(world);
        if (options_.ghost) draw_ghost_hud(*options_.ghost, world.tick());
        // The prompt follows the sim's positions (its rule, at this tick); the marker the
        // drawn ones, so it stays on the vehicle as it moves.
        // Watching a replay, E switches nothing: the prompt is for a player (after a take over).
        const sim::Vehicle aboard = world.get<sim::Player>().vehicle();
        const bool watching = hooks.viewer && !hooks.viewer->handed_over();
        draw_wayfinding(watching ? SwitchPrompt::None
                                 : switch_prompt(aboard, world.get<sim::Car>().position(), world.get<sim::Boat>().position()),
                        vehicle_marker(aboard, poses.car.position, poses.boat.position, poses.camera,
                                       float(size.width), float(size.height),
                                       hooks.viewer ? hooks.viewer->covered_bottom_px() : 0.0f));
    }
    if (hooks.viewer) hooks.viewer->draw(size);
    if (panel_open_) {
        QualityChoice quality = quality_;
        Settings chosen = settings_;
        if (ui_.draw_debug_panel(*renderer_, quality, &panel_open_)) chosen.quality = quality;
        // The panel's volumes are the settings' (the menu's too): one value, saved once changed.
        if (options_.sound) draw_sound_panel(*options_.sound, chosen.volume);
        if (!(chosen == settings_)) change_settings(chosen);
    }
    Settings edited = settings_;
    const PauseMenu::Choice choice = menu_.draw(
        edited, {.can_restart = bool(hooks.restart),
                 .key_down = [this](int key) { return screen_.key_down(key); },
                 .settings_path = options_.settings_file ? options_.settings_file->path().string() : std::string(),
                 .settings_error = settings_error_});
    if (!(edited == settings_)) change_settings(edited);
    if (choice == PauseMenu::Choice::Quit) screen_.request_close();
    if (choice == PauseMenu::Choice::Restart) restart_wanted_ = true;
    if (const auto now = Clock::now(); now < hint_until_ && !menu_.is_open())
        draw_menu_hint(std::chrono::duration<float>(hint_until_ - now).count());
    // The UI's own time (at the output's size), exact one frame in eight: glFinish
    // before and after it, as the renderer's sampled pass times.
    const bool time_ui = ++ui_frames_ % 8 == 0;
    if (time_ui) glFinish();
    const auto ui_start = Clock::now();
    ui_.end_frame();
    if (time_ui) {
        glFinish();
        ui_ms_ = std::chrono::duration<double, std::milli>(Clock::now() - ui_start).count();
    }

    if (screenshot_wanted_) {
        screenshot_wanted_ = false;
        take_screenshot(size);
    }
}

effects::FramePoses PlayLoop::poses_now(const sim::World& world) const {
    effects::FramePoses poses = effects::capture_poses(world);
    poses.camera = options_.cameras.view_at(world.tick(), poses.camera);
    return poses;
}

void PlayLoop::take_screenshot(Screen::Size size) {
    const fs::path path = screenshot_path(std::chrono::system_clock::now());
    try {
        write_png(path, read_framebuffer_rgba8(screen_.framebuffer(), size.width, size.height));
        std::cout << "screenshot: " << path.string() << std::endl;
    } catch (const std::exception& e) {
        // A full disk should not end the game.
        std::cerr << "screenshot failed: " << e.what() << std::endl;
    }
}

}  // namespace game
