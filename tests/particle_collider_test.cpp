// sim/rain's particle collisions: four pairs at a time give the same bits as the
// plain pair-by-pair pass in the buckets' order (the particle state is hashed into
// replays), on piles, coincident particles and pairs just in and out of reach.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "sim/core/Rng.h"
#include "sim/rain/ParticleCollider.h"

namespace {

// The pass one pair at a time, as RainSim did before ParticleCollider.
void collide_pair_by_pair(std::vector<sim::WaterParticle>& ps, float radius_m, float restitution) {
    const float two_r = 2.0f * radius_m, two_r2 = two_r * two_r;
    sim::ParticleBuckets buckets;
    buckets.build(ps, two_r);
    std::vector<glm::vec2> push(ps.size(), glm::vec2(0.0f));
    auto meet = [&](int32_t a, int32_t b) {
        const size_t i = size_t(buckets.particle(a)), j = size_t(buckets.particle(b));
        const glm::vec2 d = ps[i].pos_m - ps[j].pos_m;
        const float d2 = d.x * d.x + d.y * d.y;
        if (d2 >= two_r2) return;
        const float dist = std::sqrt(d2);
        const glm::vec2 dir = dist > 1e-7f ? d / dist : glm::vec2(i < j ? 1.0f : -1.0f, 0.0f);
        const glm::vec2 p = dir * (0.5f * (two_r - dist) * (1.0f + restitution));
        push[i] += p;
        push[j] -= p;
    };
    for (int32_t k = 0; k < buckets.buckets(); ++k)
        for (int32_t a = buckets.begin(k); a < buckets.end(k); ++a) {
            for (int32_t b = a + 1; b < buckets.end(k); ++b) meet(a, b);
            buckets.for_each_ahead(k, [&](int32_t first, int32_t last) {
                for (int32_t b = first; b < last; ++b) meet(a, b);
            });
        }
    for (size_t i = 0; i < ps.size(); ++i) ps[i].pos_m += push[i];
}

std::vector<sim::WaterParticle> bead(uint64_t seed, float radius_m) {
    sim::Rng rng(seed, 5);
    std::vector<sim::WaterParticle> out;
    for (int k = 0; k < 1500; ++k) out.push_back({rng.unit2() * glm::vec2(0.2f, 0.1f) - 0.05f, 20.0f, 0u});
    for (int k = 0; k < 600; ++k) out.push_back({glm::vec2(0.03f, 0.01f) + rng.unit2() * 0.012f, 20.0f, 0u});
    for (int k = 0; k < 20; ++k) out.push_back(out[size_t(rng.below(uint32_t(out.size())))]);  // coincident
    const glm::vec2 at = out.front().pos_m;
    out.push_back({at + glm::vec2(2.0f * radius_m, 0.0f), 20.0f, 0u});  // just out of reach
    out.push_back({at + glm::vec2(0.0f, std::nextafter(2.0f * radius_m, 0.0f)), 20.0f, 0u});  // just in
    return out;
}

TEST(RainParticleCollider, FourPairsAtATimeGiveTheBitsOfOneAtATime) {
    const float radius = 0.0021f;
    for (uint64_t seed = 1; seed <= 3; ++seed) {
        std::vector<sim::WaterParticle> fast = bead(seed, radius), plain = fast;
        sim::ParticleCollider collider;
        for (int pass = 0; pass < 4; ++pass) {
            collider.collide(fast, radius, 0.2f);
            collide_pair_by_pair(plain, radius, 0.2f);
            ASSERT_EQ(std::memcmp(fast.data(), plain.data(), fast.size() * sizeof(sim::WaterParticle)), 0)
                << "seed " << seed << ", pass " << pass;
        }
        EXPECT_NE(fast.front().pos_m, bead(seed, radius).front().pos_m) << "the particles moved";
    }
}

}  // namespace
