#pragma once
// Numbers in the sim's refusal messages, printed one way everywhere.
#include <cstdio>
#include <string>

namespace sim {

// %g: short, and exact enough to tell which value was refused.
inline std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace sim
