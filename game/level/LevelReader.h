#pragma once
// Typed access to a level's JSON: every error is a LevelError naming the file and the
// JSON path of the value ("props[3].position[1]: 2000 is out of range ...").
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "game/level/LevelError.h"

namespace game {

inline constexpr float kMaxAbsCoordinate_m = 1000.0f;

// JSON paths for messages: "rain" + "cell_size_m" -> "rain.cell_size_m", "props" + 3 -> "props[3]".
inline std::string key_path(const std::string& where, std::string_view key) {
    return where.empty() ? std::string(key) : where + "." + std::string(key);
}
inline std::string index_path(const std::string& where, size_t i) { return where + "[" + std::to_string(i) + "]"; }

// The shortest text that reads back as `v`.
inline std::string show(float v) {
    char buf[32];
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

// Typed access to the level JSON; every error names the file and the JSON path.
class LevelReader {
public:
    using json = nlohmann::json;

    explicit LevelReader(const std::filesystem::path& file) : file_(file) {}

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw LevelError(file_.string() + ": " + (where.empty() ? "" : where + ": ") + what);
    }

    // `v` must be an object whose keys are all in `known` (or start with '_').
    void object(const json& v, const std::string& where, std::initializer_list<std::string_view> known) const {
        if (!v.is_object()) fail(where, "expected an object");
        for (auto it = v.begin(); it != v.end(); ++it) {
            const std::string& k = it.key();
            if (!k.empty() && k[0] == '_') continue;
            if (std::find(known.begin(), known.end(), k) == known.end()) fail(key_path(where, k), "unknown key");
        }
    }
    const json& required(const json& obj, const std::string& where, const char* key) const {
        auto it = obj.find(key);
        if (it == obj.end()) fail(where, std::string("missing required key '") + key + "'");
        return *it;
    }
    static const json* optional(const json& obj, const char* key) {
        auto it = obj.find(key);
        return it == obj.end() ? nullptr : &*it;
    }
    const json& array(const json& v, const std::string& where, size_t max_size) const {
        if (!v.is_array()) fail(where, "expected an array");
        if (v.size() > max_size)
            fail(where, std::to_string(v.size()) + " entries, at most " + std::to_string(max_size) + " allowed");
        return v;
    }
    float number(const json& v, const std::string& where) const {
        if (!v.is_number()) fail(where, "expected a number");
        double d = v.get<double>();
        if (!std::isfinite(d) || !std::isfinite(float(d))) fail(where, "is not a finite number");
        return float(d);
    }
    // In [lo, hi]; the bound is left out at lo when lo_open, at hi when hi_open.
    float number_in(const json& v, const std::string& where, float lo, float hi, bool lo_open = false,
                    bool hi_open = false) const {
        float f = number(v, where);
        if (f > hi || f < lo || (lo_open && f == lo) || (hi_open && f == hi))
            fail(where, show(f) + " is out of range " + (lo_open ? "(" : "[") + show(lo) + ", " + show(hi) +
                            (hi_open ? ")" : "]"));
        return f;
    }
    template <int N>
    glm::vec<N, float> vec(const json& v, const std::string& where) const {
        const char* expected = N == 2 ? "expected an array of 2 numbers" : "expected an array of 3 numbers";
        if (!v.is_array() || v.size() != size_t(N)) fail(where, expected);
        glm::vec<N, float> out;
        for (int i = 0; i < N; ++i) {
            if (!v[size_t(i)].is_number()) fail(where, expected);
            out[i] = number_in(v[size_t(i)], index_path(where, size_t(i)), -kMaxAbsCoordinate_m, kMaxAbsCoordinate_m);
        }
        return out;
    }
    std::string string(const json& v, const std::string& where) const {
        if (!v.is_string()) fail(where, "expected a string");
        return v.get<std::string>();
    }

private:
    const std::filesystem::path& file_;
};

}  // namespace game
