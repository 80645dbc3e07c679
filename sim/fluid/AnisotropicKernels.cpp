#include "sim/fluid/AnisotropicKernels.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "sim/core/DetMath.h"
#include "sim/core/Float4.h"
#include "sim/core/JobPool.h"

namespace sim {

void symmetric_eigen(const float m[3][3], float values[3], glm::vec3 vectors[3]) {
    double a[3][3], v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a[i][j] = double(m[i][j]);
    for (int sweep = 0; sweep < 12; ++sweep) {
        double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        double scale = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (off <= 1e-24 * scale || off == 0.0) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.0) continue;
                double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
                double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; ++k) {  // A <- A J
                    double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {  // A <- J^T A
                    double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    int idx[3] = {0, 1, 2};
    std::sort(idx, idx + 3, [&](int x, int y) { return a[x][x] > a[y][y]; });
    for (int k = 0; k < 3; ++k) {
        values[k] = float(a[idx[k]][idx[k]]);
        vectors[k] = glm::vec3(float(v[0][idx[k]]), float(v[1][idx[k]]), float(v[2][idx[k]]));
    }
}

void anisotropic_kernels(const std::vector<glm::vec3>& positions, const AnisotropyParams& p,
                         std::vector<FluidEllipsoid>& out, JobPool* jobs) {
    const size_t n = positions.size();
    out.resize(n);
    if (n == 0) return;
    const float r = p.neighbourhood_m, r2 = r * r, rp = p.particle_radius_m;
    // A uniform grid of cell r / 2 over the particles' bounds, counting-sorted: the 5^3
    // cells around a particle cover less empty space than 3^3 cells of r.
    const float cell_m = 0.5f * r;
    glm::vec3 lo = positions[0], hi = positions[0];
    for (const glm::vec3& q : positions) {
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    glm::ivec3 cells = glm::max(glm::ivec3((hi - lo) / cell_m) + 1, glm::ivec3(1));
    const size_t ncell = size_t(cells.x) * size_t(cells.y) * size_t(cells.z);
    std::vector<uint32_t> start(ncell + 1, 0), cell(n), sorted(n);
    auto cell_of = [&](glm::vec3 q) { return glm::clamp(glm::ivec3((q - lo) / cell_m), glm::ivec3(0), cells - 1); };
    for (size_t i = 0; i < n; ++i) {
        glm::ivec3 c = cell_of(positions[i]);
        cell[i] = uint32_t((size_t(c.z) * size_t(cells.y) + size_t(c.y)) * size_t(cells.x) + size_t(c.x));
        ++start[cell[i] + 1];
    }
    for (size_t c = 1; c <= ncell; ++c) start[c] += start[c - 1];
    {
        std::vector<uint32_t> fill(start.begin(), start.end() - 1);
        for (size_t i = 0; i < n; ++i) sorted[fill[cell[i]]++] = uint32_t(i);
    }
    // The positions in grid order, coordinate by coordinate.
    std::vector<float> sx(n), sy(n), sz(n);
    for (size_t k = 0; k < n; ++k) {
        sx[k] = positions[sorted[k]].x;
        sy[k] = positions[sorted[k]].y;
        sz[k] = positions[sorted[k]].z;
    }
    // The ellipsoid of particle i from the weighted sums over its neighbourhood (the sums
    // of d and of d d^T, relative to x for precision, give the mean and the covariance
    // about it).
    const auto finish = [&](uint32_t i, glm::vec3 sum_d, const float sum_dd[6], float wsum, int count) {
        const glm::vec3 x = positions[i];
        const glm::vec3 mean = sum_d / wsum;  // the particle itself is always in its neighbourhood, weight 1
        FluidEllipsoid& e = out[i];
        e.centre = x + p.centre_smoothing * mean;
        if (count < p.full_neighbours) {
            e.axis[0] = {rp, 0.0f, 0.0f};
            e.axis[1] = {0.0f, rp, 0.0f};
            e.axis[2] = {0.0f, 0.0f, rp};
            return;
        }
        const float xx = sum_dd[0] / wsum - mean.x * mean.x, xy = sum_dd[1] / wsum - mean.x * mean.y,
                    xz = sum_dd[2] / wsum - mean.x * mean.z, yy = sum_dd[3] / wsum - mean.y * mean.y,
                    yz = sum_dd[4] / wsum - mean.y * mean.z, zz = sum_dd[5] / wsum - mean.z * mean.z;
        const float cov[3][3] = {{xx, xy, xz}, {xy, yy, yz}, {xz, yz, zz}};
        float sigma[3];
        glm::vec3 axes[3];
        symmetric_eigen(cov, sigma, axes);
        const float floor = std::max(sigma[0], 1e-12f) / p.max_stretch;
        for (float& s : sigma) s = std::max(s, floor);
        const float norm = rp / det::cbrt(sigma[0] * sigma[1] * sigma[2]);
        for (int k = 0; k < 3; ++k) e.axis[k] = axes[k] * (sigma[k] * norm);
    };

    // Each particle's kernel reads only the positions and the grid, and writes only its
    // own ellipsoid: the pool may split the cells any way. The particles of one cell look
    // through the same cells in the same order, so four of them are summed side by side,
    // one in each element, every element adding what the particle's own loop would add,
    // in its order; a candidate beyond r adds zeros (w = +0), which leave every sum as
    // it was (a sum that starts at +0 never becomes -0).
    auto build = [&](size_t cell_first, size_t cell_end) {
        const Float4 one = Float4::splat(1.0f), zero = Float4::splat(0.0f), r4 = Float4::splat(r),
                     r24 = Float4::splat(r2);
        for (size_t ci = cell_first; ci < cell_end; ++ci) {
            for (uint32_t g0 = start[ci]; g0 < start[ci + 1]; g0 += 4) {
                const int lanes = int(std::min<uint32_t>(4, start[ci + 1] - g0));
                const glm::ivec3 c = cell_of(positions[sorted[g0]]);
                alignas(16) float gx[4], gy[4], gz[4];
                for (int l = 0; l < 4; ++l) {  // spare elements repeat the last particle
                    const uint32_t k = g0 + uint32_t(std::min(l, lanes - 1));
                    gx[l] = sx[k];
                    gy[l] = sy[k];
                    gz[l] = sz[k];
                }
                const Float4 x4 = Float4::load(gx), y4 = Float4::load(gy), z4 = Float4::load(gz);
                Float4 sum_x = zero, sum_y = zero, sum_z = zero, wsum = zero, count = zero;
                Float4 dd[6] = {zero, zero, zero, zero, zero, zero};  // xx, xy, xz, yy, yz, zz
                for (int z = std::max(c.z - 2, 0); z <= std::min(c.z + 2, cells.z - 1); ++z)
                    for (int y = std::max(c.y - 2, 0); y <= std::min(c.y + 2, cells.y - 1); ++y) {
                        size_t row = (size_t(z) * size_t(cells.y) + size_t(y)) * size_t(cells.x);
                        uint32_t first_k = start[row + size_t(std::max(c.x - 2, 0))];
                        uint32_t last_k = start[row + size_t(std::min(c.x + 2, cells.x - 1)) + 1];
                        for (uint32_t k = first_k; k < last_k; ++k) {
                            const Float4 dx = Float4::splat(sx[k]) - x4, dy = Float4::splat(sy[k]) - y4,
                                         dz = Float4::splat(sz[k]) - z4;
                            const Float4 d2 = dx * dx + dy * dy + dz * dz;
                            const Mask4 near = d2 < r24;
                            if (!near.bits()) continue;
                            const Float4 q = sqrt(d2) / r4;
                            const Float4 w = select(near, one - q * q * q, zero);
                            const Float4 wx = w * dx, wy = w * dy, wz = w * dz;
                            sum_x = sum_x + wx;
                            sum_y = sum_y + wy;
                            sum_z = sum_z + wz;
                            dd[0] = dd[0] + wx * dx;
                            dd[1] = dd[1] + wx * dy;
                            dd[2] = dd[2] + wx * dz;
                            dd[3] = dd[3] + wy * dy;
                            dd[4] = dd[4] + wy * dz;
                            dd[5] = dd[5] + wz * dz;
                            wsum = wsum + w;
                            count = count + select(near, one, zero);
                        }
                    }
                alignas(16) float sums[11][4];
                const Float4* all[11] = {&sum_x, &sum_y, &sum_z, &dd[0], &dd[1], &dd[2], &dd[3], &dd[4], &dd[5], &wsum, &count};
                for (int m = 0; m < 11; ++m) all[m]->store(sums[m]);
                for (int l = 0; l < lanes; ++l) {
                    const float lane_dd[6] = {sums[3][l], sums[4][l], sums[5][l], sums[6][l], sums[7][l], sums[8][l]};
                    // The count holds the particle itself.
                    finish(sorted[g0 + uint32_t(l)], {sums[0][l], sums[1][l], sums[2][l]}, lane_dd, sums[9][l],
                           int(sums[10][l]) - 1);
                }
            }
        }
    };
    if (jobs) jobs->parallel_for(ncell, build);
    else build(0, ncell);
}

}  // namespace sim
