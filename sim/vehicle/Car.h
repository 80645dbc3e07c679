#pragma once
// The car: a dynamic bicycle model (front steer, rear drive) with saturating tyre
// grip that depends on the surface (road or not), following the ground and decks.
#include "sim/core/Pose.h"
#include "sim/player/Player.h"
#include "sim/world/LevelDesc.h"
#include "sim/world/DescribedSubsystem.h"

namespace sim {

class Player;

struct CarParams {
    float mass_kg = 1300.0f;
    float yaw_inertia_kgm2 = 2000.0f;
    float cg_to_front_m = 1.2f;
    float cg_to_rear_m = 1.4f;
    float cornering_stiffness_npr = 80000.0f;  // per axle, N per radian of slip
    float grip_road = 1.0f;                    // friction coefficient
    float grip_off_road = 0.65f;
    float engine_force_n = 6000.0f;
    float engine_power_w = 90000.0f;
    float brake_force_n = 12000.0f;
    float reverse_speed_mps = 5.0f;
    float drag_coeff = 0.42f;       // N per (m/s)^2
    float rolling_resist_n = 180.0f;
    float engine_braking_n = 500.0f;  // off the throttle the drivetrain slows the car
    float max_steer_rad = 0.55f;
    float steer_rate_radps = 2.5f;
    float radius_m = 1.1f;          // collision circles at front and rear axle
    float height_m = 1.45f;
};

class Car final : public DescribedSubsystem<Car> {
public:
    Car(const Spawn& spawn, CarParams params = {});

    static constexpr std::string_view kName = "car";
    std::string_view name() const override { return kName; }
    void connect(const SubsystemLinks& links) override;
    void step(StepContext& ctx) override;
    template <class Archive> void describe(Archive& ar) {
        ar.fields(pose_);
        ar.f32(u_);
        ar.f32(v_);
        ar.f32(r_);
        ar.f32(steer_);
        ar.f32(wheel_spin_);
        ar.f32(scraping_s_);
        ar.unhashed(accel_);
    }

    const Pose& pose() const { return pose_; }
    glm::vec3 position() const { return pose_.position; }
    glm::vec3 velocity() const;  // world space
    float speed_mps() const { return u_; }  // signed, along the car
    float steer_rad() const { return steer_; }
    float wheel_spin_rad() const { return wheel_spin_; }
    glm::vec2 accel_body_mps2() const { return accel_; }  // longitudinal, lateral: drops lurch with it
    const CarParams& params() const { return p_; }

private:
    void substep(const DriveInput& in, bool reverse, const class Terrain& terrain, float h);
    // Backspace: upright and stopped on the nearest road, along it.
    void reset(const class Terrain& terrain);
    bool fits(const class Terrain& terrain, glm::vec2 xz, float heading_rad) const;
    void touch_solids(const class Terrain& terrain);
    void touch_edges(const class Terrain& terrain);
    // A touch at `offset` from the centre (ground plane) against an obstacle facing `normal`.
    void touch(glm::vec2 offset, glm::vec2 normal);
    void follow_ground(const class Terrain& terrain);

    CarParams p_;
    Pose pose_;
    float u_ = 0.0f;      // forward speed, m/s
    float v_ = 0.0f;      // lateral speed, m/s (positive to the left)
    float r_ = 0.0f;      // yaw rate, rad/s
    float steer_ = 0.0f;  // front wheel angle, rad (positive turns left)
    float wheel_spin_ = 0.0f;
    float scraping_s_ = 0.0f;  // time left of the last contact's hold on the tyres
    // This tick's hardest contact, for the tick report only (not state, not hashed).
    float touch_impulse_ns_ = 0.0f;
    glm::vec2 touch_offset_{0.0f};
    glm::vec2 accel_{0.0f};

    // Connected at assembly (connect).
    const Player* player_ = nullptr;
};

}  // namespace sim
