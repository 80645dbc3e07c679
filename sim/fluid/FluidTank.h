#pragma once
// The glass tank of liquid (docs/effects/fluid.md): a particle fluid in the tank's frame,
// standing on the pier at the level's tank spot or riding the boat's deck. Thrown
// objects falling into it push the liquid aside; the boat's accelerations slosh it.
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "sim/fluid/ParticleFluid.h"
#include "sim/world/LevelDesc.h"
#include "sim/world/DescribedSubsystem.h"

namespace sim {

class Boat;
class ThrownObjects;

class FluidTank final : public DescribedSubsystem<FluidTank> {
public:
    // Where the tank sits on the boat, in the boat's model space (floor centre); a tank
    // longer than about 1.2 m reaches into the cabin.
    static constexpr glm::vec3 kBoatDeckOffset{-2.35f, 0.55f, 0.0f};  // the aft deck, behind the cabin

    // Throws std::invalid_argument naming the field for unusable parameters.
    FluidTank(const FluidTankDesc& desc, glm::vec3 tank_spot, uint64_t seed);

    static constexpr std::string_view kName = "fluid";
    std::string_view name() const override { return kName; }
    void connect(const SubsystemLinks& links) override;
    void step(StepContext& ctx) override;
    template <class Archive> void describe(Archive& ar) {
        ar.vec(origin_prev_[0]);
        ar.vec(origin_prev_[1]);
        ar.u32(ticks_);
        ar.i32(objects_inside_);
        ar.u32(calm_ticks_);
        ar.boolean(asleep_);
        ar.nested(fluid_);
        ar.unhashed(tank_to_world_);
    }

    const ParticleFluid& fluid() const { return fluid_; }
    const FluidTankDesc& desc() const { return desc_; }
    glm::vec3 inner_size() const { return desc_.inner_size_m; }
    // Tank frame (x, y, z in [0, inner size], y up) to world, as of the last step.
    const glm::mat4& tank_to_world() const { return tank_to_world_; }
    // Objects inside the tank's volume during the last step.
    int objects_inside() const { return objects_inside_; }
    bool asleep() const { return asleep_; }

private:
    glm::mat4 pose() const;  // on the boat when it rides one, else at its spot

    FluidTankDesc desc_;
    glm::vec3 spot_;
    ParticleFluid fluid_;
    glm::mat4 tank_to_world_{1.0f};
    glm::vec3 origin_prev_[2]{};  // the tank origin one and two ticks ago
    uint32_t ticks_ = 0;
    int objects_inside_ = 0;
    // Sleeping (as rigid bodies do): a calm liquid with nothing near it and a still
    // tank is not stepped. Most of the harbour's time the tank just stands there, so it
    // starts asleep as filled, and wakes for the first object or tank motion.
    uint32_t calm_ticks_ = 0;
    bool asleep_ = true;
    std::vector<FluidSphere> spheres_;  // scratch

    // Connected at assembly (connect); nullptr where the world has none.
    const Boat* boat_ = nullptr;
    const ThrownObjects* thrown_ = nullptr;
};

// The glass panes of a tank standing at `spot` (floor centre), as solids for vehicles
// and thrown objects: what flies in over the rim stays in. A tank on the boat has none.
std::vector<Aabb> tank_walls(const FluidTankDesc& desc, glm::vec3 spot);

}  // namespace sim
