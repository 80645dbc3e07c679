#include "sim/objectives/Course.h"

#include <utility>

#include "sim/core/DetMath.h"

namespace sim {

namespace {
float cross(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }
}  // namespace

GatePosts gate_posts(const GateDesc& gate) {
    float s = 0.0f, c = 0.0f;
    det::sincos(gate.heading_rad, s, c);
    const glm::vec2 ahead(c, -s);               // heading 0 faces +x, positive turns towards -z
    const glm::vec2 left(ahead.y, -ahead.x);    // a quarter turn towards -z from ahead
    const glm::vec2 half = left * (0.5f * gate.width_m);
    return {gate.centre_xz + half, gate.centre_xz - half};
}

bool crosses_gate(const GatePosts& gate, glm::vec2 from, glm::vec2 to) {
    // Which side of the gate's line each end is on: the back is positive.
    const glm::vec2 line = gate.right - gate.left;
    const float side_from = cross(line, from - gate.left);
    const float side_to = cross(line, to - gate.left);
    if (!(side_from > 0.0f && side_to <= 0.0f)) return false;
    // And the posts on either side of the move (or one on it): between them.
    const glm::vec2 move = to - from;
    const float side_left = cross(move, gate.left - from);
    const float side_right = cross(move, gate.right - from);
    return (side_left <= 0.0f && side_right >= 0.0f) || (side_left >= 0.0f && side_right <= 0.0f);
}

Course::Course(CourseDesc desc) : desc_(std::move(desc)) {
    for (const GateDesc& g : desc_.gates) posts_.push_back(gate_posts(g));
}

void Course::advance(glm::vec2 from, glm::vec2 to, uint64_t ticks) {
    if (posts_.empty() || !crosses_gate(posts_[next_], from, to)) return;
    if (next_ == 0) {
        // The start line: it ends the running lap (every other gate was passed to get
        // here) and starts the next.
        if (lap_start_) {
            const uint64_t lap = ticks - *lap_start_;
            last_ = lap;
            if (!best_ || lap < *best_) best_ = lap;
            ++laps_;
        }
        lap_start_ = ticks;
    }
    next_ = (next_ + 1) % posts_.size();
}


}  // namespace sim
