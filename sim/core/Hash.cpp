#include "sim/core/Hash.h"

#include <bit>
#include <cstring>

namespace sim {

namespace {

constexpr uint64_t kP1 = 0x9E3779B185EBCA87ull;
constexpr uint64_t kP2 = 0xC2B2AE3D27D4EB4Full;
constexpr uint64_t kP3 = 0x165667B19E3779F9ull;

inline uint64_t mix_round(uint64_t lane, uint64_t word) { return std::rotl(lane + word * kP2, 31) * kP1; }

inline uint64_t load64(const unsigned char* p) {
    uint64_t w;
    std::memcpy(&w, p, sizeof w);
    return w;
}

}  // namespace

uint64_t hash_words(const void* data, size_t bytes, uint64_t seed) {
    const auto* p = static_cast<const unsigned char*>(data);
    uint64_t a = seed + kP1 + kP2, b = seed + kP2, c = seed, d = seed - kP1;
    size_t i = 0;
    for (; i + 32 <= bytes; i += 32) {
        a = mix_round(a, load64(p + i));
        b = mix_round(b, load64(p + i + 8));
        c = mix_round(c, load64(p + i + 16));
        d = mix_round(d, load64(p + i + 24));
    }
    uint64_t h = std::rotl(a, 1) + std::rotl(b, 7) + std::rotl(c, 12) + std::rotl(d, 18);
    for (; i + 8 <= bytes; i += 8) h = std::rotl(h ^ mix_round(0, load64(p + i)), 27) * kP1 + kP3;
    for (; i < bytes; ++i) h = std::rotl(h ^ (uint64_t(p[i]) * kP3), 11) * kP1;
    h ^= uint64_t(bytes);
    h ^= h >> 33;
    h *= kP2;
    h ^= h >> 29;
    h *= kP3;
    h ^= h >> 32;
    return h;
}

}  // namespace sim
