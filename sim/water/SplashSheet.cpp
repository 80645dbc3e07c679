#include "sim/water/SplashSheet.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/core/DetMath.h"
#include "sim/core/NumberText.h"

namespace sim {

namespace {

bool positive(float v) { return std::isfinite(v) && v > 0.0f; }

// Which torn vertices gather their neighbours' film into a drop: a hash of where the
// vertex is (deterministic, and no regular pattern over the sheet).
uint32_t bead(glm::vec3 p) {
    uint32_t h = std::bit_cast<uint32_t>(p.x) * 0x9E3779B1u ^ std::bit_cast<uint32_t>(p.z) * 0x85EBCA77u ^
                 std::bit_cast<uint32_t>(p.y) * 0xC2B2AE3Du;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    return h;
}

}  // namespace

SplashSheet::SplashSheet(const SplashSheetParams& params) : p_(params), n_(params.size) {
    auto refuse = [](const std::string& what) { throw std::invalid_argument("SplashSheet: " + what); };
    if (p_.size < 3 || p_.size > 256) refuse("size must be 3..256 vertices per side, got " + std::to_string(p_.size));
    if (!positive(p_.spacing_m)) refuse("spacing_m must be positive, got " + num(p_.spacing_m));
    if (!std::isfinite(p_.hidden_depth_m) || p_.hidden_depth_m < 0.0f)
        refuse("hidden_depth_m must be >= 0, got " + num(p_.hidden_depth_m));
    if (!std::isfinite(p_.velocity_scale) || p_.velocity_scale < 0.0f)
        refuse("velocity_scale must be >= 0, got " + num(p_.velocity_scale));
    if (!std::isfinite(p_.speed_per_momentum) || p_.speed_per_momentum < 0.0f)
        refuse("speed_per_momentum must be >= 0, got " + num(p_.speed_per_momentum));
    if (!positive(p_.max_speed_mps) || p_.max_speed_mps > 100.0f)
        refuse("max_speed_mps must be in (0, 100], got " + num(p_.max_speed_mps));
    if (!positive(p_.gravity_mps2)) refuse("gravity_mps2 must be positive, got " + num(p_.gravity_mps2));
    if (p_.min_skirt_rings < 1 || p_.min_skirt_rings > 16)
        refuse("min_skirt_rings must be 1..16, got " + std::to_string(p_.min_skirt_rings));
    if (!std::isfinite(p_.ripple_depth_m) || p_.ripple_depth_m < 0.0f)
        refuse("ripple_depth_m must be >= 0, got " + num(p_.ripple_depth_m));
    if (!std::isfinite(p_.tear_stretch) || p_.tear_stretch < 1.0f)
        refuse("tear_stretch must be >= 1, got " + num(p_.tear_stretch));
    if (!positive(p_.torn_drop_radius_m)) refuse("torn_drop_radius_m must be positive, got " + num(p_.torn_drop_radius_m));
    if (p_.torn_drop_share < 1 || p_.torn_drop_share > 64)
        refuse("torn_drop_share must be 1..64, got " + std::to_string(p_.torn_drop_share));
    if (!(p_.bow_lift >= 0.0f && p_.bow_lift <= 1.0f)) refuse("bow_lift must be in [0, 1], got " + num(p_.bow_lift));
    if (!std::isfinite(p_.rim_break_stretch) || p_.rim_break_stretch < 1.0f)
        refuse("rim_break_stretch must be >= 1, got " + num(p_.rim_break_stretch));
    const size_t count = size_t(n_) * size_t(n_);
    pos_.assign(count, glm::vec3(0.0f));
    vel_.assign(count, glm::vec3(0.0f));
    airborne_.assign(count, 0);
}

glm::vec2 SplashSheet::rest_xz(int i, int j) const {
    const int half = n_ / 2;
    return {centre_.x + float(i - half) * p_.spacing_m, centre_.y + float(j - half) * p_.spacing_m};
}

SplashSheet::Band SplashSheet::ring_band(float object_radius_m) const {
    const int max_ring = (n_ - 1) / 2;  // the whole band must lie inside the sheet
    float cells = std::isfinite(object_radius_m) ? object_radius_m / p_.spacing_m : 1.0f;
    int rim = std::clamp(int(std::lround(std::clamp(cells, 0.0f, 1e6f))), 1, max_ring);
    int skirt = std::clamp(rim, p_.min_skirt_rings, 2 * p_.min_skirt_rings);
    return {rim, std::min(rim + skirt, max_ring)};
}

float SplashSheet::launch_speed(float momentum_kgmps) const {
    float m = std::isfinite(momentum_kgmps) ? std::max(momentum_kgmps, 0.0f) : 0.0f;
    return std::min(m * p_.speed_per_momentum, p_.max_speed_mps) * p_.velocity_scale;
}

void SplashSheet::reset(glm::vec2 centre_xz, const WaveGrid& grid, float sea_level_m) {
    centre_ = centre_xz;
    flying_ = 0;
    for (int j = 0; j < n_; ++j)
        for (int i = 0; i < n_; ++i) {
            size_t idx = size_t(j) * size_t(n_) + size_t(i);
            glm::vec2 r = rest_xz(i, j);
            pos_[idx] = {r.x, sea_level_m + grid.sample(r) - p_.hidden_depth_m, r.y};
            vel_[idx] = glm::vec3(0.0f);
            airborne_[idx] = 0;
        }
}

void SplashSheet::launch(size_t idx, glm::vec3 velocity, const WaveGrid& grid, float sea_level_m) {
    const int i = int(idx % size_t(n_)), j = int(idx / size_t(n_));
    glm::vec2 r = rest_xz(i, j);
    // Leaves from the surface itself, so even a weak splash shows for a moment.
    pos_[idx] = {r.x, sea_level_m + grid.sample(r), r.y};
    vel_[idx] = velocity;
    airborne_[idx] = 1;
    ++flying_;
}

int SplashSheet::first_splash(float object_radius_m, float momentum_kgmps, Rng& rng, const WaveGrid& grid,
                              float sea_level_m, std::optional<glm::vec2> ahead, glm::vec2 carry_xz) {
    const Band band = ring_band(object_radius_m);
    const float s = launch_speed(momentum_kgmps);
    const int half = n_ / 2;
    // The seed draws alpha in [0.1, 1] independently per vertex; neighbours then fly
    // apart into shards. Here alpha is drawn per direction (kAlphaBins round the ring)
    // and blended smoothly between them: still in [0.1, 1] at every vertex, but the
    // crown holds together as one sheet whose height varies round the rim.
    constexpr int kAlphaBins = 12;
    float alpha_bin[kAlphaBins];
    for (float& a : alpha_bin) a = rng.range(0.1f, 1.0f);
    auto alpha_at = [&](float theta) {
        float f = (theta + 3.14159265f) / 6.2831853f * float(kAlphaBins);
        int k0 = int(std::floor(f));
        float t = f - float(k0);
        t = t * t * (3.0f - 2.0f * t);
        k0 = ((k0 % kAlphaBins) + kAlphaBins) % kAlphaBins;
        return alpha_bin[k0] + (alpha_bin[(k0 + 1) % kAlphaBins] - alpha_bin[k0]) * t;
    };
    int launched = 0;
    for (int dj = -band.outer; dj <= band.outer; ++dj)
        for (int di = -band.outer; di <= band.outer; ++di) {
            const int ring = std::max(std::abs(di), std::abs(dj));
            if (ring < band.inner) continue;
            if (ahead && float(di) * ahead->x + float(dj) * ahead->y < 0.0f) continue;  // behind: seed 4.2.4
            const size_t idx = size_t(half + dj) * size_t(n_) + size_t(half + di);
            if (airborne_[idx]) continue;
            // The rim ring flies at the seed's speed; the skirt outside it slower, so
            // at any moment it lies below and inside the rim: the crown's wall.
            const float skirt = float(ring - band.inner) / float(band.outer - band.inner + 1);
            const float a = alpha_at(det::atan2(float(dj), float(di))) * s * (1.0f - skirt);
            // Seed: alpha*s along an axis, alpha*s/2 per axis on the diagonals; in
            // between, the same rule blended (the L1-normalised offset).
            const float l1 = float(std::abs(di) + std::abs(dj));
            glm::vec3 v(a * float(di) / l1, ahead ? a * p_.bow_lift : a, a * float(dj) / l1);
            v.x += carry_xz.x;
            v.z += carry_xz.y;
            launch(idx, v, grid, sea_level_m);
            ++launched;
        }
    return launched;
}

int SplashSheet::second_splash(float object_radius_m, float momentum_kgmps, Rng& rng, const WaveGrid& grid,
                               float sea_level_m) {
    const int patch = std::max(1, ring_band(object_radius_m).outer / 2);
    const float s = launch_speed(momentum_kgmps);
    const int half = n_ / 2;
    // One alpha for the whole jet and a smooth fall-off from its axis: drawn per vertex,
    // neighbours flew apart and the column read as a heap of shards.
    const float alpha = 0.75f + 0.25f * rng.range(0.1f, 1.0f);
    const float reach = float(patch + 1);
    int launched = 0;
    for (int dj = -patch; dj <= patch; ++dj)
        for (int di = -patch; di <= patch; ++di) {
            const size_t idx = size_t(half + dj) * size_t(n_) + size_t(half + di);
            if (airborne_[idx]) continue;
            const float r2 = float(di * di + dj * dj) / (reach * reach);
            const float up = alpha * s * (1.0f - 0.6f * r2);
            glm::vec3 v(0.0f, up, 0.0f);
            if (r2 > 0.0f) {  // a slight outward lean keeps the column from being a needle
                float len = std::sqrt(float(di * di + dj * dj));
                v.x = 0.05f * up * float(di) / len;
                v.z = 0.05f * up * float(dj) / len;
            }
            launch(idx, v, grid, sea_level_m);
            ++launched;
        }
    return launched;
}

void SplashSheet::hide(size_t idx, const WaveGrid& grid, float sea_level_m) {
    airborne_[idx] = 0;
    vel_[idx] = glm::vec3(0.0f);
    --flying_;
    const glm::vec2 r = rest_xz(int(idx % size_t(n_)), int(idx / size_t(n_)));
    pos_[idx] = {r.x, sea_level_m + grid.sample(r) - p_.hidden_depth_m, r.y};
}

void SplashSheet::step(float dt, const WaveGrid& grid, float sea_level_m, std::vector<Ripple>& ripples) {
    torn_.clear();
    tore_off_ = 0;
    if (flying_ == 0) return;  // nothing to show: hidden vertices need not follow
    const float g = p_.gravity_mps2;
    for (size_t idx = 0; idx < airborne_.size(); ++idx) {
        if (!airborne_[idx]) continue;
        glm::vec3& v = vel_[idx];
        glm::vec3& p = pos_[idx];
        v.y -= g * dt;
        p += v * dt;
        if (v.y < 0.0f && p.y < sea_level_m + grid.sample({p.x, p.z})) {
            ripples.push_back({{p.x, p.z}, p_.ripple_depth_m});
            hide(idx, grid, sea_level_m);
        }
    }
    // Torn off: no airborne neighbour within reach, so no triangle of the film holds it
    // (a lone vertex would otherwise fly on as an invisible point, or a dot); or on the
    // film's free edge or at a peak with its longest bond past the rim's breaking
    // stretch, or at a peak past its apex. All are found before any is hidden, so the order of the scan does not
    // matter, and a receding rim loses one row of vertices a tick at most.
    const float reach2 = p_.tear_stretch * p_.spacing_m * p_.tear_stretch * p_.spacing_m;
    const float rim2 = p_.rim_break_stretch * p_.spacing_m * p_.rim_break_stretch * p_.spacing_m;
    const size_t n = size_t(n_);
    tearing_.clear();
    for (size_t idx = 0; idx < airborne_.size(); ++idx) {
        if (!airborne_[idx]) continue;
        const size_t i = idx % n, j = idx / n;
        bool held = false, edge = false, peak = true;
        float longest2 = 0.0f;
        for (int k = 0; k < 4; ++k) {
            if ((k == 0 && i == 0) || (k == 1 && i + 1 == n) || (k == 2 && j == 0) || (k == 3 && j + 1 == n)) {
                edge = true;
                continue;
            }
            const size_t b = k == 0 ? idx - 1 : k == 1 ? idx + 1 : k == 2 ? idx - n : idx + n;
            if (!airborne_[b]) {
                edge = true;
                continue;
            }
            const glm::vec3 d = pos_[b] - pos_[idx];
            const float d2 = d.x * d.x + d.y * d.y + d.z * d.z;
            held = held || d2 <= reach2;
            longest2 = std::max(longest2, d2);
            peak = peak && pos_[b].y < pos_[idx].y;
        }
        // A peak past its apex pinches off: the jet's top falls apart into drops.
        if (!held || ((edge || peak) && longest2 > rim2) || (peak && vel_[idx].y < 0.0f)) tearing_.push_back(idx);
    }
    tore_off_ = int(tearing_.size());
    for (size_t idx : tearing_) {
        if (bead(pos_[idx]) % uint32_t(p_.torn_drop_share) == 0) torn_.push_back({pos_[idx], vel_[idx]});
        hide(idx, grid, sea_level_m);
    }
    // Hidden vertices next to airborne ones follow the surface: they shape the normals
    // at the torn edge of the film. The rest are never drawn.
    for (int j = 0; j < n_; ++j)
        for (int i = 0; i < n_; ++i) {
            const size_t idx = size_t(j) * size_t(n_) + size_t(i);
            if (airborne_[idx]) continue;
            const bool edge = (i > 0 && airborne_[idx - 1]) || (i + 1 < n_ && airborne_[idx + 1]) ||
                              (j > 0 && airborne_[idx - size_t(n_)]) || (j + 1 < n_ && airborne_[idx + size_t(n_)]);
            if (!edge) continue;
            glm::vec2 r = rest_xz(i, j);
            pos_[idx] = {r.x, sea_level_m + grid.sample(r) - p_.hidden_depth_m, r.y};
        }
}


}  // namespace sim
