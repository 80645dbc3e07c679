#include "effects/water/SplashFoam.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace effects {

namespace {
// Ticks after which a vertex at height y above the sea, rising at vy, is back below it,
// stepped as sim::SplashSheet::step steps it (v -= g dt, then p += v dt): after k ticks
// it stands at y + k vy dt - g dt^2 k (k + 1) / 2. The first whole k past the root.
int64_t ticks_to_land(float y, float vy, float g, float dt) {
    const double a = 0.5 * double(g) * dt * dt, b = a - double(vy) * dt, c = -double(y);
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return 1;  // below the sea already, with no way up
    const double k = (-b + std::sqrt(disc)) / (2.0 * a);
    return std::max<int64_t>(1, int64_t(std::floor(k)) + 1);
}
}  // namespace

float FoamField::at(glm::vec2 xz) const {
    if (size == 0) return 0.0f;
    const glm::vec2 t = (xz - origin_xz) / texel_m;
    if (!(t.x >= 0.0f && t.y >= 0.0f && t.x < float(size) && t.y < float(size))) return 0.0f;
    return float(texels[size_t(int(t.y)) * size_t(size) + size_t(int(t.x))]) / 255.0f;
}

void SplashFoam::forget() {
    landings_.clear();
    flights_.clear();
    field_ = FoamField{};
    live_ = 0;
}

void SplashFoam::follow(const SheetView& sheet, const WaterView& view) {
    if (sheet.id < 0 || sheet.velocities.empty()) return;
    const float dt = view.tick_s;
    for (size_t idx = 0; idx < sheet.positions.size(); ++idx) {
        if (!sheet.airborne[idx]) continue;
        // A fixed pick of the bow's vertices (a multiplicative hash of the index).
        if (sheet.bow && (uint32_t(idx) * 2654435761u >> 16) % kBowStride != 0) continue;
        const glm::vec3 p = sheet.positions[idx], v = sheet.velocities[idx];
        const int64_t k = ticks_to_land(p.y - view.sea_level_m, v.y, sheet.gravity_mps2, dt);
        const int64_t lands = view.tick + k;
        int64_t& known = flights_[(uint64_t(uint32_t(sheet.id)) << 32) | uint64_t(idx)];
        // The same flight seen again lands within a tick or two of where it was seen to
        // (the waves move the surface it lands on); a later one is a new launch.
        if (known != 0 && std::abs(known - lands) <= 3) continue;
        known = lands;
        const glm::vec2 xz = glm::vec2(p.x, p.z) + glm::vec2(v.x, v.z) * (float(k) * dt);
        // The bow's foam does not drift out from the sheet's centre, which moves with the boat.
        const glm::vec2 from = sheet.centre_xz && !sheet.bow ? xz - *sheet.centre_xz : glm::vec2(0.0f);
        const float d = glm::length(from);
        landings_.push_back({xz, d > 1e-3f ? from / d : glm::vec2(0.0f), lands, sheet.bow});
    }
}

void SplashFoam::update(const WaterView& view, const FoamLook& look) {
    if (view.tick < 0 || view.restore_generation != restore_generation_ || view.tick < last_tick_) {
        forget();
        restore_generation_ = view.restore_generation;
    }
    last_tick_ = view.tick;
    if (view.tick < 0) return;
    for (const SheetView& s : view.sheets) follow(s, view);

    // Drop the landings whose foam has gone, and the flights that landed before them.
    const int64_t life_ticks = int64_t(std::ceil(look.life_s / view.tick_s));
    const int64_t gone = view.tick - life_ticks;
    std::erase_if(landings_, [&](const Landing& l) { return l.tick < gone; });
    std::erase_if(flights_, [&](const auto& f) { return f.second < gone; });
    rasterise(view.tick, view.tick_s, look);
}

void SplashFoam::rasterise(int64_t now, float tick_s, const FoamLook& look) {
    const float max_radius = look.start_radius_m + look.spread_m + look.drift_m;
    glm::vec2 lo(0.0f), hi(0.0f);
    live_ = 0;
    for (const Landing& l : landings_) {
        if (l.tick > now) continue;
        const glm::vec2 xz = l.xz;
        lo = live_ ? glm::min(lo, xz) : xz;
        hi = live_ ? glm::max(hi, xz) : xz;
        ++live_;
    }
    field_.size = 0;
    field_.texels.clear();
    if (live_ == 0) return;
    lo -= max_radius;
    hi += max_radius;
    const float extent = std::max(hi.x - lo.x, hi.y - lo.y);
    float texel = kFinestTexelM;
    while (extent > texel * float(kMaxSide)) texel *= 2.0f;
    // Texels on a fixed lattice of their size, so a patch does not shimmer as the map's
    // box grows; the side a multiple of 4 (rows of bytes uploaded without padding).
    const glm::vec2 origin = glm::floor(lo / texel) * texel;
    const glm::vec2 span = (hi - origin) / texel;
    const int side = std::min(kMaxSide, (int(std::ceil(std::max(span.x, span.y))) + 4) & ~3);
    field_.origin_xz = origin;
    field_.texel_m = texel;
    field_.size = side;
    accum_.assign(size_t(side) * size_t(side), 0.0f);
    for (const Landing& l : landings_) {
        if (l.tick > now) continue;
        const float age = float(now - l.tick) * tick_s;
        const float grown = 1.0f - std::exp(-age / look.spread_s);
        const float radius = look.start_radius_m + look.spread_m * grown;
        // Spread thinner as it grows, and fading: the same foam over a wider patch.
        const float strength = look.per_landing * (l.bow ? look.bow_share * float(kBowStride) : 1.0f) * std::exp(-age / look.fade_s) * (look.start_radius_m / radius) *
                               std::clamp(1.0f - (age - (look.life_s - 1.0f)), 0.0f, 1.0f);
        const glm::vec2 c = (l.xz + l.out * (look.drift_m * grown) - origin) / texel - 0.5f;  // in texel centres
        const float r = radius / texel;
        const int i0 = std::max(0, int(std::ceil(c.x - r))), i1 = std::min(side - 1, int(std::floor(c.x + r)));
        const int j0 = std::max(0, int(std::ceil(c.y - r))), j1 = std::min(side - 1, int(std::floor(c.y + r)));
        const float inv_r2 = 1.0f / (r * r);
        for (int j = j0; j <= j1; ++j) {
            const float dy = float(j) - c.y;
            float* row = accum_.data() + size_t(j) * size_t(side);
            // Without a branch, so the row vectorises: outside the disc q is 0 and the
            // texel gains exactly nothing.
            for (int i = i0; i <= i1; ++i) {
                const float dx = float(i) - c.x;
                const float q = std::max(0.0f, 1.0f - (dx * dx + dy * dy) * inv_r2);
                row[i] += strength * q * q;
            }
        }
    }
    field_.texels.resize(accum_.size());
    // Most of the map is open water: no exponential where no patch reached.
    for (size_t t = 0; t < accum_.size(); ++t)
        field_.texels[t] = accum_[t] == 0.0f ? 0 : uint8_t(std::lround(255.0f * (1.0f - std::exp(-accum_[t]))));
}

}  // namespace effects
