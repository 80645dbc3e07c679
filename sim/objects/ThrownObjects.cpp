#include "sim/objects/ThrownObjects.h"

#include <algorithm>
#include <cmath>

#include "sim/player/Player.h"
#include "sim/vehicle/Boat.h"
#include "sim/vehicle/Car.h"
#include "sim/world/Terrain.h"
#include "sim/world/World.h"

namespace sim {

namespace {
constexpr float kGravity = 9.81f;
constexpr float kWaterDensity = 1000.0f;
constexpr float kAirDensity = 1.2f;
constexpr float kPi = 3.14159265f;
constexpr int kSubsteps = 4;
constexpr float kMinSlopeBase_m = 0.25f;        // about the harbour grid's spacing
constexpr float kWaterVelocityLeak_per_s = 0.2f;

// The highest top of the solids under `xz` that lie below `bottom`, or -inf.
float solid_top_below(const std::vector<Aabb>& solids, glm::vec2 xz, float bottom) {
    float top = -INFINITY;
    for (const Aabb& b : solids)
        if (b.contains_xz(xz) && b.max.y <= bottom + 1e-4f) top = std::max(top, b.max.y);
    return top;
}

void step_object(ThrownObject& o, const World& world, float dt) {
    const Terrain& terrain = world.terrain();
    const float r = o.radius_m;
    const float volume = 4.0f / 3.0f * kPi * r * r * r;
    const float area = kPi * r * r;
    o.entered_this_tick = false;
    float h = dt / kSubsteps;
    for (int i = 0; i < kSubsteps; ++i) {
        const SeaSurface& surface = world.sea();
        float sea = surface.height_at({o.position.x, o.position.z});
        float sub = submerged_sphere_volume(r, sea - o.position.y);
        float wet = sub / volume;
        // Surface slope across the sphere's waterline (central differences).
        const float d = std::max(r, kMinSlopeBase_m);
        const glm::vec2 slope((surface.height_at({o.position.x + d, o.position.z}) -
                               surface.height_at({o.position.x - d, o.position.z})) / (2.0f * d),
                              (surface.height_at({o.position.x, o.position.z + d}) -
                               surface.height_at({o.position.x, o.position.z - d})) / (2.0f * d));
        if (wet > 0.0f) {
            // Linear shallow-water momentum, du/dt = -g grad(eta), followed along the
            // object; the leak forgets the still-water guess made when it got wet.
            o.water_velocity += -kGravity * slope * h;
            o.water_velocity *= 1.0f - kWaterVelocityLeak_per_s * h;
        } else {
            o.water_velocity = glm::vec2(0.0f);
        }
        const glm::vec3 rel = o.velocity - wet * glm::vec3(o.water_velocity.x, 0.0f, o.water_velocity.y);
        float speed = std::sqrt(rel.x * rel.x + rel.y * rel.y + rel.z * rel.z);
        // Quadratic drag in air and in water, weighted by how much is wet; a little
        // linear damping in water stands in for added mass and wave radiation. Both act
        // against the moving water, so a float drifts with passing waves.
        float rho = kAirDensity + (kWaterDensity - kAirDensity) * wet;
        glm::vec3 force = -0.5f * rho * 0.47f * area * speed * rel - 4.0f * wet * o.mass_kg * rel;
        force.y += kWaterDensity * sub * kGravity - o.mass_kg * kGravity;
        // The sloping surface's pressure gradient on the wet part (Froude-Krylov).
        force.x -= kWaterDensity * sub * kGravity * slope.x;
        force.z -= kWaterDensity * sub * kGravity * slope.y;
        glm::vec3 prev = o.position;
        o.velocity += force / o.mass_kg * h;
        o.position += o.velocity * h;

        if (prev.y > sea && o.position.y <= sea && !o.in_water) {
            o.in_water = true;
            o.entered_this_tick = true;
            o.entry_position = {o.position.x, sea, o.position.z};
            o.entry_velocity = o.velocity;
        } else if (o.position.y > sea + 3.0f * r) {
            // Clearly airborne again (a skip): the next touch-down is a new entry.
            o.in_water = false;
        }

        glm::vec2 xz(o.position.x, o.position.z);
        // A solid's top holds what comes down onto it (the tank's floor on its plinth);
        // only a solid the object was already below pushes it sideways.
        const float top = solid_top_below(terrain.level().solids, xz, prev.y - r);
        if (auto push = terrain.resolve_solids(xz, r, std::max(o.position.y - r, top), o.position.y + r)) {
            o.position.x = xz.x;
            o.position.z = xz.y;
            glm::vec2 n = *push / std::max(std::sqrt(push->x * push->x + push->y * push->y), 1e-6f);
            float into = o.velocity.x * n.x + o.velocity.z * n.y;
            if (into < 0.0f) {
                o.velocity.x -= 1.4f * into * n.x;
                o.velocity.z -= 1.4f * into * n.y;
            }
        }
        float ground = std::max(terrain.support_height({o.position.x, o.position.z}, o.position.y, r), top);
        if (o.position.y - r < ground) {
            o.position.y = ground + r;
            if (o.velocity.y < 0.0f) o.velocity.y *= -0.3f;
            o.velocity.x *= 0.96f;
            o.velocity.z *= 0.96f;
            if (std::fabs(o.velocity.y) < 0.2f) o.velocity.y = 0.0f;
        }
        float half = terrain.level().half_extent_m - r;
        o.position.x = std::clamp(o.position.x, -half, half);
        o.position.z = std::clamp(o.position.z, -half, half);
    }
    ++o.age_ticks;
}
}  // namespace

float submerged_sphere_volume(float radius, float depth) {
    float d = std::clamp(depth + radius, 0.0f, 2.0f * radius);  // height of the wet cap
    return kPi * d * d * (3.0f * radius - d) / 3.0f;
}

void ThrownObjects::launch(const ThrowKind& kind, glm::vec3 from, glm::vec3 forward, glm::vec3 carrier_velocity) {
    if (objects_.size() == kMaxObjects) objects_.erase(objects_.begin());
    ThrownObject o;
    o.radius_m = kind.radius_m;
    o.density_kgm3 = kind.density_kgm3;
    o.mass_kg = kind.density_kgm3 * 4.0f / 3.0f * kPi * kind.radius_m * kind.radius_m * kind.radius_m;
    o.position = from;
    // Thrown at about 25 degrees above the facing direction.
    o.velocity = carrier_velocity + forward * (kind.speed_mps * 0.9063f) + glm::vec3(0, kind.speed_mps * 0.4226f, 0);
    objects_.push_back(o);
}

void ThrownObjects::connect(const SubsystemLinks& links) {
    player_ = &links.need<Player>();
    car_ = &links.need<Car>();
    boat_ = &links.need<Boat>();
}

void ThrownObjects::step(StepContext& ctx) {
    const Player& player = *player_;
    if (player.throws_heavy() || player.throws_light()) {
        Pose pose;
        glm::vec3 vel;
        if (player.vehicle() == Vehicle::Car) {
            pose = car_->pose();
            vel = car_->velocity();
        } else {
            pose = boat_->pose();
            vel = boat_->velocity();
        }
        glm::vec3 fwd = pose.forward_flat();
        glm::vec3 from = pose.position + glm::vec3(0.0f, 1.8f, 0.0f) + fwd * 0.5f;
        if (player.throws_heavy()) launch(kHeavy, from, fwd, vel);
        if (player.throws_light()) launch(kLight, from + pose.right_flat() * 0.4f, fwd, vel);
    }

    const World& world = ctx.world;
    ctx.jobs.parallel_for(objects_.size(), [&](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) step_object(objects_[i], world, ctx.dt);
    });
    // Events in object order, whatever thread stepped them.
    for (const ThrownObject& o : objects_)
        if (o.entered_this_tick)
            ctx.world.events().water_entries.push_back(
                WaterEntry{o.entry_position, o.entry_velocity, o.radius_m, o.mass_kg, o.sinks()});
}


}  // namespace sim
