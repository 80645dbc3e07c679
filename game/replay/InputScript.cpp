#include "game/replay/InputScript.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <system_error>

namespace game {
namespace {

using std::to_string;

std::vector<std::string_view> split_words(std::string_view line) {
    if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    std::vector<std::string_view> words;
    constexpr std::string_view kSpace = " \t\r\v\f";
    size_t at = line.find_first_not_of(kSpace);
    while (at != std::string_view::npos) {
        const size_t end = std::min(line.find_first_of(kSpace, at), line.size());
        words.push_back(line.substr(at, end - at));
        at = line.find_first_not_of(kSpace, end);
    }
    return words;
}

bool all_digits(std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string valid_control_names() {
    std::string names;
    for (std::string_view name : sim::kControlNames) {
        if (!names.empty()) names += ", ";
        names += name;
    }
    return names;
}

// The analog axes a script can set, as NAME=VALUE: a gamepad's part of the input.
enum AxisBit : uint8_t { kThrottleAxis = 1, kBrakeAxis = 2, kSteerAxis = 4 };

// One timed change: a hold (replaces the held set and the axes from `tick` on) or taps
// (that tick only; an axis a tap names replaces the held one for that tick).
struct ScriptEvent {
    uint32_t tick = 0;
    bool hold = false;
    sim::TickInput input;  // controls and axes
    uint8_t axes = 0;      // AxisBits the line names
    int line = 0;
};

class ScriptParser {
public:
    explicit ScriptParser(std::string_view source) : source_(source) {}

    InputScript parse(std::string_view text) {
        size_t start = 0;
        while (start <= text.size()) {
            size_t end = text.find('\n', start);
            if (end == std::string_view::npos) end = text.size();
            ++line_;
            parse_line(split_words(text.substr(start, end - start)));
            start = end + 1;
        }
        if (end_line_ == 0) {
            line_ = std::max(last_content_line_, 1);
            fail("the script has no 'end' line (its last line must be e.g. '900 end' to run 900 ticks)");
        }
        expand();
        return std::move(script_);
    }

private:
    [[noreturn]] void fail(const std::string& message) const {
        throw ScriptError(std::string(source_) + ":" + to_string(line_) + ": " + message);
    }

    void parse_line(const std::vector<std::string_view>& words) {
        if (words.empty()) return;
        last_content_line_ = line_;
        if (end_line_ != 0)
            fail("'end' must be the last line, but line " + to_string(end_line_) + " already ended the script");
        const std::string_view head = words[0];
        if (head == "level") return parse_level(words);
        if (head == "frames") return parse_frames(words);
        if (head == "checkpoints") return parse_checkpoints(words);
        if (head[0] == '-' || (head[0] >= '0' && head[0] <= '9')) return parse_tick_line(words);
        fail("unknown directive '" + std::string(head) +
             "' (expected level, frames, checkpoints, or a tick number followed by hold, tap, camera or end)");
    }

    void once(int& seen_line, const char* directive) {
        if (seen_line != 0)
            fail(std::string("duplicate '") + directive + "' line (the first is line " + to_string(seen_line) + ")");
        seen_line = line_;
    }

    void parse_level(const std::vector<std::string_view>& words) {
        once(level_line_, "level");
        if (words.size() != 2) fail("'level' takes exactly one level name");
        const std::string_view name = words[1];
        const bool ok = name.size() <= kMaxLevelIdBytes && std::all_of(name.begin(), name.end(), [](char c) {
                            return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                                   c == '_' || c == '-';
                        });
        if (!ok)
            fail("level name '" + std::string(name) + "' must be 1.." + to_string(kMaxLevelIdBytes) +
                 " letters, digits, '_' or '-'");
        script_.level = std::string(name);
    }

    void parse_frames(const std::vector<std::string_view>& words) {
        once(frames_line_, "frames");
        const std::string_view size = words.size() == 2 ? words[1] : std::string_view{};
        const size_t x = size.find('x');
        const std::string_view w = size.substr(0, x), h = x == std::string_view::npos ? "" : size.substr(x + 1);
        auto side = [](std::string_view s) -> std::optional<uint32_t> {
            if (!all_digits(s) || s.size() > 4) return std::nullopt;
            const uint32_t v = uint32_t(std::stoul(std::string(s)));
            if (v < kMinFrameSide || v > kMaxFrameSide) return std::nullopt;
            return v;
        };
        const auto width = side(w), height = side(h);
        if (!width || !height)
            fail("'frames' takes WIDTHxHEIGHT with each side in " + to_string(kMinFrameSide) + ".." +
                 to_string(kMaxFrameSide) + " (e.g. 'frames 480x270')");
        script_.frame_width = *width;
        script_.frame_height = *height;
    }

    void parse_checkpoints(const std::vector<std::string_view>& words) {
        once(checkpoints_line_, "checkpoints");
        if (words.size() < 2) fail("'checkpoints' needs at least one tick number");
        if (words.size() - 1 > kMaxCheckpoints)
            fail("more than " + to_string(kMaxCheckpoints) + " checkpoints on one line");
        for (size_t i = 1; i < words.size(); ++i) {
            const uint32_t tick = parse_tick(words[i], "checkpoint");
            if (!script_.checkpoints.empty() && tick <= script_.checkpoints.back())
                fail("checkpoints must be ascending and unique: " + to_string(tick) + " follows " +
                     to_string(script_.checkpoints.back()));
            script_.checkpoints.push_back(tick);
        }
    }

    uint32_t parse_tick(std::string_view word, const char* what) const {
        if (word[0] == '-' && all_digits(word.substr(1)))
            fail(std::string(what) + " " + std::string(word) + " is negative: ticks count from 0");
        if (!all_digits(word)) fail("'" + std::string(word) + "' is not a " + what + " number");
        // More than 7 digits is above the limit whatever they are; stoul cannot overflow after this.
        const uint32_t tick = word.size() > 7 ? kMaxScriptTick + 1 : uint32_t(std::stoul(std::string(word)));
        if (tick > kMaxScriptTick)
            fail(std::string(what) + " " + std::string(word) + " is above the limit " + to_string(kMaxScriptTick) +
                 " (four hours at 60 Hz)");
        return tick;
    }

    // VALUE of an axis word: a decimal number in [lowest, 1], as the nearest step of 1/full_scale.
    int parse_axis_value(std::string_view name, std::string_view text, float lowest, int full_scale) const {
        float value = 0.0f;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value,
                                                  std::chars_format::fixed);
        if (error != std::errc() || end != text.data() + text.size() || !(value >= lowest && value <= 1.0f))
            fail("'" + std::string(name) + "=" + std::string(text) + "': the value must be a number in " +
                 (lowest < 0.0f ? "-1..1" : "0..1") + " (e.g. '" + std::string(name) + "=0.5')");
        return int(std::lround(value * float(full_scale)));
    }

    // The controls and axes a hold or tap line names.
    void parse_controls(const std::vector<std::string_view>& words, ScriptEvent& event) const {
        for (size_t i = 2; i < words.size(); ++i) {
            const std::string_view word = words[i];
            if (const size_t eq = word.find('='); eq != std::string_view::npos) {
                const std::string_view name = word.substr(0, eq), value = word.substr(eq + 1);
                uint8_t bit = 0;
                if (name == "throttle") {
                    bit = kThrottleAxis;
                    event.input.throttle = uint8_t(parse_axis_value(name, value, 0.0f, sim::kPedalFullScale));
                } else if (name == "brake") {
                    bit = kBrakeAxis;
                    event.input.brake = uint8_t(parse_axis_value(name, value, 0.0f, sim::kPedalFullScale));
                } else if (name == "steer") {
                    bit = kSteerAxis;
                    event.input.steer = int8_t(parse_axis_value(name, value, -1.0f, sim::kSteerFullScale));
                } else {
                    fail("unknown axis '" + std::string(name) + "' (valid: throttle=0..1, brake=0..1, steer=-1..1)");
                }
                if (event.axes & bit) fail("axis '" + std::string(name) + "' is set twice on one line");
                event.axes = uint8_t(event.axes | bit);
                continue;
            }
            const std::optional<sim::Control> control = sim::control_from_name(word);
            if (!control)
                fail("unknown control '" + std::string(word) + "' (valid: " + valid_control_names() +
                     "; axes: throttle=0..1, brake=0..1, steer=-1..1)");
            event.input.set(*control, true);
        }
    }

    void parse_tick_line(const std::vector<std::string_view>& words) {
        const uint32_t tick = parse_tick(words[0], "tick");
        if (have_tick_ && tick < last_tick_)
            fail("tick " + to_string(tick) + " is before the previous tick " + to_string(last_tick_) +
                 ": ticks must not go back");
        if (words.size() < 2) fail("tick " + to_string(tick) + " needs an action: hold, tap, camera or end");
        const std::string_view action = words[1];
        if (action == "end") return parse_end(tick, words);
        if (action == "camera") return parse_camera(tick, words);
        if (action != "hold" && action != "tap")
            fail("unknown action '" + std::string(action) + "' at tick " + to_string(tick) +
                 " (expected hold, tap, camera or end)");
        const bool hold = action == "hold";
        if (!hold && words.size() < 3) fail("'tap' needs at least one control to tap");
        if (hold)
            for (const ScriptEvent& e : events_)
                if (e.hold && e.tick == tick)
                    fail("tick " + to_string(tick) + " already has a 'hold' on line " + to_string(e.line) +
                         ": merge them into one");
        ScriptEvent event{tick, hold, {}, 0, line_};
        parse_controls(words, event);
        events_.push_back(event);
        have_tick_ = true;
        last_tick_ = tick;
    }

    // A camera value: a decimal number.
    float parse_camera_number(std::string_view word, const char* what) const {
        float value = 0.0f;
        const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value,
                                                  std::chars_format::fixed);
        if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value)) {
            // Appended piecewise: "'" + std::string(...) trips a false -Wrestrict in GCC 12.
            std::string message(1, '\'');
            message.append(word).append("' is not a number (the camera's ").append(what).append(")");
            fail(message);
        }
        return value;
    }

    //   T camera look EX EY EZ  TX TY TZ [fov=DEG]
    //   T camera orbit CX CY CZ  RADIUS HEIGHT DEG_PER_S [from=DEG] [fov=DEG]
    //   T camera follow
    void parse_camera(uint32_t tick, const std::vector<std::string_view>& words) {
        static constexpr const char* kForms =
            "'camera look EX EY EZ TX TY TZ [fov=DEG]', 'camera orbit CX CY CZ RADIUS HEIGHT DEG_PER_S "
            "[from=DEG] [fov=DEG]' or 'camera follow'";
        if (!script_.camera_shots.empty() && script_.camera_shots.back().tick == tick)
            fail("tick " + to_string(tick) + " already has a camera line: one camera per tick");
        if (script_.camera_shots.size() >= kMaxCameraShots)
            fail("more than " + to_string(kMaxCameraShots) + " camera lines");
        const std::string_view kind = words.size() > 2 ? words[2] : std::string_view{};
        CameraShot shot;
        shot.tick = tick;
        size_t numbers = 0;
        const char* const* names = nullptr;
        static constexpr const char* kLookNames[] = {"eye x", "eye y", "eye z", "target x", "target y", "target z"};
        static constexpr const char* kOrbitNames[] = {"centre x", "centre y", "centre z",
                                                      "orbit radius", "height", "degrees a second"};
        if (kind == "follow") {
            shot.kind = CameraShotKind::Follow;
        } else if (kind == "look") {
            shot.kind = CameraShotKind::Look;
            numbers = 6;
            names = kLookNames;
        } else if (kind == "orbit") {
            shot.kind = CameraShotKind::Orbit;
            numbers = 6;
            names = kOrbitNames;
        } else {
            fail("a camera line is " + std::string(kForms));
        }
        if (words.size() < 3 + numbers)
            fail("'camera " + std::string(kind) + "' needs " + to_string(numbers) + " numbers: " + kForms);
        float v[6] = {};
        for (size_t i = 0; i < numbers; ++i) v[i] = parse_camera_number(words[3 + i], names[i]);
        if (shot.kind == CameraShotKind::Look) {
            shot.point = {v[0], v[1], v[2]};
            shot.target = {v[3], v[4], v[5]};
        } else if (shot.kind == CameraShotKind::Orbit) {
            shot.point = {v[0], v[1], v[2]};
            shot.radius_m = v[3];
            shot.height_m = v[4];
            shot.deg_per_s = v[5];
        }
        bool fov_seen = false, from_seen = false;
        for (size_t i = 3 + numbers; i < words.size(); ++i) {
            const std::string_view word = words[i];
            const size_t eq = word.find('=');
            const std::string_view name = word.substr(0, eq == std::string_view::npos ? word.size() : eq);
            const std::string_view value = eq == std::string_view::npos ? std::string_view{} : word.substr(eq + 1);
            if (shot.kind != CameraShotKind::Follow && name == "fov" && !fov_seen) {
                shot.fov_deg = parse_camera_number(value, "field of view");
                fov_seen = true;
            } else if (shot.kind == CameraShotKind::Orbit && name == "from" && !from_seen) {
                shot.start_deg = parse_camera_number(value, "start angle");
                from_seen = true;
            } else {
                fail("unexpected '" + std::string(word) + "' on a camera line: " + kForms);
            }
        }
        if (std::string problem = camera_shot_problem(shot); !problem.empty()) fail(problem);
        script_.camera_shots.push_back(shot);
        have_tick_ = true;
        last_tick_ = tick;
    }

    void parse_end(uint32_t tick, const std::vector<std::string_view>& words) {
        if (words.size() != 2) fail("'end' takes no controls");
        if (tick == 0) fail("'0 end' runs no ticks: the end tick must be at least 1");
        if (have_tick_ && tick == last_tick_)
            fail("the script ends at tick " + to_string(tick) + ", so the input given at tick " + to_string(tick) +
                 " would never be applied");
        if (!script_.checkpoints.empty() && script_.checkpoints.back() >= tick)
            fail("checkpoint " + to_string(script_.checkpoints.back()) + " (line " + to_string(checkpoints_line_) +
                 ") is not before the end tick " + to_string(tick));
        script_.end_tick = tick;
        end_line_ = line_;
    }

    // Holds replace the held set and the axes from their tick on; taps add controls to
    // them, and replace the axes they name, at their tick only.
    void expand() {
        script_.inputs.assign(script_.end_tick, sim::TickInput{});
        sim::TickInput held;
        size_t next = 0;
        for (uint32_t t = 0; t < script_.end_tick; ++t) {
            sim::TickInput tapped;
            uint8_t tapped_axes = 0;
            for (; next < events_.size() && events_[next].tick == t; ++next) {
                const ScriptEvent& e = events_[next];
                if (e.hold) {
                    held = e.input;
                    continue;
                }
                tapped.held = uint16_t(tapped.held | e.input.held);
                if (e.axes & kThrottleAxis) tapped.throttle = e.input.throttle;
                if (e.axes & kBrakeAxis) tapped.brake = e.input.brake;
                if (e.axes & kSteerAxis) tapped.steer = e.input.steer;
                tapped_axes = uint8_t(tapped_axes | e.axes);
            }
            sim::TickInput& now = script_.inputs[t];
            now = held;
            now.held = uint16_t(held.held | tapped.held);
            if (tapped_axes & kThrottleAxis) now.throttle = tapped.throttle;
            if (tapped_axes & kBrakeAxis) now.brake = tapped.brake;
            if (tapped_axes & kSteerAxis) now.steer = tapped.steer;
        }
    }

    std::string_view source_;
    InputScript script_;
    std::vector<ScriptEvent> events_;  // in tick order (ticks never go back)
    int line_ = 0;
    int last_content_line_ = 0;
    int level_line_ = 0, frames_line_ = 0, checkpoints_line_ = 0, end_line_ = 0;
    bool have_tick_ = false;
    uint32_t last_tick_ = 0;
};

}  // namespace

InputScript parse_script(std::string_view text, std::string_view source_name) {
    return ScriptParser(source_name).parse(text);
}

InputScript load_script(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (ec) throw ScriptError(name + ": cannot read the input script: " + ec.message());
    if (!std::filesystem::is_regular_file(status))
        throw ScriptError(name + ": cannot read the input script: not a regular file");
    const uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw ScriptError(name + ": cannot read the input script: " + ec.message());
    if (size > kMaxScriptFileBytes)
        throw ScriptError(name + ": the input script is " + to_string(size) + " bytes, more than the 1 MiB allowed");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ScriptError(name + ": cannot open the input script: " + std::strerror(errno));
    // Read at most the limit even if the file grew after the size check.
    std::string text(size_t(std::min(size, kMaxScriptFileBytes)) + 1, '\0');
    in.read(text.data(), std::streamsize(text.size()));
    if (in.bad()) throw ScriptError(name + ": cannot read the input script: " + std::strerror(errno));
    text.resize(size_t(in.gcount()));
    if (text.size() > size) throw ScriptError(name + ": the input script changed while it was read");
    return parse_script(text, name);
}

}  // namespace game
