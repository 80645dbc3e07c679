#include "sim/water/WaveGrid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/core/DetMath.h"
#include "sim/core/NumberText.h"
#include "sim/water/WaveRow.h"

namespace sim {

namespace {

constexpr float kPi = 3.14159265f;
[[noreturn]] void refuse(const std::string& what) { throw std::invalid_argument("WaveGrid: " + what); }

}  // namespace

WaveGrid::WaveGrid(const WaveGridParams& p, float dt_s) {
    if (p.size < 8 || p.size > 2048) refuse("size must be 8..2048 cells per side, got " + std::to_string(p.size));
    if (!std::isfinite(p.spacing_m) || p.spacing_m <= 0.0f)
        refuse("spacing_m must be a positive number of metres, got " + num(p.spacing_m));
    if (!std::isfinite(p.wave_speed_mps) || p.wave_speed_mps <= 0.0f)
        refuse("wave_speed_mps must be positive, got " + num(p.wave_speed_mps));
    if (!std::isfinite(dt_s) || dt_s <= 0.0f) refuse("time step must be positive, got " + num(dt_s) + " s");
    if (!(p.damping_per_s >= 0.0f && p.damping_per_s < 1.0f))
        refuse("damping_per_s is the fraction of wave energy lost per second and must be in [0, 1), got " +
               num(p.damping_per_s));
    if (!std::isfinite(p.origin_xz.x) || !std::isfinite(p.origin_xz.y)) refuse("origin_xz must be finite");
    const double c = double(p.wave_speed_mps) * p.wave_speed_mps * dt_s * dt_s / (double(p.spacing_m) * p.spacing_m);
    if (c > 0.5)
        refuse("unstable parameters: the explicit scheme needs c = v^2 dt^2 / h^2 <= 0.5, but v = " +
               num(p.wave_speed_mps) + " m/s, dt = " + num(dt_s) + " s, h = " + num(p.spacing_m) + " m give c = " +
               num(c) + " (lower the wave speed or raise the spacing)");
    size_ = p.size;
    h_ = p.spacing_m;
    origin_ = p.origin_xz;
    c_ = float(c);
    // Damping drags on the surface's velocity, y[n] - y[n-1]: with keep = (1 - d)^dt of
    // it left each step, every wave's energy shrinks by 1 - d per second. A factor on
    // the whole update instead pulls every height back to 0 as hard as the waves are
    // damped, a restoring term that makes metre-long waves ring in place rather than
    // travel. The water the pushes take away still has to come back: the least pull
    // that returns the mean level without overshoot, (1 - sqrt(keep))^2, whose ~0.14
    // rad/s is far below any wave's frequency.
    damp_ = float(det::pow(1.0 - double(p.damping_per_s), double(dt_s)));
    pull_ = (1.0f - std::sqrt(damp_)) * (1.0f - std::sqrt(damp_));
    const size_t n = size_t(size_) * size_t(size_);
    cur_.assign(n, 0.0f);
    prev_.assign(n, 0.0f);
    land_.assign(n, 0);
    rebuild_coefficients();
}

void WaveGrid::rebuild_coefficients() {
    const int n = size_;
    centre_weight_.resize(land_.size());
    row_general_.assign(size_t(n), 0);
    auto water = [&](int i, int j) { return i >= 0 && j >= 0 && i < n && j < n && !land_[size_t(j) * n + i]; };
    std::vector<uint8_t> row_has_land(size_t(n), 0);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            size_t idx = size_t(j) * n + i;
            int k = int(water(i - 1, j)) + int(water(i + 1, j)) + int(water(i, j - 1)) + int(water(i, j + 1));
            centre_weight_[idx] = 1.0f + damp_ - pull_ - float(k) * c_;
            if (land_[idx]) row_has_land[size_t(j)] = 1;
        }
    for (int j = 0; j < n; ++j) {
        bool edge = j == 0 || j == n - 1;
        bool near_land = row_has_land[size_t(j)] || (j > 0 && row_has_land[size_t(j) - 1]) ||
                         (j + 1 < n && row_has_land[size_t(j) + 1]);
        row_general_[size_t(j)] = uint8_t(edge || near_land);
    }
}

void WaveGrid::step_rows(size_t row_begin, size_t row_end) {
    const size_t n = size_t(size_);
    const float* __restrict y = cur_.data();
    float* __restrict out = prev_.data();  // holds y[n-1]; becomes y[n+1] in place, cell by cell
    // y[n+1] = c sum + (2 - k c) y[n] - y[n-1] - (1 - keep)(y[n] - y[n-1]) - pull y[n]
    //        = c sum + (1 + keep - pull - k c) y[n] - keep y[n-1]
    const float c = c_, keep = damp_;
    const float w3 = 1.0f + keep - pull_ - 3.0f * c, w4 = 1.0f + keep - pull_ - 4.0f * c;
    const WaveRowCode code = wave_row_has_avx2() ? WaveRowCode::kAvx2 : WaveRowCode::kBaseline;
    for (size_t j = row_begin; j < row_end; ++j) {
        const size_t row = j * n;
        if (!row_general_[j]) {
            // Interior row with no land near: the tight loop, edges k = 3.
            step_wave_row(y + row - n, y + row, y + row + n, out + row, n, {c, w3, w4, keep}, code);
            continue;
        }
        for (size_t i = 0; i < n; ++i) {
            const size_t idx = row + i;
            if (land_[idx]) {
                out[idx] = 0.0f;
                continue;
            }
            // Missing neighbours (outside, or land pinned at 0) add nothing; their
            // absence is in the centre weight 2 - k c.
            float l = i > 0 ? y[idx - 1] : 0.0f;
            float rt = i + 1 < n ? y[idx + 1] : 0.0f;
            float u = j > 0 ? y[idx - n] : 0.0f;
            float d = j + 1 < n ? y[idx + n] : 0.0f;
            out[idx] = flushed(c * ((l + rt) + (u + d)) + centre_weight_[idx] * y[idx] - keep * out[idx]);
        }
    }
}

void WaveGrid::step() {
    step_rows(0, size_t(size_));
    std::swap(cur_, prev_);
}

void WaveGrid::step(JobPool& jobs) {
    jobs.parallel_for(size_t(size_), [this](size_t b, size_t e) { step_rows(b, e); });
    std::swap(cur_, prev_);
}

float WaveGrid::sample(glm::vec2 xz) const {
    float fx = (xz.x - origin_.x) / h_, fz = (xz.y - origin_.y) / h_;
    const float last = float(size_ - 1);
    if (!(fx >= 0.0f && fx <= last && fz >= 0.0f && fz <= last)) return 0.0f;  // also NaN
    int i = std::min(int(fx), size_ - 2), j = std::min(int(fz), size_ - 2);
    float tx = fx - float(i), tz = fz - float(j);
    const float* r0 = cur_.data() + size_t(j) * size_t(size_) + size_t(i);
    const float* r1 = r0 + size_;
    float a = r0[0] + (r0[1] - r0[0]) * tx;
    float b = r1[0] + (r1[1] - r1[0]) * tx;
    return a + (b - a) * tz;
}

glm::vec3 WaveGrid::normal(glm::vec2 xz) const {
    float dx = (sample({xz.x + h_, xz.y}) - sample({xz.x - h_, xz.y})) / (2.0f * h_);
    float dz = (sample({xz.x, xz.y + h_}) - sample({xz.x, xz.y - h_})) / (2.0f * h_);
    float len = std::sqrt(dx * dx + 1.0f + dz * dz);
    return {-dx / len, 1.0f / len, -dz / len};
}

void WaveGrid::push(glm::vec2 xz, float radius_m, float depth_m) {
    if (!std::isfinite(xz.x) || !std::isfinite(xz.y) || !std::isfinite(radius_m) || !std::isfinite(depth_m))
        refuse("push needs finite position, radius and depth, got (" + num(xz.x) + ", " + num(xz.y) + "), " +
               num(radius_m) + " m, " + num(depth_m) + " m");
    const float r = std::max(radius_m, h_);
    const float fx = (xz.x - origin_.x) / h_, fz = (xz.y - origin_.y) / h_, fr = r / h_;
    const float last = float(size_ - 1);
    if (fx + fr < 0.0f || fz + fr < 0.0f || fx - fr > last || fz - fr > last) return;
    const int i0 = std::max(0, int(std::ceil(fx - fr))), i1 = std::min(size_ - 1, int(std::floor(fx + fr)));
    const int j0 = std::max(0, int(std::ceil(fz - fr))), j1 = std::min(size_ - 1, int(std::floor(fz + fr)));
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            size_t idx = size_t(j) * size_t(size_) + size_t(i);
            if (land_[idx]) continue;
            float ddx = float(i) - fx, ddz = float(j) - fz;
            float d = std::sqrt(ddx * ddx + ddz * ddz) / fr;
            if (d >= 1.0f) continue;
            float w = 0.5f * (1.0f + det::cos(kPi * d));
            cur_[idx] = flushed(cur_[idx] - depth_m * w);
            prev_[idx] = flushed(prev_[idx] - depth_m * w);
        }
}

void WaveGrid::set_heights(const std::vector<float>& heights) {
    if (heights.size() != cur_.size())
        refuse("set_heights needs " + std::to_string(cur_.size()) + " heights (size^2), got " +
               std::to_string(heights.size()));
    for (size_t i = 0; i < heights.size(); ++i) {
        if (!std::isfinite(heights[i])) refuse("set_heights: height " + std::to_string(i) + " is not finite");
        cur_[i] = prev_[i] = land_[i] ? 0.0f : flushed(heights[i]);
    }
}

double WaveGrid::volume() const {
    double sum = 0.0;
    for (float y : cur_) sum += double(y);
    return sum * double(h_) * double(h_);
}

void WaveGrid::set_land_mask(std::vector<uint8_t> mask) {
    if (mask.size() != land_.size())
        refuse("land mask needs " + std::to_string(land_.size()) + " cells (size^2), got " +
               std::to_string(mask.size()));
    for (uint8_t& m : mask) m = m ? 1 : 0;
    land_ = std::move(mask);
    for (size_t i = 0; i < land_.size(); ++i)
        if (land_[i]) cur_[i] = prev_[i] = 0.0f;
    rebuild_coefficients();
}


}  // namespace sim
