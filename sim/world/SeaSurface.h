#pragma once
// The sea as floating bodies see it. The flat sea is the default; a wave simulation
// is the world's sea (Subsystem::sea_surface) so boats and objects ride its waves.
#include <glm/vec2.hpp>

namespace sim {

class SeaSurface {
public:
    virtual ~SeaSurface() = default;
    virtual float height_at(glm::vec2 xz) const = 0;
};

class FlatSea final : public SeaSurface {
public:
    explicit FlatSea(float level_m) : level_m_(level_m) {}
    float height_at(glm::vec2) const override { return level_m_; }

private:
    float level_m_;
};

}  // namespace sim
