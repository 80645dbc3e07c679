#pragma once
// The boat: a rigid hull floating on the sea surface. Buoyancy at four hull points
// gives heave, pitch and roll; thrust, rudder and hull drag move it in the plane.
#include "sim/core/Pose.h"
#include "sim/player/Player.h"
#include "sim/world/LevelDesc.h"
#include "sim/world/DescribedSubsystem.h"

namespace sim {

class Player;

struct BoatParams {
    float mass_kg = 1500.0f;
    float length_m = 6.0f;
    float beam_m = 2.4f;
    float waterplane_area_m2 = 11.5f;  // hull area at the waterline
    float thrust_n = 9000.0f;
    float reverse_thrust_n = 4000.0f;
    float drag_long = 60.0f;        // N per (m/s)^2 along the hull
    float drag_lat = 1500.0f;       // N per (m/s)^2 sideways
    float rudder_gain = 0.1f;       // yaw acceleration per (m/s * unit steer)
    float yaw_damping = 2.0f;       // 1/s
    float heave_damping_ratio = 0.4f;
    float planing_pitch_rad = 0.05f;  // bow lift at full speed
    float min_depth_m = 0.7f;       // grounds in shallower water
};

class Boat final : public DescribedSubsystem<Boat> {
public:
    Boat(const Spawn& spawn, BoatParams params = {});
    // Set down in any attitude (a boat dropped in, or knocked over by a wave), at rest.
    explicit Boat(const Pose& start, BoatParams params = {});

    static constexpr std::string_view kName = "boat";
    std::string_view name() const override { return kName; }
    void connect(const SubsystemLinks& links) override;
    void step(StepContext& ctx) override;
    template <class Archive> void describe(Archive& ar) {
        ar.fields(pose_);
        for (float* f : {&u_, &v_, &r_, &heave_rate_, &pitch_rate_, &roll_rate_}) ar.f32(*f);
    }

    const Pose& pose() const { return pose_; }
    glm::vec3 position() const { return pose_.position; }
    glm::vec3 velocity() const;
    float speed_mps() const { return u_; }
    const BoatParams& params() const { return p_; }
    // Hull points used for buoyancy, in model space (x forward, z right).
    static constexpr int kHullPoints = 4;
    glm::vec2 hull_point(int i) const;

private:
    void substep(const DriveInput& in, const class World& world, float h);
    void touch_solids(const class Terrain& terrain);
    void touch_shore(const class Terrain& terrain);
    // A touch at `offset` from the centre (ground plane) against an obstacle facing `normal`.
    void touch(glm::vec2 offset, glm::vec2 normal);
    bool navigable(const class Terrain& terrain, glm::vec2 xz) const;
    // Backspace: upright and stopped on the nearest open water.
    void reset(const class Terrain& terrain);
    bool fits(const class Terrain& terrain, glm::vec2 xz, float heading_rad) const;

    BoatParams p_;
    Pose pose_;
    float u_ = 0.0f, v_ = 0.0f, r_ = 0.0f;  // forward, leftward speed; yaw rate
    float heave_rate_ = 0.0f, pitch_rate_ = 0.0f, roll_rate_ = 0.0f;
    // This tick's hardest contact, for the tick report only (not state, not hashed).
    float touch_impulse_ns_ = 0.0f;
    glm::vec2 touch_offset_{0.0f};

    // Connected at assembly (connect).
    const Player* player_ = nullptr;
};

}  // namespace sim
