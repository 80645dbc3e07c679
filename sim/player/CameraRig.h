#pragma once
// Where the player looks from: a smoothed chase camera behind the vehicle (turned round
// to look the way it goes while it reverses), or the driver's seat. Sim state so that
// replays reproduce every frame exactly.
#include <glm/vec3.hpp>

#include "sim/world/DescribedSubsystem.h"

namespace sim {

class Player;
class Car;
class Boat;

struct CameraView {
    glm::vec3 eye{0.0f, 5.0f, 10.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fov_y_deg = 60.0f;
};

struct CameraRigParams {
    float chase_distance_m = 8.5f;
    float chase_height_m = 3.2f;
    float chase_look_ahead_m = 4.0f;   // look at a point ahead of the vehicle
    float speed_pullback = 0.12f;      // extra distance per m/s
    float follow_rate = 0.08f;         // fraction of the gap closed per tick
    float reverse_look_delay_s = 0.7f;  // reversing this long turns the chase camera round
    float reverse_swing_s = 1.2f;       // the half turn takes this long
    float chase_fov_deg = 60.0f;
    float driver_fov_deg = 70.0f;
};

class CameraRig final : public DescribedSubsystem<CameraRig> {
public:
    explicit CameraRig(CameraRigParams params = {});

    static constexpr std::string_view kName = "camera";
    std::string_view name() const override { return kName; }
    void connect(const SubsystemLinks& links) override;
    void step(StepContext& ctx) override;
    template <class Archive> void describe(Archive& ar) {
        ar.vec(view_.eye);
        ar.vec(view_.target);
        ar.vec(view_.up);
        ar.f32(view_.fov_y_deg);
        ar.vec(chase_eye_);
        ar.vec(chase_target_);
        ar.f32(reversing_s_);
        ar.f32(swing_);
        ar.boolean(looking_back_);
        ar.unhashed(initialised_);
    }

    const CameraView& view() const { return view_; }

private:
    CameraRigParams p_;
    CameraView view_;
    glm::vec3 chase_eye_{0.0f}, chase_target_{0.0f};
    bool initialised_ = false;
    float reversing_s_ = 0.0f;  // how long the vehicle has been moving backwards
    bool looking_back_ = false;
    float swing_ = 0.0f;        // 0 behind the nose .. 1 behind the tail, looking where it reverses


    // Connected at assembly (connect).
    const Player* player_ = nullptr;
    const Car* car_ = nullptr;
    const Boat* boat_ = nullptr;
};

}  // namespace sim
