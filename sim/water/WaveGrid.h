#pragma once
// The harbour's wave-height grid (seed 003, chapter 3; docs/effects/water.md): an explicit
// central-difference step of the 2D wave equation with the seed's free boundary (a
// missing neighbour is left out and the centre weight becomes 2 - k c), plus damping
// of the surface's velocity.
// Land cells are pinned at 0 and count as missing neighbours, so the quay reflects.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sim/core/JobPool.h"
#include "sim/core/StateArchive.h"

namespace sim {

struct WaveGridParams {
    int size = 256;                      // cells per side (8..2048)
    float spacing_m = 0.5f;              // h
    glm::vec2 origin_xz{-40.0f, 1.0f};   // world xz of cell (0,0); cell (i,j) is at origin + (i, j) * spacing
    float wave_speed_mps = 2.5f;         // v
    float damping_per_s = 0.25f;         // fraction of wave energy lost per second (0 = none)
};

class WaveGrid {
public:
    // Throws std::invalid_argument naming the bound: c = v^2 dt^2 / h^2 must be <= 0.5, etc.
    WaveGrid(const WaveGridParams& p, float dt_s);

    // One tick of the seed's explicit scheme with free boundary + damping.
    void step();
    // The same step with rows shared out over the pool: each row is written by one
    // thread from the two previous time levels, so any thread count gives the same bits.
    void step(JobPool& jobs);

    int size() const { return size_; }
    float spacing() const { return h_; }
    glm::vec2 origin() const { return origin_; }
    float courant() const { return c_; }  // c = v^2 dt^2 / h^2
    float damping_factor_per_step() const { return damp_; }  // keep: what stays of the surface's velocity

    // size*size, row-major: index j*size + i (i along x, j along z); height above sea level.
    const std::vector<float>& heights() const { return cur_; }
    const std::vector<float>& previous_heights() const { return prev_; }
    float height(int i, int j) const { return cur_[size_t(j) * size_t(size_) + size_t(i)]; }
    float sample(glm::vec2 xz) const;   // bilinear; 0 outside the grid
    glm::vec3 normal(glm::vec2 xz) const;  // from central differences of sample()

    // Smooth (raised-cosine) displacement of both time levels, so it starts at rest and
    // spreads as a ring; positive depth pushes the surface down. The radius is at least
    // one spacing so that any push reaches a grid point. Land cells are left alone.
    void push(glm::vec2 xz, float radius_m, float depth_m);
    // Replaces the surface (both time levels: at rest in that shape). Land stays 0.
    void set_heights(const std::vector<float>& heights);
    double volume() const;  // sum of heights * h^2

    // 1 = land/solid cell: height pinned to 0 and treated as a missing neighbour.
    void set_land_mask(std::vector<uint8_t> mask);
    const std::vector<uint8_t>& land_mask() const { return land_; }

    uint64_t hash() const { return hash_state(*this); }
    // The two time levels and the land (sim/core/StateArchive.h).
    template <class Archive> void describe(Archive& ar) {
        ar.words(cur_, 1);
        ar.words(prev_, 2);
        ar.words(land_, 3);
        if constexpr (Archive::kLoading) rebuild_coefficients();
    }

private:
    void step_rows(size_t row_begin, size_t row_end);
    void rebuild_coefficients();

    int size_;
    float h_;
    glm::vec2 origin_;
    float c_;
    float damp_;
    float pull_;  // back towards sea level, per step
    std::vector<float> cur_, prev_;   // y[n], y[n-1]; step writes y[n+1] over y[n-1], then swaps
    std::vector<uint8_t> land_;
    // Rows that touch the grid edge or land take the general path with per-cell weights;
    // the rest run a branch-free loop with the interior weight 2 - 4c.
    std::vector<uint8_t> row_general_;
    std::vector<float> centre_weight_;  // 1 + keep - pull - k c per cell (2 - k c without damping)
};

}  // namespace sim
