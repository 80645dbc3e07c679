#pragma once
// 64-bit FNV-1a over exact bit patterns: floats hash by representation, so any
// divergence in any bit shows.
#include <bit>
#include <cstdint>
#include <cstring>
#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/gtc/quaternion.hpp>

namespace sim {

class Hasher {
public:
    void bytes(const void* data, size_t n) {
        auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < n; ++i) {
            h_ ^= p[i];
            h_ *= 0x100000001b3ull;
        }
    }
    void u64(uint64_t v) { bytes(&v, sizeof v); }
    void u32(uint32_t v) { bytes(&v, sizeof v); }
    void i32(int32_t v) { bytes(&v, sizeof v); }
    void f32(float v) { u32(std::bit_cast<uint32_t>(v)); }
    void vec(const glm::vec2& v) { f32(v.x); f32(v.y); }
    void vec(const glm::vec3& v) { f32(v.x); f32(v.y); f32(v.z); }
    void quat(const glm::quat& q) { f32(q.x); f32(q.y); f32(q.z); f32(q.w); }
    void floats(std::span<const float> v) { for (float f : v) f32(f); }
    uint64_t value() const { return h_; }

private:
    uint64_t h_ = 0xcbf29ce484222325ull;
};

inline uint64_t hash_combine(uint64_t a, uint64_t b) {
    // splitmix64 finaliser of the pair: order-dependent, well mixed.
    uint64_t x = a ^ (b + 0x9e3779b97f4a7c15ull + (a << 6) + (a >> 2));
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// A fast 64-bit hash of raw bytes (four independent multiply-rotate lanes, then a
// final mix) for bulk state such as the water's grids, too much for byte-wise FNV.
// Each round is a bijection of its lane, so any single changed word changes the hash.
uint64_t hash_words(const void* data, size_t bytes, uint64_t seed = 0);

}  // namespace sim
