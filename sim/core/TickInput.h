#pragma once
// The quantised per-tick player input: what is recorded, replayed and applied.
#include <cstdint>
#include <optional>
#include <string_view>

namespace sim {

// Held controls, one bit each. One-shot actions (switch, throw, fire, ...) fire on the
// tick their bit goes from 0 to 1, so a replay only needs the held state per tick.
enum class Control : uint16_t {
    Throttle = 1u << 0,
    Brake = 1u << 1,
    SteerLeft = 1u << 2,
    SteerRight = 1u << 3,
    SwitchVehicle = 1u << 4,
    ThrowHeavy = 1u << 5,
    ThrowLight = 1u << 6,
    Fire = 1u << 7,
    Camera = 1u << 8,
    Wipers = 1u << 9,
    RainUp = 1u << 10,
    RainDown = 1u << 11,
    Reset = 1u << 12,
};
inline constexpr int kControlCount = 13;
inline constexpr uint16_t kAllControls = (1u << kControlCount) - 1;
// The controls that act once on their rising edge; the rest (throttle, brake,
// steering) act for as long as they are held.
inline constexpr uint16_t kOneShotControls =
    uint16_t(Control::SwitchVehicle) | uint16_t(Control::ThrowHeavy) | uint16_t(Control::ThrowLight) |
    uint16_t(Control::Fire) | uint16_t(Control::Camera) | uint16_t(Control::Wipers) |
    uint16_t(Control::RainUp) | uint16_t(Control::RainDown) | uint16_t(Control::Reset);

// Script / CLI names, index i names bit i.
inline constexpr std::string_view kControlNames[kControlCount] = {
    "throttle", "brake",      "steer_left", "steer_right", "switch_vehicle", "throw_heavy",
    "throw_light", "fire",    "camera",     "wipers",      "rain_up",        "rain_down",
    "reset"};

std::optional<Control> control_from_name(std::string_view name);

// Full scale of the analog axes: a gamepad's trigger or stick is stored in steps of
// 1/255 (throttle, brake) or 1/127 (steering), so that a replay holds exactly what the
// sim applied.
inline constexpr int kPedalFullScale = 255;
inline constexpr int kSteerFullScale = 127;

struct TickInput {
    uint16_t held = 0;  // bitmask of Control
    // Analog driving on top of the held bits (a gamepad); a held Throttle, Brake or
    // Steer* bit counts as full scale, so keyboard input needs none of these.
    uint8_t throttle = 0;  // 0..kPedalFullScale
    uint8_t brake = 0;     // 0..kPedalFullScale
    int8_t steer = 0;      // -kSteerFullScale (right) .. +kSteerFullScale (left), as DriveInput::steer

    bool has(Control c) const { return (held & static_cast<uint16_t>(c)) != 0; }
    void set(Control c, bool on) {
        held = on ? uint16_t(held | uint16_t(c)) : uint16_t(held & ~uint16_t(c));
    }
    bool operator==(const TickInput&) const = default;
};

// Unknown bits are dropped and steering is kept within full scale, so that any recorded
// value is a valid input.
inline TickInput quantise(TickInput in) {
    in.held = uint16_t(in.held & kAllControls);
    if (in.steer < -kSteerFullScale) in.steer = int8_t(-kSteerFullScale);
    return in;
}

// The driving amounts of an input: the larger of a held bit (full scale) and the analog
// axis; steering adds the axis to the bits' difference, within -1..1. Exact in IEEE-754
// (one division by a whole number), so the same input steers the same everywhere.
float throttle_amount(const TickInput& in);
float brake_amount(const TickInput& in);
float steer_amount(const TickInput& in);

}  // namespace sim
