#include "sim/rain/ParticleBuckets.h"

#include <algorithm>

#include <glm/common.hpp>

namespace sim {

void ParticleBuckets::build(const std::vector<WaterParticle>& particles, float bucket_m) {
    glm::vec2 lo = particles.front().pos_m, hi = lo;
    for (const WaterParticle& q : particles) {
        lo = glm::min(lo, q.pos_m);
        hi = glm::max(hi, q.pos_m);
    }
    cols_ = int((hi.x - lo.x) / bucket_m) + 1;
    rows_ = int((hi.y - lo.y) / bucket_m) + 1;
    start_.assign(size_t(cols_) * size_t(rows_) + 1, 0);
    particle_bucket_.resize(particles.size());
    for (size_t i = 0; i < particles.size(); ++i) {
        const glm::vec2 p = particles[i].pos_m;
        const int bi = std::min(int((p.x - lo.x) / bucket_m), cols_ - 1);
        const int bj = std::min(int((p.y - lo.y) / bucket_m), rows_ - 1);
        particle_bucket_[i] = bj * cols_ + bi;
        ++start_[size_t(particle_bucket_[i]) + 1];
    }
    for (size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
    fill_.assign(start_.begin(), start_.end() - 1);
    slot_particle_.resize(particles.size());
    slot_pos_.resize(particles.size());
    for (size_t i = 0; i < particles.size(); ++i) {
        const int32_t k = particle_bucket_[i];
        const size_t s = size_t(fill_[size_t(k)]++);
        slot_particle_[s] = int32_t(i);
        slot_pos_[s] = particles[i].pos_m;
    }
}

}  // namespace sim
