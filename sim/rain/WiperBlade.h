#pragma once
// A wiper blade in the glass's coordinates (docs/effects/rain.md, "What is implemented"): a segment on an
// arm rotating about a pivot, between radii inner_m and outer_m, swept from its rest
// angle by a fraction 0..1 of its sweep. The blades of a car share one motor
// (WiperMotor), so all of them are at the same fraction.
#include <cmath>

#include <glm/vec2.hpp>

#include "sim/core/DetMath.h"

namespace sim {

struct WiperBladeParams {
    glm::vec2 pivot_m{0.0f};
    float inner_m = 0.1f, outer_m = 0.6f;  // the rubber along the arm
    float rest_rad = 0.0f;                 // angle from +u when parked
    float sweep_rad = 2.0f;                // signed: positive sweeps counter-clockwise (towards +v from +u)
    float half_width_m = 0.006f;           // of the rubber
};

class WiperBlade {
public:
    explicit WiperBlade(WiperBladeParams params)
        : p_(params),
          angle_rad_(params.rest_rad),
          previous_rad_(params.rest_rad),
          direction_(unit(params.rest_rad)),
          previous_direction_(direction_) {}

    // Moves the blade to rest + fraction * sweep; the previous angle is kept for the
    // sweep test of this tick.
    void set_fraction(float fraction) {
        previous_rad_ = angle_rad_;
        previous_direction_ = direction_;
        angle_rad_ = p_.rest_rad + fraction * p_.sweep_rad;
        direction_ = unit(angle_rad_);
    }

    const WiperBladeParams& params() const { return p_; }
    float angle_rad() const { return angle_rad_; }
    float previous_rad() const { return previous_rad_; }
    // Kept with the angles: the particle model asks for them per particle.
    glm::vec2 direction() const { return direction_; }
    glm::vec2 previous_direction() const { return previous_direction_; }
    // +1 turning counter-clockwise this tick, -1 clockwise, 0 still.
    template <class Archive> void describe(Archive& ar) {
        ar.f32(angle_rad_);
        ar.f32(previous_rad_);
        ar.unhashed(direction_);
        ar.unhashed(previous_direction_);
    }

    float turning() const { return angle_rad_ > previous_rad_ ? 1.0f : angle_rad_ < previous_rad_ ? -1.0f : 0.0f; }

private:
    static glm::vec2 unit(float rad) {
        float s, c;
        det::sincos(rad, s, c);
        return {c, s};
    }

    WiperBladeParams p_;
    float angle_rad_, previous_rad_;
    glm::vec2 direction_, previous_direction_;
};

}  // namespace sim
