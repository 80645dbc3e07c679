// sim/rain's particle buckets: the pair search of the wiper particles' collisions finds
// every pair closer than a bucket width, once each, like a brute-force search.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>

#include "sim/core/Rng.h"
#include "sim/rain/ParticleBuckets.h"

namespace {

using Pair = std::pair<int32_t, int32_t>;  // particle indices, lower first

// Loose particles over a patch, a tight pile (a bead, layers overlapping) and
// coincident copies, as the blades leave them.
std::vector<sim::WaterParticle> scattered(uint64_t seed, int loose, int piled) {
    sim::Rng rng(seed, 3);
    std::vector<sim::WaterParticle> out;
    for (int k = 0; k < loose; ++k) out.push_back({rng.unit2() * glm::vec2(0.3f, 0.2f) - 0.1f, 20.0f, 0u});
    for (int k = 0; k < piled; ++k) out.push_back({glm::vec2(0.05f, 0.02f) + rng.unit2() * 0.01f, 20.0f, 0u});
    out.push_back(out.front());
    out.push_back(out.back());
    return out;
}

// Every pair of slots the buckets give, in their order, as pair(a, b) calls.
template <typename Pair2>
void for_each_pair(const sim::ParticleBuckets& buckets, Pair2&& pair) {
    for (int32_t k = 0; k < buckets.buckets(); ++k)
        for (int32_t a = buckets.begin(k); a < buckets.end(k); ++a) {
            for (int32_t b = a + 1; b < buckets.end(k); ++b) pair(a, b);
            buckets.for_each_ahead(k, [&](int32_t first, int32_t last) {
                for (int32_t b = first; b < last; ++b) pair(a, b);
            });
        }
}

std::set<Pair> brute_force(const std::vector<sim::WaterParticle>& ps, float reach_m) {
    std::set<Pair> out;
    for (size_t i = 0; i < ps.size(); ++i)
        for (size_t j = i + 1; j < ps.size(); ++j) {
            const glm::vec2 d = ps[i].pos_m - ps[j].pos_m;
            if (d.x * d.x + d.y * d.y < reach_m * reach_m) out.insert({int32_t(i), int32_t(j)});
        }
    return out;
}

TEST(RainParticleBuckets, FindEveryPairInReachOnceLikeBruteForce) {
    const float reach = 0.0042f;  // two radii of a 20 mg particle
    for (uint64_t seed = 1; seed <= 4; ++seed) {
        const std::vector<sim::WaterParticle> ps = scattered(seed, 3000, 400);
        sim::ParticleBuckets buckets;
        buckets.build(ps, reach);
        ASSERT_EQ(buckets.slots(), int32_t(ps.size()));

        std::set<int32_t> seen;
        for (int32_t a = 0; a < buckets.slots(); ++a) {
            const int32_t i = buckets.particle(a);
            EXPECT_TRUE(seen.insert(i).second) << "particle " << i << " in two slots";
            EXPECT_EQ(buckets.position(a), ps[size_t(i)].pos_m);
        }
        ASSERT_EQ(buckets.end(buckets.buckets() - 1), buckets.slots());
        std::set<Pair> found;
        int32_t last_a = 0;
        for_each_pair(buckets, [&](int32_t a, int32_t b) {
            EXPECT_GT(b, a) << "a pair comes from its first slot";
            EXPECT_GE(a, last_a) << "slots in turn";
            last_a = a;
            const int32_t i = buckets.particle(a), j = buckets.particle(b);
            const glm::vec2 d = buckets.position(a) - buckets.position(b);
            if (d.x * d.x + d.y * d.y >= reach * reach) return;
            EXPECT_TRUE(found.insert({std::min(i, j), std::max(i, j)}).second) << "pair " << i << ", " << j << " twice";
        });
        EXPECT_EQ(found, brute_force(ps, reach)) << "seed " << seed;
    }
}

TEST(RainParticleBuckets, ABucketKeepsItsParticlesInIndexOrder) {
    // All in one bucket: the slots are the particles in order.
    std::vector<sim::WaterParticle> ps = {{{0.001f, 0.0f}, 1.0f, 0u}, {{0.0f, 0.001f}, 1.0f, 0u}, {{0.0f, 0.0f}, 1.0f, 0u}};
    sim::ParticleBuckets buckets;
    buckets.build(ps, 0.01f);
    ASSERT_EQ(buckets.buckets(), 1);
    for (int32_t a = 0; a < buckets.slots(); ++a) EXPECT_EQ(buckets.particle(a), a);
    std::vector<Pair> pairs;
    for_each_pair(buckets, [&](int32_t a, int32_t b) { pairs.push_back({a, b}); });
    EXPECT_EQ(pairs, (std::vector<Pair>{{0, 1}, {0, 2}, {1, 2}}));
}

}  // namespace
