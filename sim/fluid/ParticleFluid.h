#pragma once
// A position-based fluid (Macklin & Mueller 2013) in a box, in the box's own frame:
// x, y, z in [0, size], y up. Neighbours come from a uniform grid rebuilt each tick;
// particles are kept sorted by cell so neighbour loops walk memory in order. Every
// parallel loop writes only the particles of its own thread's range and reads other
// ranges only where no one writes during the loop (Jacobi), and each particle computes
// its own pairs, so the result is the same for any thread count. The hot loops work on
// four floats at a time (sim/core/Float4.h), each with its scalar form's operations.
#include <cstdint>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "sim/core/JobPool.h"
#include "sim/core/StateArchive.h"

namespace sim {

struct ParticleFluidParams {
    glm::vec3 box_size_m{1.6f, 1.1f, 1.6f};
    float ceiling_m = 2.2f;          // an invisible lid high above the walls keeps splashes in the grid
    float particle_radius_m = 0.03f; // rest spacing is twice this
    int solver_iterations = 3;
    int body_neighbours = 12;        // a particle with fewer neighbours within the kernel is splash
    float viscosity = 0.02f;         // XSPH
    float max_speed_mps = 12.0f;
    // Throws std::invalid_argument naming the field for unusable values.
    void validate() const;
    float kernel_radius() const { return 4.0f * particle_radius_m; }
};

// A solid the liquid flows around: a box (the "step" scene) or a moving sphere (a
// thrown object), in the fluid's frame.
struct FluidSphere {
    glm::vec3 centre{0.0f};
    glm::vec3 velocity{0.0f};
    float radius_m = 0.0f;
};
struct FluidBox {
    glm::vec3 min{0.0f}, max{0.0f};
};

class ParticleFluid {
public:
    explicit ParticleFluid(const ParticleFluidParams& params);

    // Adds particles at rest; positions must lie inside the box (clamped otherwise).
    void add_particles(const std::vector<glm::vec3>& positions);
    void set_boxes(std::vector<FluidBox> boxes) { boxes_ = std::move(boxes); }

    // One step: external acceleration in the fluid's frame (gravity less the box's own
    // acceleration), spheres pushing through the liquid this step.
    void step(float dt, glm::vec3 acceleration, const std::vector<FluidSphere>& spheres, JobPool& jobs);

    const ParticleFluidParams& params() const { return p_; }
    size_t size() const { return x_.size(); }
    const std::vector<glm::vec3>& positions() const { return x_; }
    const std::vector<glm::vec3>& velocities() const { return v_; }
    // Neighbours within the kernel radius at the last step (the particle itself excluded).
    const std::vector<uint16_t>& neighbour_counts() const { return counts_; }
    bool is_splash(size_t i) const { return counts_[i] < p_.body_neighbours; }
    size_t splash_count() const;
    float rest_density() const { return rest_density_; }
    // Mean density over rest density of the particles with a full neighbourhood.
    float mean_body_density_ratio() const;
    uint64_t hash() const { return hash_state(*this); }
    // Positions, velocities and neighbour counts; the rest is rebuilt by each step.
    template <class Archive> void describe(Archive& ar) {
        ar.words(x_, 0x464c554944ull);
        ar.words_chained(v_);
        ar.words_chained(counts_);
    }

private:
    static constexpr int kMaxNeighbours = 64;

    void collide(glm::vec3& x, const std::vector<FluidSphere>& spheres) const;
    void sort_by_cell();

    ParticleFluidParams p_;
    float h_, h2_, rest_density_ = 1.0f, epsilon_ = 1.0f, scorr_w_ = 1.0f;
    glm::ivec3 cells_{1};
    std::vector<glm::vec3> x_, v_, pred_, delta_;
    std::vector<float> lambda_;
    std::vector<uint16_t> counts_;
    std::vector<uint32_t> neighbours_;  // kMaxNeighbours per particle
    std::vector<glm::vec4> pair_;  // per neighbour: this iteration's kernel gradient and tensile term (w)
    std::vector<uint32_t> cell_start_;  // cells + 1 prefix sums
    std::vector<uint32_t> cell_of_, order_, cell_fill_;
    std::vector<glm::vec3> scratch_;
    std::vector<float> sorted_x_, sorted_y_, sorted_z_;  // pred_ after the sort, for the search; padded by 3
    std::vector<FluidBox> boxes_;
};

}  // namespace sim
