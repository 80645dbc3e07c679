#pragma once
// The dust on the warehouse props (seed 004; docs/effects/dust.md): the sources around each
// dusty prop and the amount at every vertex of the props' tessellated surfaces. The
// amounts are computed when the world is built and then only lowered: a thrown object
// or an energy shot passing close blows the dust off where it went. Stepped after the
// objects and the weapon, whose state it reads.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "sim/dust/DustDesc.h"
#include "sim/dust/DustSurface.h"
#include "sim/world/DescribedSubsystem.h"

namespace sim {

class ThrownObjects;
class Weapon;

class DustField final : public DescribedSubsystem<DustField> {
public:
    // Throws std::invalid_argument naming the parameter or prop that cannot be used.
    explicit DustField(const DustDesc& desc);

    static constexpr std::string_view kName = "dust";
    std::string_view name() const override { return kName; }
    void connect(const SubsystemLinks& links) override;
    void step(StepContext& ctx) override;
    template <class Archive> void describe(Archive& ar) {
        ar.u64(revision_);
        ar.words_digest(amounts_);
    }

    const DustDesc& desc() const { return desc_; }
    const DustSurface& surface() const { return surface_; }
    std::span<const float> amounts() const { return amounts_; }
    // Sources of surface().props()[i].
    const std::vector<glm::vec3>& sources(size_t prop) const { return sources_[prop]; }
    // Changes whenever an amount does: renderers re-upload on a new revision.
    uint64_t revision() const { return revision_; }

    // Lowers the amounts within radius_m of the segment p0-p1 (fully inside 60% of
    // it, fading out to the edge). Returns whether anything changed.
    bool clear_along(glm::vec3 p0, glm::vec3 p1, float radius_m);
    // The amount at the vertex nearest to p (for tests and tools).
    float amount_near(glm::vec3 p) const;

private:
    DustDesc desc_;
    DustSurface surface_;
    std::vector<float> amounts_;
    std::vector<std::vector<glm::vec3>> sources_;
    uint64_t revision_ = 0;

    // Connected at assembly (connect).
    const ThrownObjects* thrown_ = nullptr;
    const Weapon* weapon_ = nullptr;
};

}  // namespace sim
