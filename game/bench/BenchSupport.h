#pragma once
// What the bench groups, the bench command and the timedemo share: wall-clock time since
// a start on the steady clock, printf-style formatting for case names and notes, and the
// machine's load for them.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

namespace game {

using BenchClock = std::chrono::steady_clock;

inline double seconds_since(BenchClock::time_point start) {
    return std::chrono::duration<double>(BenchClock::now() - start).count();
}
inline double ms_since(BenchClock::time_point start) {
    return std::chrono::duration<double, std::milli>(BenchClock::now() - start).count();
}

// std::snprintf into a string, whatever its length.
template <typename... Values>
std::string fmt(const char* format, Values... values) {
    const int length = std::snprintf(nullptr, 0, format, values...);
    if (length <= 0) return {};
    std::string text(size_t(length), '\0');
    std::snprintf(text.data(), text.size() + 1, format, values...);
    return text;
}

// The one-minute load average (/proc/loadavg's first field), "unknown" without it: a
// timing's note says how busy the machine was.
inline std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string one;
    in >> one;
    return one.empty() ? "unknown" : one;
}

}  // namespace game
