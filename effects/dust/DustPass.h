#pragma once
// Dusty props (seed 004, docs/effects/dust.md "What is implemented"): over each dusty
// prop already in the opaque scene, a stack of shells pushed out along the normal by
// the sim's dust amount, each keeping the texels of its fibre layer that pass the fibre
// test and the luminance clipping; fins on the edges where the surface is seen edge-on.
// Alpha tested, depth written: part of the opaque scene. Without a sim::DustField it
// draws nothing.
#include <array>
#include <memory>
#include <optional>

#include "effects/dust/DustGeometry.h"
#include "effects/dust/DustLook.h"
#include "effects/dust/FibreTexture.h"
#include "effects/gl/Program.h"
#include "effects/scene/Pass.h"

namespace effects {

struct DustLod {
    int max_shells = 12;        // up close: more shells than fibre layers, so none shows
    int min_shells = 2;         // far away: the film and one shell once the stack is a pixel
    float full_detail_m = 2.0f; // closer than this: max_shells; beyond, falling as 1/distance
    float fin_min_px = 2.0f;      // fins only where the full stack is this tall on screen
                                  // (lower, the shells cannot show as lines)
    float coarse_from_m = 5.0f;   // props farther away: shells and fins on the coarse level
};

class DustPass final : public Pass {
public:
    DustPass();
    std::string_view name() const override { return "dust"; }
    void render(const FrameContext& frame) override;
    void register_params(ParamRegistry& params) override;

    // Shells drawn for a prop whose nearest point is distance_m from the eye.
    int shells_at(float distance_m) const;
    // Whether a prop whose dust stack projects to stack_px pixels gets fins.
    bool fins_at(float stack_px) const { return fins_ && stack_px >= lod_.fin_min_px; }
    // The DustGeometry level drawn for a prop distance_m from the eye.
    int level_at(float distance_m) const;
    DustLod& lod() { return lod_; }
    bool& fins_enabled() { return fins_; }
    const DustGeometry& geometry() const { return geometry_; }

private:
    const FibreTexture& fibres_for(sim::DustKind kind, const FibreDirections& directions);

    gl::Program light_, shell_, fin_;
    DustGeometry geometry_;
    std::array<std::unique_ptr<FibreTexture>, sim::kDustKindCount> fibres_;
    DustLod lod_;
    bool fins_ = true;
};

}  // namespace effects
