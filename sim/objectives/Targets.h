#pragma once
// The level's targets and which of them were hit: a thrown object touching one, or an
// energy shot's segment passing within its radius, hits it once and for good.
#include <cstdint>
#include <vector>

#include "sim/objectives/ObjectiveDesc.h"

namespace sim {

struct ThrownObject;
struct Shot;

enum class HitBy : uint8_t { Nothing, Object, Shot };

struct TargetState {
    TargetDesc desc;
    HitBy hit_by = HitBy::Nothing;
    uint64_t hit_at_ticks = 0;  // the world's tick count when it was hit
    bool hit() const { return hit_by != HitBy::Nothing; }
};

class Targets {
public:
    explicit Targets(const std::vector<TargetDesc>& targets);

    // This tick's objects and shots against the targets not hit yet.
    void hit_by(const std::vector<ThrownObject>& objects, const std::vector<Shot>& shots, uint64_t ticks);
    // Which were hit, by what and when (the targets are the level's).
    template <class Archive> void describe(Archive& ar) {
        for (TargetState& t : states_) {
            ar.enum32(t.hit_by);
            ar.u64(t.hit_at_ticks);
        }
    }

    const std::vector<TargetState>& states() const { return states_; }
    size_t hit_count() const;

private:
    std::vector<TargetState> states_;
};

}  // namespace sim
