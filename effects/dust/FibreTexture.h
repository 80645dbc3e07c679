#pragma once
// A grown fibre volume on the GPU: a 2D array texture, one layer per shell, with mip
// levels whose coverage is rescaled to match the full-resolution layer (Castaño's
// coverage-preserving alpha mips), so distant dust keeps its density instead of
// dissolving under the alpha test. Also a tiling luminance noise for the clipping.
#include <vector>

#include "effects/dust/FibreVolume.h"
#include "effects/gl/Texture.h"

namespace effects {

// The coverage threshold the shell shader keeps fibres above (0..1).
inline constexpr float kFibreThreshold = 0.5f;

// Mip levels of one layer's two-byte texels (coverage, rank): averaged 2x2, then
// coverage scaled so the fraction above kFibreThreshold matches level 0's.
std::vector<std::vector<uint8_t>> fibre_mips(const FibreVolume& volume, int layer);

class FibreTexture {
public:
    explicit FibreTexture(const FibreVolume& volume, const char* label);
    void bind(GLuint fibre_unit, GLuint luminance_unit) const {
        fibres_.bind(fibre_unit);
        luminance_.bind(luminance_unit);
    }
    int layers() const { return fibres_.layers(); }

private:
    gl::Texture fibres_, luminance_;
};

}  // namespace effects
