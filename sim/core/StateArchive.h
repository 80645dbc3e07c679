#pragma once
// One description of a part of the sim's state, walked three ways (docs/REPLAYS.md,
// "Snapshots"): StateHasher makes the world hash from it, StateWriter saves it into a
// snapshot and StateReader restores it. A subsystem lists its state once, in
//
//     template <class Archive> void describe(Archive& ar) { ar.f32(speed_); ar.vec(pos_); ... }
//
// so a field cannot be hashed and not saved. Each call says how the field is hashed
// (these are the bytes and the order the hand-written hash functions fed the Hasher, so
// every recorded hash stays as it was); `unhashed` lists state that the recorded hashes
// leave out: saved and restored, never hashed. Per-tick scratch (what a step rebuilds
// before reading it) is not listed at all.
//
// Hashing and saving only read the fields: describe() is not const so that one function
// serves all three, and hash_state / save_state call it on a const object through a
// const_cast that no hashing or saving archive writes through.
#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sim/core/Hash.h"
#include "sim/core/Rng.h"

namespace sim {

// A snapshot that cannot be restored: cut, another layout, another sim or level.
class SnapshotError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Feeds a description to the world hash. The hash is a chain of parts joined with
// hash_combine: runs of scalars go through one FNV-1a Hasher (a run is a part), bulk
// arrays through hash_words (a part each), nested objects are parts of their own.
class StateHasher {
public:
    static constexpr bool kLoading = false;

    void u32(const uint32_t& v) { run().u32(v); }
    void i32(const int32_t& v) { run().i32(v); }
    void u64(const uint64_t& v) { run().u64(v); }
    void f32(const float& v) { run().f32(v); }
    void vec(const glm::vec2& v) { run().vec(v); }
    void vec(const glm::vec3& v) { run().vec(v); }
    void boolean(const bool& b) { run().u32(b ? 1u : 0u); }
    template <class E> void enum32(const E& e) { run().u32(uint32_t(e)); }
    // Small enums, one byte each of one u32 (the first in the low byte).
    template <class... E> void pack8(const E&... e) {
        uint32_t v = 0, shift = 0;
        ((v |= uint32_t(e) << shift, shift += 8), ...);
        run().u32(v);
    }
    // Flags, one bit each of one u32 (the first in bit 0).
    template <class... B> void flags(const B&... b) {
        uint32_t v = 0, bit = 0;
        ((v |= uint32_t(b ? 1u : 0u) << bit, ++bit), ...);
        run().u32(v);
    }
    // None hashes as ~0.
    void optional_u64(const std::optional<uint64_t>& v) { run().u64(v.value_or(~0ull)); }
    // A plain struct hashed by its bytes.
    template <class T> void raw(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        run().bytes(&v, sizeof v);
    }
    // A vector's length (its elements are described after it).
    template <class T> void size32(const std::vector<T>& v) { run().u32(uint32_t(v.size())); }
    template <class T> void size64(const std::vector<T>& v) { run().u64(uint64_t(v.size())); }
    // A bulk array as one part: hash_words(data, seed).
    template <class T> void words(const std::vector<T>& v, uint64_t seed = 0) { part(hash_words_of(v, seed)); }
    // A bulk array hashed with the hash so far as its seed (which must be a bulk part).
    template <class T> void words_chained(const std::vector<T>& v) {
        close_run();
        value_ = hash_words_of(v, value_);
        started_ = true;
    }
    // A bulk array's hash_words fed into the run as one u64.
    template <class T> void words_digest(const std::vector<T>& v) { run().u64(hash_words_of(v, 0)); }
    // A nested object (with its own describe) as one part.
    template <class T> void nested(const T& object);
    // A struct's described fields, in this run as if listed here.
    template <class T> void fields(const T& object) { const_cast<T&>(object).describe(*this); }
    // A random generator: its state (the stream is fixed by its seed and saved too).
    void rng(const Rng& r) { run().u64(r.state()); }
    void rng_with_stream(const Rng& r) {
        run().u64(r.state());
        run().u64(r.increment());
    }
    // Two arrays of vectors saved whole, hashed only where `mask` is set: a[i], b[i] in
    // turn into a new run (nothing where no mask byte is set).
    void vecs_where(const std::vector<uint8_t>& mask, const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
        for (size_t i = 0; i < mask.size(); ++i)
            if (mask[i]) {
                run().vec(a[i]);
                run().vec(b[i]);
            }
    }
    template <class T> void unhashed(const T&) {}

    uint64_t value() {
        close_run();
        return started_ ? value_ : Hasher().value();
    }

private:
    template <class T> static uint64_t hash_words_of(const std::vector<T>& v, uint64_t seed) {
        static_assert(std::is_trivially_copyable_v<T>);
        return hash_words(v.data(), v.size() * sizeof(T), seed);
    }
    Hasher& run() {
        if (!in_run_) {
            run_ = Hasher();
            in_run_ = true;
        }
        return run_;
    }
    void close_run() {
        if (!in_run_) return;
        in_run_ = false;
        part(run_.value());
    }
    void part(uint64_t p) {
        close_run();
        value_ = started_ ? hash_combine(value_, p) : p;
        started_ = true;
    }

    Hasher run_;
    bool in_run_ = false;
    uint64_t value_ = 0;
    bool started_ = false;
};

// Appends a description's fields to a byte buffer (little-endian hosts: x86-64, aarch64).
class StateWriter {
public:
    static constexpr bool kLoading = false;

    explicit StateWriter(std::vector<uint8_t>& out) : out_(out) {}

    void u32(const uint32_t& v) { put(v); }
    void i32(const int32_t& v) { put(v); }
    void u64(const uint64_t& v) { put(v); }
    void f32(const float& v) { put(v); }
    void vec(const glm::vec2& v) { put(v); }
    void vec(const glm::vec3& v) { put(v); }
    void boolean(const bool& b) { put(uint8_t(b)); }
    template <class E> void enum32(const E& e) { put(e); }
    template <class... E> void pack8(const E&... e) { (put(e), ...); }
    template <class... B> void flags(const B&... b) { (boolean(b), ...); }
    void optional_u64(const std::optional<uint64_t>& v) { put(v.value_or(~0ull)); }
    template <class T> void raw(const T& v) { put(v); }
    template <class T> void size32(const std::vector<T>& v) { put(uint64_t(v.size())); }
    template <class T> void size64(const std::vector<T>& v) { put(uint64_t(v.size())); }
    template <class T> void words(const std::vector<T>& v, uint64_t = 0) { array(v); }
    template <class T> void words_chained(const std::vector<T>& v) { array(v); }
    template <class T> void words_digest(const std::vector<T>& v) { array(v); }
    template <class T> void nested(const T& object) { const_cast<T&>(object).describe(*this); }
    template <class T> void fields(const T& object) { const_cast<T&>(object).describe(*this); }
    void rng(const Rng& r) { rng_with_stream(r); }
    void rng_with_stream(const Rng& r) {
        put(r.state());
        put(r.increment());
    }
    void vecs_where(const std::vector<uint8_t>&, const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
        array(a);
        array(b);
    }
    template <class T> void unhashed(const T& v) {
        if constexpr (requires { v.data(); v.size(); }) array(v);
        else put(v);
    }

private:
    template <class T> void put(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        const auto* p = reinterpret_cast<const uint8_t*>(&v);
        out_.insert(out_.end(), p, p + sizeof v);
    }
    template <class V> void array(const V& v) {
        using T = std::remove_cvref_t<decltype(*v.data())>;
        static_assert(std::is_trivially_copyable_v<T>);
        put(uint64_t(v.size()));
        const auto* p = reinterpret_cast<const uint8_t*>(v.data());
        out_.insert(out_.end(), p, p + v.size() * sizeof(T));
    }

    std::vector<uint8_t>& out_;
};

// Reads a description's fields back, in the order StateWriter wrote them. Throws
// SnapshotError when the bytes run out or an array's length is impossible.
class StateReader {
public:
    static constexpr bool kLoading = true;

    explicit StateReader(std::span<const uint8_t> in) : in_(in) {}

    void u32(uint32_t& v) { get(v); }
    void i32(int32_t& v) { get(v); }
    void u64(uint64_t& v) { get(v); }
    void f32(float& v) { get(v); }
    void vec(glm::vec2& v) { get(v); }
    void vec(glm::vec3& v) { get(v); }
    void boolean(bool& b) {
        uint8_t v;
        get(v);
        if (v > 1) throw SnapshotError("snapshot: a flag holds " + std::to_string(v));
        b = v != 0;
    }
    template <class E> void enum32(E& e) { get(e); }
    template <class... E> void pack8(E&... e) { (get(e), ...); }
    template <class... B> void flags(B&... b) { (boolean(b), ...); }
    void optional_u64(std::optional<uint64_t>& v) {
        uint64_t x;
        get(x);
        v = x == ~0ull ? std::nullopt : std::optional<uint64_t>(x);
    }
    template <class T> void raw(T& v) { get(v); }
    template <class T> void size32(std::vector<T>& v) { resize(v); }
    template <class T> void size64(std::vector<T>& v) { resize(v); }
    template <class T> void words(std::vector<T>& v, uint64_t = 0) { array(v); }
    template <class T> void words_chained(std::vector<T>& v) { array(v); }
    template <class T> void words_digest(std::vector<T>& v) { array(v); }
    template <class T> void nested(T& object) { object.describe(*this); }
    template <class T> void fields(T& object) { object.describe(*this); }
    void rng(Rng& r) { rng_with_stream(r); }
    void rng_with_stream(Rng& r) {
        uint64_t state, inc;
        get(state);
        get(inc);
        r.restore(state, inc);
    }
    void vecs_where(const std::vector<uint8_t>&, std::vector<glm::vec3>& a, std::vector<glm::vec3>& b) {
        array(a);
        array(b);
    }
    template <class T> void unhashed(T& v) {
        if constexpr (requires { v.data(); v.size(); }) array(v);
        else get(v);
    }

    size_t remaining() const { return in_.size() - at_; }
    // The next `n` bytes as they are (a part of its own, named in the message).
    std::span<const uint8_t> bytes(uint64_t n, std::string_view part) {
        if (n > remaining()) throw SnapshotError("snapshot: '" + std::string(part) + "' is cut short");
        const std::span<const uint8_t> s = in_.subspan(at_, size_t(n));
        at_ += size_t(n);
        return s;
    }

private:
    void take(void* p, size_t n) {
        if (n > remaining()) throw SnapshotError("snapshot: cut short (a field wants more bytes than are left)");
        if (n == 0) return;  // an empty list's data() may be null, which memcpy must not see
        std::memcpy(p, in_.data() + at_, n);
        at_ += n;
    }
    template <class T> void get(T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        take(&v, sizeof v);
    }
    template <class T> void resize(std::vector<T>& v) {
        uint64_t n;
        get(n);
        // Every element takes at least a byte of what is left: a bound before allocating.
        if (n > remaining()) throw SnapshotError("snapshot: a list claims " + std::to_string(n) + " elements");
        v.resize(size_t(n));
    }
    template <class V> void array(V& v) {
        using T = std::remove_cvref_t<decltype(*v.data())>;
        static_assert(std::is_trivially_copyable_v<T>);
        uint64_t n;
        get(n);
        if (n > remaining() / sizeof(T)) throw SnapshotError("snapshot: an array claims " + std::to_string(n) + " elements");
        if constexpr (requires { v.resize(size_t(n)); }) v.resize(size_t(n));
        else if (n != v.size()) throw SnapshotError("snapshot: a fixed array has another length");
        take(v.data(), size_t(n) * sizeof(T));
    }

    std::span<const uint8_t> in_;
    size_t at_ = 0;
};

template <class T> void StateHasher::nested(const T& object) {
    StateHasher inner;
    const_cast<T&>(object).describe(inner);
    part(inner.value());
}

// The hash of anything with a describe(): what its hash() returns.
template <class T> uint64_t hash_state(const T& object) {
    StateHasher h;
    const_cast<T&>(object).describe(h);
    return h.value();
}

}  // namespace sim
