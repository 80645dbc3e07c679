#include "sim/fluid/ParticleFluid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/core/Hash.h"
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
    mirror_.resize(n * kMaxNeighbours);
    back_counts_.resize(n);
    cell_of_.resize(n);
    order_.resize(n);
    scratch_.resize(n);
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
    for (size_t k = 0; k < n; ++k) scratch_[k] = pred_[order_[k]];
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
    // The density constraint's multiplier of particle i, from its neighbours' kernel
    // weights and gradients (kept in pair_ for the position correction).
    struct Constraint {
        float rho, grad2 = 0.0f;
        glm::vec3 grad_i{0.0f};
    };
    const auto add_neighbour = [&](Constraint& s, glm::vec3 d, float r2, glm::vec4& pair) {
        float w = poly6(r2, h2_);
        s.rho += w;
        glm::vec3 g = spiky_gradient(d, std::sqrt(r2), h_);
        pair = glm::vec4(g, w);
        g *= inv_rho0;
        s.grad_i += g;
        s.grad2 += g.x * g.x + g.y * g.y + g.z * g.z;
    };
    const auto lambda_of = [&](Constraint& s) {
        s.grad2 += s.grad_i.x * s.grad_i.x + s.grad_i.y * s.grad_i.y + s.grad_i.z * s.grad_i.z;
        // Only compression is corrected: a free surface must not pull together.
        float c = std::max(s.rho * inv_rho0 - 1.0f, 0.0f);
        return -c / (s.grad2 + epsilon_);
    };
    // A pair's kernel weight and gradient taken from the other particle's side, where
    // this thread computed them already: the distance is the same float, the
    // difference vector exactly its negation, so the weight is the same and the gradient
    // its negation.
    const auto add_mirrored = [&](Constraint& s, glm::vec4 other, glm::vec4& pair) {
        const float w = other.w;
        s.rho += w;
        glm::vec3 g = -glm::vec3(other);
        pair = glm::vec4(g, w);
        g *= inv_rho0;
        s.grad_i += g;
        s.grad2 += g.x * g.x + g.y * g.y + g.z * g.z;
    };
    const float self_weight = poly6(0.0f, h2_);

    // Neighbours from the grid, and the first iteration's density on the way: the
    // distances the search takes are the ones the density needs. A thread goes through
    // its particles in order; each particle looks through the grid only for neighbours
    // below the thread's range or above itself, and hands itself (with its place in its
    // own list) to those above it in the range: their neighbours below them in the
    // range arrive that way, in order, before their turn. A list is the same whichever
    // way its entries came, so it does not depend on the ranges.
    constexpr uint32_t cap = kMaxNeighbours;
    jobs.parallel_for(n, [&](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) back_counts_[i] = 0;
        uint32_t below[kMaxNeighbours];
        uint8_t below_slot[kMaxNeighbours];
        for (size_t i = b; i < e; ++i) {
            const glm::vec3 p = pred_[i];
            const glm::ivec3 c = glm::clamp(glm::ivec3(p / h_), glm::ivec3(0), cells_ - 1);
            uint32_t* out = &neighbours_[i * kMaxNeighbours];
            uint8_t* mirror = &mirror_[i * kMaxNeighbours];
            glm::vec4* pair = &pair_[i * kMaxNeighbours];
            // The neighbours handed over sit at the start of the list until now.
            const uint32_t handed = back_counts_[i];
            const int kept = int(std::min(handed, cap));
            std::copy(out, out + kept, below);
            std::copy(mirror, mirror + kept, below_slot);
            Constraint s{self_weight};
            uint32_t count = 0;
            const auto search = [&](uint32_t lo, uint32_t hi, bool hand_over) {
                for (int z = std::max(c.z - 1, 0); z <= std::min(c.z + 1, cells_.z - 1); ++z)
                    for (int y = std::max(c.y - 1, 0); y <= std::min(c.y + 1, cells_.y - 1); ++y) {
                        const size_t row = size_t((z * cells_.y + y) * cells_.x);
                        const uint32_t first = std::max(cell_start_[row + size_t(std::max(c.x - 1, 0))], lo);
                        const uint32_t last = std::min(cell_start_[row + size_t(std::min(c.x + 1, cells_.x - 1)) + 1], hi);
                        for (uint32_t j = first; j < last; ++j) {
                            glm::vec3 d = p - pred_[j];
                            const float r2 = d.x * d.x + d.y * d.y + d.z * d.z;
                            if (r2 >= h2_) continue;
                            if (count < cap) {
                                out[count] = j;
                                mirror[count] = kNoMirror;
                                add_neighbour(s, d, r2, pair[count]);
                            }
                            if (hand_over && j < e) {
                                uint32_t& k = back_counts_[j];
                                if (k < cap) {
                                    neighbours_[j * kMaxNeighbours + k] = uint32_t(i);
                                    mirror_[j * kMaxNeighbours + k] = count < cap ? uint8_t(count) : kNoMirror;
                                }
                                ++k;
                            }
                            ++count;
                        }
                    }
            };
            search(0, uint32_t(b), false);
            for (int k = 0; k < kept; ++k, ++count) {
                if (count >= cap) continue;
                const uint32_t j = below[k];
                out[count] = j;
                mirror[count] = below_slot[k];
                if (below_slot[k] != kNoMirror) {
                    add_mirrored(s, pair_[j * kMaxNeighbours + below_slot[k]], pair[count]);
                } else {
                    glm::vec3 d = p - pred_[j];
                    add_neighbour(s, d, d.x * d.x + d.y * d.y + d.z * d.z, pair[count]);
                }
            }
            count += handed - uint32_t(kept);
            search(uint32_t(i) + 1, uint32_t(n), true);
            counts_[i] = uint16_t(std::min<uint32_t>(count, 65535));
            lambda_[i] = lambda_of(s);
        }
    });

    const float max_correction = 2.0f * p_.particle_radius_m;
    const float inv_dt = 1.0f / dt;
    for (int it = 0; it < p_.solver_iterations; ++it) {
        const bool last = it + 1 == p_.solver_iterations;
        // The position correction, from the multipliers (written by the loop before) and
        // the kernel gradients kept with them; it reads no other particle's position.
        jobs.parallel_for(n, [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) {
                const uint32_t* nb = &neighbours_[i * kMaxNeighbours];
                const int m = std::min<int>(counts_[i], kMaxNeighbours);
                const glm::vec4* pair = &pair_[i * kMaxNeighbours];
                glm::vec3 dp(0.0f);
                for (int k = 0; k < m; ++k) {
                    float w = pair[k].w / scorr_w_;
                    float scorr = -0.001f * w * w * w * w;  // tensile instability term, k = 0.001, n = 4
                    dp += (lambda_[i] + lambda_[nb[k]] + scorr) * glm::vec3(pair[k]);
                }
                // With few iterations a deep compression would be undone in one leap and
                // fling particles: a step moves at most the rest spacing.
                dp *= inv_rho0;
                const float len = length3(dp);
                pred_[i] += len > max_correction ? dp * (max_correction / len) : dp;
                collide(pred_[i], spheres);
                if (last) delta_[i] = (pred_[i] - x_[order_[i]]) * inv_dt;  // the new velocity
            }
        });
        if (last) break;
        // The next iteration's density; a pair with a neighbour below in this thread's
        // range was computed on the neighbour's turn.
        jobs.parallel_for(n, [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) {
                const uint32_t* nb = &neighbours_[i * kMaxNeighbours];
                const uint8_t* mirror = &mirror_[i * kMaxNeighbours];
                const int m = std::min<int>(counts_[i], kMaxNeighbours);
                glm::vec4* pair = &pair_[i * kMaxNeighbours];
                Constraint s{self_weight};
                for (int k = 0; k < m; ++k) {
                    const uint32_t j = nb[k];
                    if (mirror[k] != kNoMirror && j >= b) {
                        add_mirrored(s, pair_[j * kMaxNeighbours + mirror[k]], pair[k]);
                    } else {
                        glm::vec3 d = pred_[i] - pred_[j];
                        add_neighbour(s, d, d.x * d.x + d.y * d.y + d.z * d.z, pair[k]);
                    }
                }
                lambda_[i] = lambda_of(s);
            }
        });
    }

    // XSPH viscosity, reading the new velocities and writing its own. The kernel weights
    // go to pair_ (free now) for the mirrored pairs, as in the density.
    jobs.parallel_for(n, [&](size_t b, size_t e) {
        for (size_t i = b; i < e; ++i) {
            const uint32_t* nb = &neighbours_[i * kMaxNeighbours];
            const uint8_t* mirror = &mirror_[i * kMaxNeighbours];
            const int m = std::min<int>(counts_[i], kMaxNeighbours);
            glm::vec4* pair = &pair_[i * kMaxNeighbours];
            glm::vec3 dv(0.0f);
            float wsum = 0.0f;
            for (int k = 0; k < m; ++k) {
                const uint32_t j = nb[k];
                float w;
                if (mirror[k] != kNoMirror && j >= b) {
                    w = pair_[j * kMaxNeighbours + mirror[k]].w;
                } else {
                    glm::vec3 d = pred_[i] - pred_[j];
                    w = poly6(d.x * d.x + d.y * d.y + d.z * d.z, h2_);
                }
                pair[k].w = w;
                dv += (delta_[j] - delta_[i]) * w;
                wsum += w;
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

uint64_t ParticleFluid::hash() const {
    uint64_t h = hash_words(x_.data(), x_.size() * sizeof(glm::vec3), 0x464c554944ull);
    h = hash_words(v_.data(), v_.size() * sizeof(glm::vec3), h);
    return hash_words(counts_.data(), counts_.size() * sizeof(uint16_t), h);
}

}  // namespace sim
