#pragma once
// One pass of the wiper particles' pairwise collisions (docs/effects/rain.md, "What is implemented"):
// centres closer than two radii are pushed apart along the line between them by half
// the overlap each, plus the restitution times that. Jacobi style: every push is
// taken from the positions before the pass, then all are applied.
//
// The sums are part of the hashed state, so their order is fixed: pairs in the order
// ParticleBuckets gives them, each push added to the first particle of the pair and
// taken from the second as the pair comes. Four pairs are measured at a time (SSE,
// the same IEEE operations as one at a time); a pair out of reach adds +0, which
// leaves every sum as it was (they start at +0 and so can never be -0). The test
// holds it to the bits of the plain pair-by-pair pass.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "sim/rain/ParticleBuckets.h"
#include "sim/rain/WaterParticle.h"

namespace sim {

class ParticleCollider {
public:
    void collide(std::vector<WaterParticle>& particles, float radius_m, float restitution);

private:
    ParticleBuckets buckets_;
    std::vector<glm::vec2> push_;  // per slot
    // One bucket's slots and those of the buckets ahead, in order and padded for the
    // last four: positions, slots and particle indices, then the pushes on one slot.
    std::vector<float> near_u_, near_v_, push_u_, push_v_;
    std::vector<int32_t> near_slot_, near_index_;
};

}  // namespace sim
