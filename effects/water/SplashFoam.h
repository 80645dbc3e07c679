#pragma once
// White water where a splash falls back (docs/effects/water.md, "Foam where the splash
// falls back"): presentation only, the sim is read, never written. Each frame the
// airborne vertices of the splash sheets are followed to where and at which tick they
// will land (their flight is ballistic, stepped as the sim steps it, so one look at a
// vertex in the air is enough); from that tick on each landing leaves a patch of foam
// that spreads and fades over a few seconds. The foam is rasterised into a small
// world-space map over the live landings, which the sea's shading reads.
//
// A function of the ticks rendered, not of wall time: the same frames give the same
// foam. Forgotten when the world is restored from a snapshot or its tick goes back.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <glm/vec2.hpp>

#include "effects/water/WaterView.h"

namespace effects {

struct FoamLook {
    float life_s = 5.0f;           // a landing's foam is gone after this
    float fade_s = 1.8f;           // its strength falls by e over this
    float start_radius_m = 0.15f;  // the patch one landing vertex leaves
    float spread_m = 0.9f;         // how much wider it grows, approached over spread_s
    float spread_s = 1.8f;
    float drift_m = 0.6f;          // how far it drifts out from the splash, over spread_s: the ring opens
    float per_landing = 0.3f;      // strength of one vertex's patch at its centre
    // The bow's sheet throws vertices on every tick under way: a share of that, so its
    // foam along the hull and in the wake thins to lace instead of a white carpet.
    float bow_share = 0.12f;
};

// The foam map: size x size texels of texel_m, texel (i, j) centred at origin_xz +
// (i + 0.5, j + 0.5) * texel_m, values 0..255 (255: solid white water).
struct FoamField {
    glm::vec2 origin_xz{0.0f};
    float texel_m = 0.1f;
    int size = 0;  // 0: no foam anywhere
    std::vector<uint8_t> texels;

    // The stored value at xz, 0..1 (nearest texel; 0 outside).
    float at(glm::vec2 xz) const;
};

class SplashFoam {
public:
    static constexpr int kMaxSide = 384;        // texels of the map along a side
    static constexpr float kFinestTexelM = 0.1f;  // doubled until the live landings fit
    // Of the bow's sheet, which lands thousands of vertices a second under way, one vertex
    // in this many is followed, standing for the others (the cost is per landing).
    static constexpr uint32_t kBowStride = 16;

    // Follows the sheets of `view` (those with velocities and an id) at view.tick, and
    // rasterises the foam of the landings up to it into field().
    void update(const WaterView& view, const FoamLook& look);
    const FoamField& field() const { return field_; }
    size_t live_landings() const { return live_; }

private:
    struct Landing {
        glm::vec2 xz{0.0f};
        glm::vec2 out{0.0f};  // unit, away from the splash's centre (0 at it)
        int64_t tick = 0;
        bool bow = false;
    };
    void forget();
    void follow(const SheetView& sheet, const WaterView& view);
    void rasterise(int64_t now, float tick_s, const FoamLook& look);

    std::vector<Landing> landings_;
    // Per (sheet, vertex): the tick its current flight lands, so a vertex seen in the air
    // on several frames lands once.
    std::unordered_map<uint64_t, int64_t> flights_;
    FoamField field_;
    std::vector<float> accum_;  // scratch
    size_t live_ = 0;
    int64_t last_tick_ = -1;
    uint64_t restore_generation_ = 0;
};

}  // namespace effects
