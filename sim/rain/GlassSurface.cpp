#include "sim/rain/GlassSurface.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/core/DetMath.h"
#include "sim/core/Rng.h"

namespace sim {

namespace {

void refuse(const std::string& what) { throw std::invalid_argument("windshield glass: " + what); }

float length(glm::vec3 v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }
glm::vec3 normalised(glm::vec3 v) { return v / length(v); }

// Cumulative share of the polyline's length at each point; returns the total length.
float parameterise(const std::vector<glm::vec3>& edge, std::vector<float>& at) {
    at.assign(edge.size(), 0.0f);
    float total = 0.0f;
    for (size_t i = 1; i < edge.size(); ++i) {
        total += length(edge[i] - edge[i - 1]);
        at[i] = total;
    }
    if (!(total > 0.0f)) return 0.0f;
    for (float& a : at) a /= total;
    at.back() = 1.0f;
    return total;
}

// Value noise on a lattice of `spacing` cells: smooth blotches of dirt.
std::vector<float> lattice_noise(int cols, int rows, int spacing, Rng& rng) {
    const int lc = cols / spacing + 2, lr = rows / spacing + 2;
    std::vector<float> lattice(size_t(lc) * size_t(lr));
    for (float& v : lattice) v = rng.unit();
    std::vector<float> out(size_t(cols) * size_t(rows));
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i) {
            float x = float(i) / float(spacing), y = float(j) / float(spacing);
            int x0 = int(x), y0 = int(y);
            float fx = x - float(x0), fy = y - float(y0);
            fx = fx * fx * (3.0f - 2.0f * fx);
            fy = fy * fy * (3.0f - 2.0f * fy);
            auto at = [&](int a, int b) { return lattice[size_t(b) * size_t(lc) + size_t(a)]; };
            float top = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * fx;
            float bottom = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * fx;
            out[size_t(j) * size_t(cols) + size_t(i)] = top + (bottom - top) * fy;
        }
    return out;
}

}  // namespace

GlassSurface::GlassSurface(std::vector<glm::vec3> lower, std::vector<glm::vec3> upper, float cell_size_m, Rng& rng)
    : lower_(std::move(lower)), upper_(std::move(upper)), cell_m_(cell_size_m) {
    if (lower_.size() < 2 || upper_.size() < 2)
        refuse("each edge needs at least two points, got " + std::to_string(lower_.size()) + " lower and " +
               std::to_string(upper_.size()) + " upper");
    for (const auto* edge : {&lower_, &upper_})
        for (glm::vec3 p : *edge)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) refuse("an edge point is not finite");
    if (!(cell_size_m > 0.0f) || !std::isfinite(cell_size_m))
        refuse("cell_size_m must be positive, got " + std::to_string(cell_size_m));
    const float lower_len = parameterise(lower_, lower_at_), upper_len = parameterise(upper_, upper_at_);
    if (!(lower_len > 0.0f) || !(upper_len > 0.0f)) refuse("an edge has zero length");
    width_m_ = 0.5f * (lower_len + upper_len);
    float rise = 0.0f;
    for (int k = 0; k <= 8; ++k) {
        float s = float(k) / 8.0f;
        rise += length(edge_point(upper_, upper_at_, s) - edge_point(lower_, lower_at_, s)) / 9.0f;
    }
    height_m_ = rise;
    if (!(height_m_ > 1e-3f)) refuse("the lower and upper edges coincide");
    const double cols = std::floor(double(width_m_) / double(cell_m_)), rows = std::floor(double(height_m_) / double(cell_m_));
    if (cols < 2.0 || rows < 2.0 || cols * rows > double(kMaxCells))
        refuse("cell_size_m " + std::to_string(cell_m_) + " gives " + std::to_string(int64_t(cols)) + " x " +
               std::to_string(int64_t(rows)) + " cells (at least 2 x 2, at most " + std::to_string(kMaxCells) + ")");
    cols_ = int(cols);
    rows_ = int(rows);

    // Affinity: blotches of dirt at two scales and fine grain, stretched to 0..1.
    const std::vector<float> coarse = lattice_noise(cols_, rows_, 9, rng), fine = lattice_noise(cols_, rows_, 3, rng);
    cells_.resize(size_t(cols_) * size_t(rows_));
    const float h = 0.5f * cell_m_;
    for (int j = 0; j < rows_; ++j)
        for (int i = 0; i < cols_; ++i) {
            const size_t k = size_t(j) * size_t(cols_) + size_t(i);
            GlassCell& c = cells_[k];
            glm::vec2 uv = (glm::vec2(float(i), float(j)) + 0.5f) * cell_m_;
            c.tangent_u = normalised(point(uv + glm::vec2(h, 0.0f)) - point(uv - glm::vec2(h, 0.0f)));
            c.tangent_v = normalised(point(uv + glm::vec2(0.0f, h)) - point(uv - glm::vec2(0.0f, h)));
            float a = 0.55f * coarse[k] + 0.3f * fine[k] + 0.15f * rng.unit();
            c.affinity = std::clamp((a - 0.2f) / 0.6f, 0.0f, 1.0f);
        }
}

glm::vec3 GlassSurface::edge_point(const std::vector<glm::vec3>& edge, const std::vector<float>& at, float s) const {
    s = std::clamp(s, 0.0f, 1.0f);
    size_t i = size_t(std::upper_bound(at.begin(), at.end(), s) - at.begin());
    i = std::clamp(i, size_t(1), edge.size() - 1);
    float span = at[i] - at[i - 1];
    float f = span > 0.0f ? (s - at[i - 1]) / span : 0.0f;
    return edge[i - 1] + (edge[i] - edge[i - 1]) * f;
}

glm::vec3 GlassSurface::point(glm::vec2 uv_m) const {
    const float s = uv_m.x / width_m_, t = uv_m.y / height_m_;
    glm::vec3 lo = edge_point(lower_, lower_at_, s), hi = edge_point(upper_, upper_at_, s);
    return lo + (hi - lo) * t;
}

int GlassSurface::cell_of(glm::vec2 uv_m) const {
    int i = std::clamp(int(uv_m.x / cell_m_), 0, cols_ - 1), j = std::clamp(int(uv_m.y / cell_m_), 0, rows_ - 1);
    return j * cols_ + i;
}

void GlassSurface::flat_edges(float width_m, float height_m, float rake_rad, std::vector<glm::vec3>& lower,
                              std::vector<glm::vec3>& upper) {
    const float run = height_m * det::cos(rake_rad), rise = height_m * det::sin(rake_rad);
    lower = {{0.0f, 0.0f, -0.5f * width_m}, {0.0f, 0.0f, 0.5f * width_m}};
    upper = {{-run, rise, -0.5f * width_m}, {-run, rise, 0.5f * width_m}};
}

}  // namespace sim
