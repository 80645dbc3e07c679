#pragma once
// The game's goals (README, Playing): lap the level's courses, the car's on the roads
// and the boat's on the water, against a lap timer, and hit its targets with stones
// and shots. Reads where the vehicles, objects and shots are this tick; changes nothing
// else in the world.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "sim/objectives/Course.h"
#include "sim/objectives/ObjectiveDesc.h"
#include "sim/objectives/Targets.h"
#include "sim/world/DescribedSubsystem.h"

namespace sim {

class Car;
class Boat;
class ThrownObjects;
class Weapon;

class Objectives final : public DescribedSubsystem<Objectives> {
public:
    // The vehicles' positions on the ground at the start: the first move is from there.
    Objectives(const ObjectivesDesc& desc, glm::vec2 car_xz, glm::vec2 boat_xz);

    static constexpr std::string_view kName = "objectives";
    std::string_view name() const override { return kName; }
    void connect(const SubsystemLinks& links) override;
    void step(StepContext& ctx) override;
    template <class Archive> void describe(Archive& ar) {
        for (Course& c : courses_) ar.fields(c);  // as many as the level has
        ar.fields(targets_);
        ar.vec(car_xz_);
        ar.vec(boat_xz_);
    }

    const std::vector<Course>& courses() const { return courses_; }
    const Targets& targets() const { return targets_; }
    // The first course for that vehicle, or none.
    const Course* course_for(CourseVehicle vehicle) const;

private:
    std::vector<Course> courses_;
    Targets targets_;
    std::vector<glm::vec3> target_positions_;  // for the tick report
    glm::vec2 car_xz_, boat_xz_;  // as of the last tick

    // Connected at assembly (connect).
    const Car* car_ = nullptr;
    const Boat* boat_ = nullptr;
    const ThrownObjects* thrown_ = nullptr;
    const Weapon* weapon_ = nullptr;
};

}  // namespace sim
