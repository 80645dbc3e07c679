#pragma once
// The wiper particles sorted into square buckets one contact distance wide over their
// bounding box, for the pairwise collisions (docs/effects/rain.md, "What is implemented"): two particles
// closer than a bucket width lie in the same or in neighbouring buckets. The
// particles' positions are copied out in bucket order (slots), so a pair search reads
// memory in sequence; a counting sort keeps each bucket's particles in index order.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "sim/rain/WaterParticle.h"

namespace sim {

class ParticleBuckets {
public:
    // Sorts `particles` (not empty) into buckets `bucket_m` wide.
    void build(const std::vector<WaterParticle>& particles, float bucket_m);

    int32_t slots() const { return int32_t(slot_pos_.size()); }  // one per particle
    glm::vec2 position(int32_t slot) const { return slot_pos_[size_t(slot)]; }
    int32_t particle(int32_t slot) const { return slot_particle_[size_t(slot)]; }

    // Two particles in reach are in one bucket or in neighbouring ones. Each pair of
    // them comes once, in a fixed order, from the buckets k = 0, 1, ... and their slots
    // a in turn: a meets the later slots of its own bucket, then the slots of the four
    // buckets ahead of k (right, and up-left, up, up-right in the row above).
    int32_t buckets() const { return int32_t(start_.size()) - 1; }
    int32_t begin(int32_t k) const { return start_[size_t(k)]; }
    int32_t end(int32_t k) const { return start_[size_t(k) + 1]; }
    // Calls slots(first, last) for each bucket ahead of k in that order (last excluded).
    template <typename Slots>
    void for_each_ahead(int32_t k, Slots&& slots) const {
        const int ki = k % cols_, kj = k / cols_;
        for (int n = 0; n < 4; ++n) {
            const int ni = ki + kAheadI[n], nj = kj + kAheadJ[n];
            if (ni < 0 || ni >= cols_ || nj >= rows_) continue;
            const int32_t nk = nj * cols_ + ni;
            slots(begin(nk), end(nk));
        }
    }

private:
    static constexpr int kAheadI[4] = {1, -1, 0, 1}, kAheadJ[4] = {0, 1, 1, 1};

    int cols_ = 0, rows_ = 0;
    std::vector<int32_t> start_;          // first slot of each bucket, and the slot count last
    std::vector<int32_t> fill_;           // scratch for the sort
    std::vector<int32_t> particle_bucket_;
    std::vector<int32_t> slot_particle_;
    std::vector<glm::vec2> slot_pos_;
};

}  // namespace sim
