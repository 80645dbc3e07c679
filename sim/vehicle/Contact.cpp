#include "sim/vehicle/Contact.h"

#include <algorithm>

namespace sim {

namespace {
float dot(glm::vec2 a, glm::vec2 b) { return a.x * b.x + a.y * b.y; }
// How a point at `offset` moves per unit of yaw rate (d offset / d heading).
glm::vec2 swing(glm::vec2 offset) { return {offset.y, -offset.x}; }
}  // namespace

void touch(PlanarBody& body, glm::vec2 offset, glm::vec2 normal, ContactMaterial material) {
    const glm::vec2 arm = swing(offset);
    glm::vec2 v = body.velocity + body.yaw_rate * arm;
    float into = dot(v, normal);
    if (into >= 0.0f) return;
    auto push = [&](glm::vec2 dir, float impulse) {
        body.velocity += dir * (impulse / body.mass_kg);
        body.yaw_rate += impulse * dot(arm, dir) / body.yaw_inertia_kgm2;
    };
    auto inverse_mass = [&](glm::vec2 dir) {
        float k = dot(arm, dir);
        return 1.0f / body.mass_kg + k * k / body.yaw_inertia_kgm2;
    };
    float j = -(1.0f + material.restitution) * into / inverse_mass(normal);
    push(normal, j);
    glm::vec2 tangent(-normal.y, normal.x);
    v = body.velocity + body.yaw_rate * arm;
    float jt = std::clamp(-dot(v, tangent) / inverse_mass(tangent), -material.friction * j, material.friction * j);
    push(tangent, jt);
}

}  // namespace sim
