#pragma once
// Yu & Turk (2013) anisotropic kernels: each particle becomes an ellipsoid stretched
// along the surface its neighbours form, so that a flat liquid surface renders flat.
// A pure function of the positions: the renderer calls it for the particles it draws.
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace sim {

class JobPool;

struct AnisotropyParams {
    float particle_radius_m = 0.03f;
    float neighbourhood_m = 0.24f;  // r of the weights 1 - (d/r)^3, about twice the kernel radius h
    int full_neighbours = 25;       // N_eps: fewer neighbours, an isotropic sphere
    float max_stretch = 4.0f;       // k_r: small eigenvalues clamped to at least sigma_1 / k_r
    float centre_smoothing = 0.9f;  // lambda: centre moved this far towards the weighted mean
};

// Centre and three axes (unit direction times radius): the ellipsoid is
// {centre + a0 u + a1 v + a2 w : u^2 + v^2 + w^2 <= 1}.
struct FluidEllipsoid {
    glm::vec3 centre{0.0f};
    glm::vec3 axis[3]{};
};

// Ellipsoids for `positions`. Isolated particles (and those with fewer than
// full_neighbours) are spheres of the particle radius; the others keep the sphere's
// volume (k_s chosen per particle) with stretch at most k_r. With `jobs`, the
// particles are shared among its threads (the same result for any count).
void anisotropic_kernels(const std::vector<glm::vec3>& positions, const AnisotropyParams& params,
                         std::vector<FluidEllipsoid>& out, JobPool* jobs = nullptr);

// Eigen-decomposition of a symmetric 3x3 matrix (cyclic Jacobi): eigenvalues
// descending, eigenvectors as unit columns in the same order.
void symmetric_eigen(const float m[3][3], float values[3], glm::vec3 vectors[3]);

}  // namespace sim
