#include "sim/core/TickInput.h"

#include <algorithm>

namespace sim {

std::optional<Control> control_from_name(std::string_view name) {
    for (int i = 0; i < kControlCount; ++i)
        if (kControlNames[i] == name) return static_cast<Control>(1u << i);
    return std::nullopt;
}

namespace {
float pedal(bool held, uint8_t axis) { return held ? 1.0f : float(axis) / float(kPedalFullScale); }
}  // namespace

float throttle_amount(const TickInput& in) { return pedal(in.has(Control::Throttle), in.throttle); }

float brake_amount(const TickInput& in) { return pedal(in.has(Control::Brake), in.brake); }

float steer_amount(const TickInput& in) {
    const float keys = (in.has(Control::SteerLeft) ? 1.0f : 0.0f) - (in.has(Control::SteerRight) ? 1.0f : 0.0f);
    if (in.steer == 0) return keys;  // the keyboard's path: exactly -1, 0 or 1
    return std::clamp(keys + float(in.steer) / float(kSteerFullScale), -1.0f, 1.0f);
}

}  // namespace sim
