#pragma once
// PCG32 (O'Neill, pcg-random.org): small, fast, and the same sequence everywhere.
// One instance per subsystem, stored in the state it drives.
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace sim {

class Rng {
public:
    explicit Rng(uint64_t seed = 0x853c49e6748fea9bull, uint64_t stream = 0xda3e39cb94b95bdbull) {
        inc_ = (stream << 1u) | 1u;
        next_u32();
        state_ += seed;
        next_u32();
    }
    uint32_t next_u32() {
        uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    // Uniform in [0, 1): 24 random bits, exact in float.
    float unit() { return float(next_u32() >> 8) * (1.0f / 16777216.0f); }
    float range(float lo, float hi) { return lo + (hi - lo) * unit(); }
    // Vectors draw x, then y, then z. Never draw twice inside one call's arguments
    // (glm::vec2(unit(), unit())): their order is unspecified, and gcc and clang differ.
    glm::vec2 unit2() {
        const float x = unit();
        return {x, unit()};
    }
    glm::vec3 range3(float lo, float hi) {
        const float x = range(lo, hi);
        const float y = range(lo, hi);
        return {x, y, range(lo, hi)};
    }
    // Uniform integer in [0, n) without modulo bias (Lemire's method, rejection).
    uint32_t below(uint32_t n) {
        uint64_t m = uint64_t(next_u32()) * n;
        uint32_t l = uint32_t(m);
        if (l < n) {
            uint32_t t = (0u - n) % n;
            while (l < t) {
                m = uint64_t(next_u32()) * n;
                l = uint32_t(m);
            }
        }
        return uint32_t(m >> 32);
    }
    uint64_t state() const { return state_; }
    uint64_t increment() const { return inc_; }
    // Back to a saved state (a snapshot restored).
    void restore(uint64_t state, uint64_t increment) {
        state_ = state;
        inc_ = increment;
    }

private:
    uint64_t state_ = 0;
    uint64_t inc_ = 0;
};

}  // namespace sim
