#include "sim/dust/SourceDepthMap.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "sim/core/DetMath.h"

namespace sim {

namespace {
constexpr float kInf = std::numeric_limits<float>::infinity();
// Depth slack of the visibility test: a few texels' worth of the sampled surfaces.
constexpr float kBias_m = 0.03f;
// glm::perspective (right-handed, clip z in [-w, w]) with the sim's own tan: glm's calls libm.
glm::mat4 perspective(float fovy_rad, float aspect, float near_m, float far_m) {
    const float tan_half = det::tan(fovy_rad / 2.0f);
    glm::mat4 m(0.0f);
    m[0][0] = 1.0f / (aspect * tan_half);
    m[1][1] = 1.0f / tan_half;
    m[2][2] = -(far_m + near_m) / (far_m - near_m);
    m[2][3] = -1.0f;
    m[3][2] = -(2.0f * far_m * near_m) / (far_m - near_m);
    return m;
}
}  // namespace

SourceDepthMap::SourceDepthMap(glm::vec3 source, glm::vec3 centre, float radius, int size)
    : size_(size), depth_(size_t(size) * size_t(size), kInf) {
    glm::vec3 axis = centre - source;
    float dist = glm::length(axis);
    glm::vec3 up = std::fabs(axis.y) > 0.99f * dist ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
    float half_angle = det::asin(std::min(radius / std::max(dist, 1e-3f), 0.99f));
    near_m_ = std::max(0.05f, dist - radius * 1.05f);
    view_proj_ = perspective(2.0f * half_angle * 1.05f, 1.0f, near_m_, dist + radius * 1.1f) *
                 glm::lookAt(source, centre, up);
}

void SourceDepthMap::rasterise(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    glm::vec4 clip[3] = {view_proj_ * glm::vec4(a, 1.0f), view_proj_ * glm::vec4(b, 1.0f),
                         view_proj_ * glm::vec4(c, 1.0f)};
    float sx[3], sy[3], inv_w[3];
    for (int k = 0; k < 3; ++k) {
        if (!(clip[k].w >= near_m_)) return;
        inv_w[k] = 1.0f / clip[k].w;
        sx[k] = (clip[k].x * inv_w[k] * 0.5f + 0.5f) * float(size_);
        sy[k] = (clip[k].y * inv_w[k] * 0.5f + 0.5f) * float(size_);
    }
    float area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
    if (std::fabs(area) < 1e-12f) return;
    int x0 = std::max(0, int(std::floor(std::min({sx[0], sx[1], sx[2]}))));
    int x1 = std::min(size_ - 1, int(std::ceil(std::max({sx[0], sx[1], sx[2]}))));
    int y0 = std::max(0, int(std::floor(std::min({sy[0], sy[1], sy[2]}))));
    int y1 = std::min(size_ - 1, int(std::ceil(std::max({sy[0], sy[1], sy[2]}))));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            float px = float(x) + 0.5f, py = float(y) + 0.5f;
            // Barycentrics from edge functions; either winding.
            float w0 = ((sx[1] - px) * (sy[2] - py) - (sx[2] - px) * (sy[1] - py)) / area;
            float w1 = ((sx[2] - px) * (sy[0] - py) - (sx[0] - px) * (sy[2] - py)) / area;
            float w2 = 1.0f - w0 - w1;
            if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f) continue;
            // 1/w is affine in screen space: interpolate it, then invert.
            float depth = 1.0f / (w0 * inv_w[0] + w1 * inv_w[1] + w2 * inv_w[2]);
            float& d = depth_[size_t(y) * size_t(size_) + size_t(x)];
            d = std::min(d, depth);
        }
}

float SourceDepthMap::visibility(glm::vec3 p) const {
    glm::vec4 clip = view_proj_ * glm::vec4(p, 1.0f);
    if (!(clip.w > 0.0f)) return 1.0f;
    float fx = (clip.x / clip.w * 0.5f + 0.5f) * float(size_);
    float fy = (clip.y / clip.w * 0.5f + 0.5f) * float(size_);
    int cx = int(std::floor(fx)), cy = int(std::floor(fy));
    if (cx < 0 || cy < 0 || cx >= size_ || cy >= size_) return 1.0f;
    int seen = 0, count = 0;
    for (int y = cy - 1; y <= cy + 1; ++y)
        for (int x = cx - 1; x <= cx + 1; ++x) {
            if (x < 0 || y < 0 || x >= size_ || y >= size_) continue;
            ++count;
            if (clip.w <= depth_[size_t(y) * size_t(size_) + size_t(x)] + kBias_m) ++seen;
        }
    return float(seen) / float(count);
}

}  // namespace sim
