#pragma once
// The seed's splash model (seed 003, 4.1-4.2): a patch of vertices finer than the wave
// grid, centred on an impact and kept just below the surface, so it is hidden until
// displaced. A splash gives some vertices initial velocities; they fly ballistically
// and, when they fall back below the surface, hide again and leave a ripple.
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sim/core/Rng.h"
#include "sim/core/StateArchive.h"
#include "sim/water/WaveGrid.h"

namespace sim {

struct SplashSheetParams {
    int size = 64;                 // vertices per side (3..256)
    float spacing_m = 0.04f;       // d: fine, so the rim of a stone has ~50 vertices
    // Rings launched outside the seed's ring (the crown's skirt, slower than its rim):
    // at least this many, up to twice as many for wide objects.
    int min_skirt_rings = 3;
    float hidden_depth_m = 0.03f;  // how far below the surface a hidden vertex waits
    float velocity_scale = 1.0f;   // artistic multiplier on every launch speed
    // The seed launches vertices at alpha * M * V (kg m/s read as m/s): for a 116 kg
    // stone at 12 m/s that is kilometres per second. This converts impact momentum to
    // launch speed so such a stone throws a crown two to three metres high (7 m/s at
    // alpha 1), as a boulder that size would.
    float speed_per_momentum = 0.005f;  // (m/s) per (kg m/s)
    float max_speed_mps = 8.0f;    // cap for huge momenta (the boat): about 3 m high
    float gravity_mps2 = 9.81f;
    float ripple_depth_m = 0.0003f; // wave-grid push where a vertex (d x d of film) falls back in
    // A vertex further than tear_stretch spacings from every airborne neighbour has torn
    // off the film (the renderer drops triangles stretched as far): it leaves the
    // sheet as a droplet of torn_drop_radius_m, a scrap of film larger than the spray.
    float tear_stretch = 12.0f;
    // A scrap of film (d x d, a few millimetres thick) holds a drop about a centimetre
    // across, and a breaking rim gathers into beads a few film widths apart (Plateau-
    // Rayleigh): one torn vertex in torn_drop_share flies on as a drop, the rest of the
    // film goes with it.
    float torn_drop_radius_m = 0.012f;
    int torn_drop_share = 3;
    // A moving bow's sheet peels off lower, at about 40 degrees: its launch's vertical part
    // is this share of the crown's (a thrown object's crown rises at 45 degrees).
    float bow_lift = 0.8f;
    // The film thins fastest at its free edge (the crown's rim) and at a peak (the jet's
    // top): a vertex there whose longest bond to an airborne neighbour has stretched past
    // rim_break_stretch spacings breaks off as a droplet too, so the rim sheds drops and
    // recedes; a peak past its apex pinches off, so the jet's column breaks into drops
    // from its top down.
    float rim_break_stretch = 5.0f;
};

// A vertex that tore off the film this step, to fly on as a droplet.
struct TornOff {
    glm::vec3 position{0.0f};
    glm::vec3 velocity{0.0f};
};

// Something fell back into the water here: the caller pushes the wave grid.
struct Ripple {
    glm::vec2 xz{0.0f};
    float depth_m = 0.0f;
};

class SplashSheet {
public:
    // Throws std::invalid_argument for absurd parameters.
    explicit SplashSheet(const SplashSheetParams& params);

    bool active() const { return flying_ > 0; }  // some vertex is still in the air
    glm::vec2 centre_xz() const { return centre_; }
    int size() const { return n_; }
    float spacing() const { return p_.spacing_m; }
    // World positions, size*size, row-major like the grid (index j*size + i, i along x).
    const std::vector<glm::vec3>& positions() const { return pos_; }
    // 1 where the vertex is in the air (launched and not yet fallen back below the
    // surface): the renderer draws triangles whose 3 vertices are airborne.
    const std::vector<uint8_t>& airborne() const { return airborne_; }
    const std::vector<glm::vec3>& velocities() const { return vel_; }
    int airborne_count() const { return flying_; }
    const SplashSheetParams& params() const { return p_; }
    uint64_t hash() const { return hash_state(*this); }
    // Hidden vertices carry no state the hash needs (a launch starts from the surface),
    // so it takes only the airborne ones: the mask, then their positions and speeds.
    template <class Archive> void describe(Archive& ar) {
        ar.vec(centre_);
        ar.i32(flying_);
        ar.words(airborne_, 13);
        ar.vecs_where(airborne_, pos_, vel_);
        ar.unhashed(torn_);  // the last step's, read after it
        ar.unhashed(tore_off_);
    }

    // Vertex (i, j) rests at centre + (i - size/2, j - size/2) * spacing: the centre is a vertex.
    glm::vec2 rest_xz(int i, int j) const;
    // Seed 4.2.2: the splash ring is at the object's rim, Chebyshev distance `inner` =
    // its radius in cells (at least 1): diameter 2d -> the 8 vertices around the
    // centre; 4d -> the 16 of the next ring. A single ring makes no surface, so the
    // band goes on outward to `outer` (the skirt, min_skirt_rings or more).
    struct Band {
        int inner, outer;
    };
    Band ring_band(float object_radius_m) const;
    // alpha M V turned into metres per second (speed_per_momentum, velocity_scale, cap).
    float launch_speed(float momentum_kgmps) const;

    // Centres the sheet on xz with every vertex hidden just below the surface.
    void reset(glm::vec2 centre_xz, const WaveGrid& grid, float sea_level_m);
    // Moves where the hidden vertices rest (the bow sheet rides ahead of the bow);
    // vertices in the air fly on.
    void move_to(glm::vec2 centre_xz) { centre_ = centre_xz; }

    // First splash (seed eqs. 4.1-4.3): each hidden vertex of the rim ring leaves from
    // the surface with alpha in [0.1, 1] (uniform per direction, smooth round the
    // ring): vertical speed alpha*s, horizontal away from the centre, alpha*s along an
    // axis and alpha*s/2 per axis on the diagonals (s = launch_speed(M V)); the skirt
    // rings outside it the same, slowed linearly towards the outermost. With `ahead`
    // (unit xz direction of a moving object) vertices behind the centre are left
    // alone (seed 4.2.4, the bow spray), the lift is bow_lift of it, and `carry_xz` (the object's velocity) is
    // added, so the rule holds in the moving object's frame and the sheet stays
    // whole around the bow instead of stretching back along its path. Returns how
    // many vertices were launched.
    int first_splash(float object_radius_m, float momentum_kgmps, Rng& rng, const WaveGrid& grid,
                     float sea_level_m, std::optional<glm::vec2> ahead = std::nullopt,
                     glm::vec2 carry_xz = glm::vec2(0.0f));
    // Second splash (seed eq. 4.4) after the crater refills: a near-vertical jet from
    // a small central patch (the seed's single vertex looked coarse), alpha*s upward
    // (one alpha for the patch), falling off smoothly towards its edge, with a slight
    // outward lean: a column whose top breaks into drops. Returns the count.
    int second_splash(float object_radius_m, float momentum_kgmps, Rng& rng, const WaveGrid& grid,
                      float sea_level_m);

    // Ballistic flight under gravity; a vertex that falls back below the surface hides
    // again at its rest point and adds a Ripple where it fell, one that has torn off
    // (no airborne neighbour within tear_stretch, a thinned rim or peak past
    // rim_break_stretch, or a peak past its apex) hides, and one in torn_drop_share of
    // those (picked by a hash of its position) is listed in torn(). Hidden vertices
    // follow the surface while the sheet is active.
    void step(float dt, const WaveGrid& grid, float sea_level_m, std::vector<Ripple>& ripples);
    const std::vector<TornOff>& torn() const { return torn_; }  // in the last step, in index order
    int tore_off() const { return tore_off_; }  // vertices that tore off in the last step, drops or not

private:
    void launch(size_t idx, glm::vec3 velocity, const WaveGrid& grid, float sea_level_m);
    void hide(size_t idx, const WaveGrid& grid, float sea_level_m);

    SplashSheetParams p_;
    int n_;
    glm::vec2 centre_{0.0f};
    std::vector<glm::vec3> pos_, vel_;
    std::vector<uint8_t> airborne_;
    int flying_ = 0;
    std::vector<TornOff> torn_;
    int tore_off_ = 0;
    std::vector<size_t> tearing_;  // scratch
};

}  // namespace sim
