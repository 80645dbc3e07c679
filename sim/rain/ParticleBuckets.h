#pragma once
// The wiper particles sorted into square buckets one contact distance wide over their
// bounding box, for the pairwise collisions (specs/rain.md, "Wipers"): two particles
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

    int32_t slots() const { return int32_t(slot_pos_.size()); }
    glm::vec2 position(int32_t slot) const { return slot_pos_[size_t(slot)]; }
    int32_t particle(int32_t slot) const { return slot_particle_[size_t(slot)]; }

    // Calls partner(b) for every slot b that slot a meets, so that over a = 0, 1, ...
    // each pair of slots in one or in neighbouring buckets comes once, a before b: the
    // later slots of a's bucket, then those of the four buckets ahead (right, and
    // up-left, up, up-right in the row above), each in slot order.
    template <typename Partner>
    void for_each_partner(int32_t a, Partner&& partner) const {
        const int32_t k = slot_bucket_[size_t(a)];
        for (int32_t b = a + 1; b < start_[size_t(k) + 1]; ++b) partner(b);
        const int ki = k % cols_, kj = k / cols_;
        for (int n = 0; n < 4; ++n) {
            const int ni = ki + kAheadI[n], nj = kj + kAheadJ[n];
            if (ni < 0 || ni >= cols_ || nj >= rows_) continue;
            const size_t nk = size_t(nj * cols_ + ni);
            for (int32_t b = start_[nk]; b < start_[nk + 1]; ++b) partner(b);
        }
    }

private:
    static constexpr int kAheadI[4] = {1, -1, 0, 1}, kAheadJ[4] = {0, 1, 1, 1};

    int cols_ = 0, rows_ = 0;
    std::vector<int32_t> start_;          // first slot of each bucket, and the slot count last
    std::vector<int32_t> fill_;           // scratch for the sort
    std::vector<int32_t> particle_bucket_;
    std::vector<int32_t> slot_bucket_, slot_particle_;
    std::vector<glm::vec2> slot_pos_;
};

}  // namespace sim
