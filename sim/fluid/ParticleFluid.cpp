#include "sim/fluid/ParticleFluid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/core/Float4.h"
#include "sim/core/NumberText.h"

namespace sim {

namespace {

// Kernels in units of the kernel radius h: poly6 without its factor 315 / (64 pi h^3),
// which cancels in density / rest density, and the spiky gradient (45 / (pi h^4))
// (1 - r/h)^2 over the same factor, so that the constraint's gradient keeps its true
// scale against the density (the Newton-like step overshoots otherwise).
float poly6(float r2, float h2) {
    float d = 1.0f - r2 / h2;
    return d > 0.0f ? d * d * d : 0.0f;
}
constexpr float kSpikyOverPoly6 = 45.0f * 64.0f / 315.0f;
glm::vec3 spiky_gradient(glm::vec3 d, float r, float h) {
    if (r <= 1e-9f || r >= h) return glm::vec3(0.0f);
    float q = 1.0f - r / h;
    return d * (-kSpikyOverPoly6 * q * q / (h * r));
}

float length3(glm::vec3 v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

// The pairs of one particle's list, gathered so that four are computed at once with
// the scalar kernels' operations (poly6 and spiky_gradient above, and the tensile term
// of the position correction), each into its place in the list.
struct PairBatch {
    static constexpr int kCap = 64;
    alignas(16) float dx[kCap + 3], dy[kCap + 3], dz[kCap + 3], r2[kCap + 3];
    alignas(16) float weight[kCap + 3];  // what kernels() and weights() computed
    int size = 0;

    void add(glm::vec3 d, float dist2) {
        dx[size] = d.x;
        dy[size] = d.y;
        dz[size] = d.z;
        r2[size++] = dist2;
    }
    // Padding to a multiple of four with pairs at the kernel's edge, never stored.
    int padded(float h2) {
        for (int k = size; k % 4; ++k) dx[k] = dy[k] = dz[k] = 0.0f, r2[k] = h2;
        return (size + 3) & ~3;
    }
    // Weight, gradient and tensile term (gradient and tensile term into pair, as x, y, z, w).
    void kernels(float h, float h2, float scorr_w, glm::vec4* pair) {
        const Float4 one = Float4::splat(1.0f), zero = Float4::splat(0.0f), h4 = Float4::splat(h),
                     h24 = Float4::splat(h2), tiny = Float4::splat(1e-9f), spiky = Float4::splat(-kSpikyOverPoly6),
                     scorr_w4 = Float4::splat(scorr_w), tensile = Float4::splat(-0.001f);
        const int end = padded(h2);
        for (int k = 0; k < end; k += 4) {
            const Float4 d2 = Float4::load(r2 + k);
            const Float4 t = one - d2 / h24;
            const Float4 w = select(t > zero, t * t * t, zero);
            const Float4 r = sqrt(d2);
            const Float4 q = one - r / h4;
            const Float4 f = spiky * q * q / (h4 * r);
            const Mask4 inside = (r > tiny) & (r < h4);
            Float4 gx = select(inside, Float4::load(dx + k) * f, zero);
            Float4 gy = select(inside, Float4::load(dy + k) * f, zero);
            Float4 gz = select(inside, Float4::load(dz + k) * f, zero);
            const Float4 ws = w / scorr_w4;
            Float4 sc = tensile * ws * ws * ws * ws;  // k = 0.001, n = 4
            transpose(gx, gy, gz, sc);
            const Float4* per_pair[4] = {&gx, &gy, &gz, &sc};
            for (int m = 0; m < 4 && k + m < size; ++m) per_pair[m]->store(&pair[k + m].x);
            w.store(weight + k);
        }
    }
    // The weights only.
    void weights(float h2) {
        const Float4 one = Float4::splat(1.0f), zero = Float4::splat(0.0f), h24 = Float4::splat(h2);
        const int end = padded(h2);
        for (int k = 0; k < end; k += 4) {
            const Float4 t = one - Float4::load(r2 + k) / h24;
            select(t > zero, t * t * t, zero).store(weight + k);
        }
    }
};

}  // namespace

void ParticleFluidParams::validate() const {
    auto refuse = [](const std::string& what) { throw std::invalid_argument("fluid: " + what); };
    if (!(particle_radius_m > 0.001f && particle_radius_m <= 1.0f))
        refuse("particle_radius_m must be in (0.001, 1], got " + num(particle_radius_m));
    for (int a = 0; a < 3; ++a)
        if (!(box_size_m[a] >= 4.0f * particle_radius_m && box_size_m[a] <= 100.0f))
            refuse("tank size must be 4 particle radii to 100 m on each axis, got " + num(box_size_m[a]));
    if (!(ceiling_m >= box_size_m.y && ceiling_m <= 200.0f))
        refuse("ceiling_m must be at least the tank height, got " + num(ceiling_m));
    if (solver_iterations < 1 || solver_iterations > 20)
        refuse("solver_iterations must be 1..20, got " + std::to_string(solver_iterations));
    if (body_neighbours < 1 || body_neighbours > 60)
        refuse("body_neighbours must be 1..60, got " + std::to_string(body_neighbours));
    if (!(viscosity >= 0.0f && viscosity <= 1.0f)) refuse("viscosity must be in [0, 1], got " + num(viscosity));
    if (!(max_speed_mps > 0.0f && max_speed_mps <= 1000.0f))
        refuse("max_speed_mps must be in (0, 1000], got " + num(max_speed_mps));
    const float h = kernel_radius();
    const double cells = std::ceil(double(box_size_m.x) / h) * std::ceil(double(ceiling_m) / h) *
                         std::ceil(double(box_size_m.z) / h);
    if (cells > 8e6) refuse("tank of " + num(cells) + " grid cells is too large for its particle radius");
}

ParticleFluid::ParticleFluid(const ParticleFluidParams& params) : p_(params) {
    p_.validate();
    h_ = p_.kernel_radius();
    h2_ = h_ * h_;
    cells_ = {int(std::ceil(p_.box_size_m.x / h_)), int(std::ceil(p_.ceiling_m / h_)),
              int(std::ceil(p_.box_size_m.z / h_))};
    cell_start_.assign(size_t(cells_.x) * size_t(cells_.y) * size_t(cells_.z) + 1, 0);
    // Rest density and the constraint's gradient scale: a particle inside a cubic
    // lattice at the rest spacing.
    const float s = 2.0f * p_.particle_radius_m;
    const int n = int(std::ceil(h_ / s));
    float rho = 0.0f, grad2 = 0.0f;
    for (int k = -n; k <= n; ++k)
        for (int j = -n; j <= n; ++j)
            for (int i = -n; i <= n; ++i) {
                glm::vec3 d(float(i) * s, float(j) * s, float(k) * s);
                float r2 = d.x * d.x + d.y * d.y + d.z * d.z;
                rho += poly6(r2, h2_);
                glm::vec3 g = spiky_gradient(d, std::sqrt(r2), h_);
                grad2 += g.x * g.x + g.y * g.y + g.z * g.z;
            }
    rest_density_ = rho;
    // Relaxation (the paper's epsilon) relative to the gradient sum of a full neighbourhood.
    epsilon_ = 1.0f * grad2 / (rho * rho);
    scorr_w_ = poly6(0.04f * h2_, h2_);  // W at |dq| = 0.2 h
}

void ParticleFluid::add_particles(const std::vector<glm::vec3>& positions) {
    for (glm::vec3 q : positions) {
        const float r = p_.particle_radius_m;
        q = glm::clamp(q, glm::vec3(r), glm::vec3(p_.box_size_m.x - r, p_.ceiling_m - r, p_.box_size_m.z - r));
        x_.push_back(q);
        v_.push_back(glm::vec3(0.0f));
    }
    const size_t n = x_.size();
    pred_.resize(n);
    delta_.resize(n);
    lambda_.resize(n);
    counts_.assign(n, uint16_t(p_.body_neighbours));
    neighbours_.resize(n * kMaxNeighbours);
    pair_.resize(n * kMaxNeighbours);
    cell_of_.resize(n);
    order_.resize(n);
    scratch_.resize(n);
    for (std::vector<float>* v : {&sorted_x_, &sorted_y_, &sorted_z_}) v->assign(n + 3, 0.0f);
}

size_t ParticleFluid::splash_count() const {
    size_t k = 0;
    for (size_t i = 0; i < counts_.size(); ++i) k += is_splash(i) ? 1 : 0;
    return k;
}

float ParticleFluid::mean_body_density_ratio() const {
    double sum = 0.0;
    size_t k = 0;
    for (size_t i = 0; i < x_.size(); ++i) {
        if (counts_[i] < 20) continue;
        float rho = poly6(0.0f, h2_);
        const uint32_t* nb = &neighbours_[i * kMaxNeighbours];
        for (int m = 0; m < std::min<int>(counts_[i], kMaxNeighbours); ++m) {
            glm::vec3 d = x_[i] - x_[nb[m]];
            rho += poly6(d.x * d.x + d.y * d.y + d.z * d.z, h2_);
        }
        sum += rho / rest_density_;
        ++k;
    }
    return k ? float(sum / double(k)) : 0.0f;
}

void ParticleFluid::collide(glm::vec3& x, const std::vector<FluidSphere>& spheres) const {
    const float r = p_.particle_radius_m;
    for (const FluidSphere& s : spheres) {
        glm::vec3 d = x - s.centre;
        float dist = length3(d);
        float reach = s.radius_m + r;
        if (dist < reach) x = dist > 1e-6f ? s.centre + d * (reach / dist) : s.centre + glm::vec3(0.0f, reach, 0.0f);
    }
    for (const FluidBox& b : boxes_) {
        glm::vec3 lo = b.min - glm::vec3(r), hi = b.max + glm::vec3(r);
        if (x.x <= lo.x || x.x >= hi.x || x.y <= lo.y || x.y >= hi.y || x.z <= lo.z || x.z >= hi.z) continue;
        // Out through the nearest face.
        float best = 1e30f, to = 0.0f;
        int axis = 0;
        for (int a = 0; a < 3; ++a) {
            if (x[a] - lo[a] < best) { best = x[a] - lo[a]; axis = a; to = lo[a]; }
            if (hi[a] - x[a] < best) { best = hi[a] - x[a]; axis = a; to = hi[a]; }
        }
        x[axis] = to;
    }
    x = glm::clamp(x, glm::vec3(r), glm::vec3(p_.box_size_m.x - r, p_.ceiling_m - r, p_.box_size_m.z - r));
}

void ParticleFluid::sort_by_cell() {
    // Counting sort by cell, stable in particle order.
    const size_t n = x_.size();
    std::fill(cell_start_.begin(), cell_start_.end(), 0u);
    for (size_t i = 0; i < n; ++i) ++cell_start_[cell_of_[i] + 1];
    for (size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    cell_fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
    for (size_t i = 0; i < n; ++i) order_[cell_fill_[cell_of_[i]]++] = uint32_t(i);
    // Only the predicted positions are reordered now, so that cell neighbours are memory
    // neighbours for the neighbour search. The old positions are read through order_ when
    // the new velocities are taken, and the old velocities are not read again this step.
    for (size_t k = 0; k < n; ++k) {
        const glm::vec3 q = pred_[order_[k]];
        scratch_[k] = q;
        sorted_x_[k] = q.x;
        sorted_y_[k] = q.y;
        sorted_z_[k] = q.z;
    }
    pred_.swap(scratch_);
}

void ParticleFluid::step(float dt, glm::vec3 acceleration, const std::vector<FluidSphere>& spheres, JobPool& jobs) {
    const size_t n = x_.size();
    if (n == 0) return;
    // Eight parallel loops a step with three solver iterations, each starting where the
    // one before had to have written every particle: the prediction (with each particle's
    // cell), the neighbour search with the first iteration's density, then per iteration
    // the position correction and the next iteration's density, and the viscosity.
    const float max_step = p_.max_speed_mps * dt;
    jobs.parallel_for(n, [&](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) {
            v_[i] += acceleration * dt;
            float speed = length3(v_[i]);
            if (speed * dt > max_step) v_[i] *= max_step / (speed * dt);
            pred_[i] = x_[i] + v_[i] * dt;
            collide(pred_[i], spheres);
            const glm::ivec3 c = glm::clamp(glm::ivec3(pred_[i] / h_), glm::ivec3(0), cells_ - 1);
            cell_of_[i] = uint32_t((c.z * cells_.y + c.y) * cells_.x + c.x);
        }
    });
    sort_by_cell();

    const float inv_rho0 = 1.0f / rest_density_;
    static_assert(kMaxNeighbours <= PairBatch::kCap, "a batch holds a whole list");
    // The density constraint's multiplier of a particle from its neighbours' kernel
    // weights and gradients (in list order), the self weight first.
    const float self_weight = poly6(0.0f, h2_);
    const auto lambda_of = [&](const glm::vec4* pair, const float* weight, int m) {
        float rho = self_weight, grad2 = 0.0f;
        glm::vec3 grad_i(0.0f);
        for (int k = 0; k < m; ++k) {
            rho += weight[k];
            const glm::vec3 g = glm::vec3(pair[k]) * inv_rho0;
            grad_i += g;
            grad2 += g.x * g.x + g.y * g.y + g.z * g.z;
        }
        grad2 += grad_i.x * grad_i.x + grad_i.y * grad_i.y + grad_i.z * grad_i.z;
        // Only compression is corrected: a free surface must not pull together.
        float c = std::max(rho * inv_rho0 - 1.0f, 0.0f);
        return -c / (grad2 + epsilon_);
    };
    // Neighbours from the grid, in index order (the cells are walked in index order and
    // hold their particles in order), and the first iteration's density on the way: the
    // distances the search takes are the ones the density needs. Each particle computes
    // all its pairs itself: what the other particle has is in memory far away, and
    // computing four kernels at a time costs no more than fetching them.
    constexpr uint32_t cap = kMaxNeighbours;
    jobs.parallel_for(n, [&](size_t b, size_t e) {
        PairBatch batch;
        const Float4 h2 = Float4::splat(h2_);
        for (size_t i = b; i < e; ++i) {
            const glm::vec3 p = pred_[i];
            const glm::ivec3 c = glm::clamp(glm::ivec3(p / h_), glm::ivec3(0), cells_ - 1);
            uint32_t* out = &neighbours_[i * kMaxNeighbours];
            batch.size = 0;
            uint32_t count = 0;
            const Float4 px = Float4::splat(p.x), py = Float4::splat(p.y), pz = Float4::splat(p.z);
            // Four candidates at a time, those within the kernel (but the particle itself)
            // taken in index order.
            for (int z = std::max(c.z - 1, 0); z <= std::min(c.z + 1, cells_.z - 1); ++z)
                for (int y = std::max(c.y - 1, 0); y <= std::min(c.y + 1, cells_.y - 1); ++y) {
                    const size_t row = size_t((z * cells_.y + y) * cells_.x);
                    const uint32_t first = cell_start_[row + size_t(std::max(c.x - 1, 0))];
                    const uint32_t last = cell_start_[row + size_t(std::min(c.x + 1, cells_.x - 1)) + 1];
                    for (uint32_t j0 = first; j0 < last; j0 += 4) {
                        const Float4 dx = px - Float4::load(&sorted_x_[j0]);
                        const Float4 dy = py - Float4::load(&sorted_y_[j0]);
                        const Float4 dz = pz - Float4::load(&sorted_z_[j0]);
                        const Float4 r2 = dx * dx + dy * dy + dz * dz;
                        int hits = (r2 < h2).bits();
                        if (last - j0 < 4) hits &= (1 << (last - j0)) - 1;
                        if (i - j0 < 4) hits &= ~(1 << (i - j0));
                        if (!hits) continue;
                        alignas(16) float lx[4], ly[4], lz[4], lr2[4];
                        dx.store(lx);
                        dy.store(ly);
                        dz.store(lz);
                        r2.store(lr2);
                        for (; hits; hits &= hits - 1, ++count) {
                            const int t = __builtin_ctz(unsigned(hits));
                            if (count >= cap) continue;
                            out[count] = j0 + uint32_t(t);
                            batch.add({lx[t], ly[t], lz[t]}, lr2[t]);
                        }
                    }
                }
            glm::vec4* pair = &pair_[i * kMaxNeighbours];
            batch.kernels(h_, h2_, scorr_w_, pair);
            counts_[i] = uint16_t(std::min<uint32_t>(count, 65535));
            lambda_[i] = lambda_of(pair, batch.weight, batch.size);
        }
    });

    const float max_correction = 2.0f * p_.particle_radius_m;
    const float inv_dt = 1.0f / dt;
    for (int it = 0; it < p_.solver_iterations; ++it) {
        const bool last = it + 1 == p_.solver_iterations;
        // The position correction, from the multipliers (written by the loop before) and
        // the kernel gradients and tensile terms kept with them; it reads no other
        // particle's position.
        jobs.parallel_for(n, [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) {
                const uint32_t* nb = &neighbours_[i * kMaxNeighbours];
                const int m = std::min<int>(counts_[i], kMaxNeighbours);
                const glm::vec4* pair = &pair_[i * kMaxNeighbours];
                // x, y and z of the sum side by side (the fourth element is not used).
                Float4 sum = Float4::splat(0.0f);
                for (int k = 0; k < m; ++k)
                    sum = sum + Float4::splat(lambda_[i] + lambda_[nb[k]] + pair[k].w) * Float4::load(&pair[k].x);
                alignas(16) float s4[4];
                sum.store(s4);
                // With few iterations a deep compression would be undone in one leap and
                // fling particles: a step moves at most the rest spacing.
                const glm::vec3 dp = glm::vec3(s4[0], s4[1], s4[2]) * inv_rho0;
                const float len = length3(dp);
                pred_[i] += len > max_correction ? dp * (max_correction / len) : dp;
                collide(pred_[i], spheres);
                if (last) delta_[i] = (pred_[i] - x_[order_[i]]) * inv_dt;  // the new velocity
            }
        });
        if (last) break;
        // The next iteration's density.
        jobs.parallel_for(n, [&](size_t b, size_t e) {
            PairBatch batch;
            for (size_t i = b; i < e; ++i) {
                const uint32_t* nb = &neighbours_[i * kMaxNeighbours];
                const int m = std::min<int>(counts_[i], kMaxNeighbours);
                batch.size = 0;
                for (int k = 0; k < m; ++k) {
                    const glm::vec3 d = pred_[i] - pred_[nb[k]];
                    batch.add(d, d.x * d.x + d.y * d.y + d.z * d.z);
                }
                glm::vec4* pair = &pair_[i * kMaxNeighbours];
                batch.kernels(h_, h2_, scorr_w_, pair);
                lambda_[i] = lambda_of(pair, batch.weight, m);
            }
        });
    }

    // XSPH viscosity, reading the new velocities and writing its own.
    jobs.parallel_for(n, [&](size_t b, size_t e) {
        PairBatch batch;
        for (size_t i = b; i < e; ++i) {
            const uint32_t* nb = &neighbours_[i * kMaxNeighbours];
            const int m = std::min<int>(counts_[i], kMaxNeighbours);
            const float* weight = batch.weight;
            batch.size = 0;
            for (int k = 0; k < m; ++k) {
                const glm::vec3 d = pred_[i] - pred_[nb[k]];
                batch.add(d, d.x * d.x + d.y * d.y + d.z * d.z);
            }
            batch.weights(h2_);
            glm::vec3 dv(0.0f);
            float wsum = 0.0f;
            for (int k = 0; k < m; ++k) {
                dv += (delta_[nb[k]] - delta_[i]) * weight[k];
                wsum += weight[k];
            }
            glm::vec3 v = delta_[i] + (wsum > 0.0f ? dv * (p_.viscosity * std::min(wsum, 1.0f) / wsum) : glm::vec3(0.0f));
            // Particles pinned in an edge or corner of the box would be squeezed out
            // along it as a jet; friction there keeps them with the rest.
            const glm::vec3 x = pred_[i];
            const float touch = 1.05f * p_.particle_radius_m;
            const int walls = int(x.x < touch) + int(x.x > p_.box_size_m.x - touch) + int(x.z < touch) +
                              int(x.z > p_.box_size_m.z - touch) + int(x.y < touch);
            if (walls >= 2) v *= 0.5f;
            const float speed = length3(v);
            v_[i] = speed > p_.max_speed_mps ? v * (p_.max_speed_mps / speed) : v;
        }
    });
    x_.swap(pred_);
}


}  // namespace sim
