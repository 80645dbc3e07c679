#pragma once
// The person playing: which vehicle they are in, how they look, weather controls,
// and this tick's one-shot actions for the subsystems after it.
#include <cstdint>

#include "sim/world/DescribedSubsystem.h"

namespace sim {

class Car;
class Boat;

enum class Vehicle : uint8_t { Car, Boat };
enum class ViewMode : uint8_t { Chase, Driver };
enum class WiperMode : uint8_t { Off, Intermittent, Low, High };

struct DriveInput {
    float throttle = 0.0f;  // 0..1
    float brake = 0.0f;     // 0..1 (also reverse when stopped)
    float steer = 0.0f;     // -1 right .. +1 left
    bool parked = false;    // nobody aboard: hold still, never reverse
};

class Player final : public DescribedSubsystem<Player> {
public:
    static constexpr float kSwitchDistance_m = 18.0f;  // from the road by the pier to the boat
    static constexpr float kRainStep = 0.25f;

    explicit Player(float rain_intensity);

    static constexpr std::string_view kName = "player";
    std::string_view name() const override { return kName; }
    void connect(const SubsystemLinks& links) override;
    void step(StepContext& ctx) override;
    template <class Archive> void describe(Archive& ar) {
        ar.pack8(vehicle_, view_, wipers_);
        ar.f32(rain_intensity_);
        ar.f32(controls_.throttle);
        ar.f32(controls_.brake);
        ar.f32(controls_.steer);
        ar.unhashed(controls_.parked);
        ar.flags(throw_heavy_, throw_light_, fire_, reset_);
    }

    Vehicle vehicle() const { return vehicle_; }
    ViewMode view() const { return view_; }
    WiperMode wipers() const { return wipers_; }
    float rain_intensity() const { return rain_intensity_; }
    // Driving input for a vehicle this tick: the controls if the player is in it,
    // else parked (full brake).
    DriveInput drive_input(Vehicle v) const;
    bool throws_heavy() const { return throw_heavy_; }
    bool throws_light() const { return throw_light_; }
    bool fires() const { return fire_; }
    // Put the player's vehicle back upright and stopped on a road or open water.
    bool resets() const { return reset_; }

private:
    Vehicle vehicle_ = Vehicle::Car;
    ViewMode view_ = ViewMode::Chase;
    WiperMode wipers_ = WiperMode::Off;
    float rain_intensity_ = 0.0f;
    DriveInput controls_;
    bool throw_heavy_ = false, throw_light_ = false, fire_ = false, reset_ = false;

    // Connected at assembly (connect).
    const Car* car_ = nullptr;
    const Boat* boat_ = nullptr;
};

}  // namespace sim
