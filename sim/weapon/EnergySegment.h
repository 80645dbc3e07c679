#pragma once
// One segment of an energy wave's field (docs/effects/energy.md): start M, unit direction D,
// length L, sphere strength a and beam strength b. Behind the plane through M normal
// to D the density is the sphere part a/|P-M|, in the slab 0 <= (P-M).D <= L the beam
// part b/dist(P, axis), beyond it the head sphere a/|P-(M+L D)|. Each part is cut off
// smoothly at radius_m (density minus its value there, zero outside): the field stays
// continuous, its line integrals stay closed-form, and a segment covers a bounded
// part of the screen so the renderer can cull it per tile.
#include <glm/vec3.hpp>

namespace sim {

struct EnergySegment {
    glm::vec3 start{0.0f};
    glm::vec3 direction{1.0f, 0.0f, 0.0f};
    float length_m = 0.0f;
    float sphere_strength = 0.0f;
    float beam_strength = 0.0f;
    float radius_m = 1.0f;  // influence radius: no density beyond it

    template <class Archive> void describe(Archive& ar) {
        ar.vec(start);
        ar.vec(direction);
        ar.f32(length_m);
        ar.f32(sphere_strength);
        ar.f32(beam_strength);
        ar.f32(radius_m);
    }
};

}  // namespace sim
