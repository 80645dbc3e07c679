#pragma once
// Spheres the player throws: heavy ones (stone) sink, light ones (cork) float. They
// fly, bounce on ground and solids, and report when they enter the water.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sim/world/DescribedSubsystem.h"

namespace sim {

class Player;
class Car;
class Boat;

struct ThrownObject {
    glm::vec3 position{0.0f};
    glm::vec3 velocity{0.0f};
    float radius_m = 0.25f;
    float density_kgm3 = 2500.0f;
    float mass_kg = 0.0f;
    uint32_t age_ticks = 0;
    bool in_water = false;      // centre below the surface since the last entry
    bool entered_this_tick = false;
    glm::vec3 entry_position{0.0f};
    glm::vec3 entry_velocity{0.0f};
    // The water's horizontal (orbital) velocity where the object floats, built up from
    // the surface slope it has felt since it got wet; its drag is against this.
    glm::vec2 water_velocity{0.0f};
    bool sinks() const { return density_kgm3 > 1000.0f; }

    template <class Archive> void describe(Archive& ar) {
        ar.vec(position);
        ar.vec(velocity);
        ar.f32(radius_m);
        ar.f32(density_kgm3);
        ar.u32(age_ticks);
        ar.boolean(in_water);
        ar.vec(water_velocity);
        ar.unhashed(mass_kg);
        ar.unhashed(entered_this_tick);
        ar.unhashed(entry_position);
        ar.unhashed(entry_velocity);
    }
};

struct ThrowKind {
    float radius_m;
    float density_kgm3;
    float speed_mps;  // launch speed relative to the thrower
};

class ThrownObjects final : public DescribedSubsystem<ThrownObjects> {
public:
    static constexpr size_t kMaxObjects = 32;  // the oldest goes when a new one is thrown
    static constexpr ThrowKind kHeavy{0.22f, 2600.0f, 11.0f};  // a stone
    static constexpr ThrowKind kLight{0.30f, 240.0f, 12.0f};   // a cork float

    static constexpr std::string_view kName = "objects";
    std::string_view name() const override { return kName; }
    void connect(const SubsystemLinks& links) override;
    void step(StepContext& ctx) override;
    template <class Archive> void describe(Archive& ar) {
        ar.size32(objects_);
        for (ThrownObject& o : objects_) ar.fields(o);
    }

    // Adds an object; the thrower's position, facing and velocity set its launch.
    void launch(const ThrowKind& kind, glm::vec3 from, glm::vec3 forward, glm::vec3 carrier_velocity);
    const std::vector<ThrownObject>& objects() const { return objects_; }

private:
    std::vector<ThrownObject> objects_;  // oldest first

    // Connected at assembly (connect).
    const Player* player_ = nullptr;
    const Car* car_ = nullptr;
    const Boat* boat_ = nullptr;
};

// Submerged volume of a sphere of radius r whose centre is `depth` below the surface.
float submerged_sphere_volume(float radius, float depth);

}  // namespace sim
