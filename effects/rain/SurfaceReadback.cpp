#include "effects/rain/SurfaceReadback.h"

#include <algorithm>
#include <cmath>

namespace effects {

std::vector<SurfaceSample> read_surface(const gl::Texture& surface) {
    const size_t texels = size_t(surface.width()) * size_t(surface.height());
    std::vector<float> rgba(texels * 4);
    glGetTextureImage(surface.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
    std::vector<SurfaceSample> out(texels);
    for (size_t k = 0; k < out.size(); ++k) {
        const float x = rgba[4 * k], y = rgba[4 * k + 1];
        out[k] = {{x, y, std::sqrt(std::max(1.0f - x * x - y * y, 0.0f))}, rgba[4 * k + 3] > 0.5f ? rgba[4 * k + 2] : 0.0f};
    }
    return out;
}

}  // namespace effects
