#pragma once
// One course of gates and its lap timer. A vehicle's move from one tick to the next is
// a segment on the ground; a gate counts when that segment crosses the gate's line
// between its posts in the gate's direction, and only if it is the next gate: gates out
// of order, or crossed backwards, do nothing. Times are whole ticks.
#include <cstdint>
#include <optional>

#include <glm/vec2.hpp>

#include "sim/objectives/ObjectiveDesc.h"

namespace sim {

struct GatePosts {
    glm::vec2 left{0.0f}, right{0.0f};  // as seen by a vehicle passing the right way
};

// The posts of a gate (det:: trigonometry, so the same bits everywhere).
GatePosts gate_posts(const GateDesc& gate);
// True when the move from -> to crosses the line left -> right from its back to its
// front (the front is where a vehicle passing the right way ends up). Touching the
// line counts as crossing it; starting on it does not.
bool crosses_gate(const GatePosts& gate, glm::vec2 from, glm::vec2 to);

class Course {
public:
    explicit Course(CourseDesc desc);

    // The vehicle moved from -> to during the step that brings the world's tick count
    // to `ticks` (World::tick() once the step is done).
    void advance(glm::vec2 from, glm::vec2 to, uint64_t ticks);
    // The lap state (the gates are the level's).
    template <class Archive> void describe(Archive& ar) {
        ar.u64(next_);
        ar.optional_u64(lap_start_);
        ar.u32(laps_);
        ar.optional_u64(last_);
        ar.optional_u64(best_);
    }

    const CourseDesc& desc() const { return desc_; }
    const GatePosts& posts(size_t gate) const { return posts_[gate]; }
    size_t next_gate() const { return next_; }
    bool lap_running() const { return lap_start_.has_value(); }
    // Ticks since the running lap started, at the world's tick count `ticks`; 0 when none runs.
    uint64_t lap_ticks(uint64_t ticks) const { return lap_start_ ? ticks - *lap_start_ : 0; }
    uint32_t laps() const { return laps_; }
    std::optional<uint64_t> last_lap_ticks() const { return last_; }
    std::optional<uint64_t> best_lap_ticks() const { return best_; }

private:
    CourseDesc desc_;
    std::vector<GatePosts> posts_;
    uint64_t next_ = 0;
    std::optional<uint64_t> lap_start_;  // the world's tick count when gate 0 was crossed
    uint32_t laps_ = 0;
    std::optional<uint64_t> last_, best_;
};

}  // namespace sim
