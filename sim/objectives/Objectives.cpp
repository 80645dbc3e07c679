#include "sim/objectives/Objectives.h"

#include "sim/objects/ThrownObjects.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/weapon/Weapon.h"
#include "sim/world/World.h"

namespace sim {

namespace {
glm::vec2 ground_xz(glm::vec3 p) { return {p.x, p.z}; }
}  // namespace

Objectives::Objectives(const ObjectivesDesc& desc, glm::vec2 car_xz, glm::vec2 boat_xz)
    : targets_(desc.targets), car_xz_(car_xz), boat_xz_(boat_xz) {
    for (const CourseDesc& c : desc.courses) courses_.emplace_back(c);
    for (const TargetDesc& t : desc.targets) target_positions_.push_back(t.position);
}

const Course* Objectives::course_for(CourseVehicle vehicle) const {
    for (const Course& c : courses_)
        if (c.desc().vehicle == vehicle) return &c;
    return nullptr;
}

void Objectives::connect(const SubsystemLinks& links) {
    car_ = &links.need<Car>();
    boat_ = &links.need<Boat>();
    thrown_ = &links.need<ThrownObjects>();
    weapon_ = &links.need<Weapon>();
}

void Objectives::step(StepContext& ctx) {
    const uint64_t ticks = ctx.tick + 1;  // the world's tick count once this step is done
    const glm::vec2 car = ground_xz(car_->position());
    const glm::vec2 boat = ground_xz(boat_->position());
    TickReport& report = ctx.world.report();
    for (size_t i = 0; i < courses_.size(); ++i) {
        Course& c = courses_[i];
        const size_t gate = c.next_gate();
        const uint32_t laps = c.laps();
        if (c.desc().vehicle == CourseVehicle::Car) c.advance(car_xz_, car, ticks);
        else c.advance(boat_xz_, boat, ticks);
        if (c.next_gate() != gate) report.gates.push_back({uint32_t(i), uint32_t(gate), c.laps() != laps});
    }
    car_xz_ = car;
    boat_xz_ = boat;
    targets_.hit_by(thrown_->objects(), weapon_->shots(), ticks);
    for (size_t i = 0; i < targets_.states().size(); ++i)
        if (targets_.states()[i].hit() && targets_.states()[i].hit_at_ticks == ticks)
            report.targets_hit.push_back(target_positions_[i]);
}


}  // namespace sim
