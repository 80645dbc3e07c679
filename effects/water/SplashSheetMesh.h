#pragma once
// The airborne part of the splash sheets as one triangle list: each sheet's vertices
// with normals from their neighbours, and the triangles whose three corners are all
// above the water (the rest of the sheet stays hidden under the surface).
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "effects/water/WaterView.h"

namespace effects {

struct SheetVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 cell{0.0f};  // (i, j) in the sheet: foam patterns stretch with the film
    float stretch = 1.0f;  // area around the vertex over its area at rest: the film thins as it grows
    float cover = 1.0f;    // share of its six triangles drawn: less where the film is torn or ends
};

struct SplashSheetMesh {
    std::vector<SheetVertex> vertices;
    std::vector<uint32_t> indices;
    // Drops drawn with the spray (SprayRenderer): the beads along each crown's free rim,
    // where surface tension gathers the rolled-up edge into drops (Plateau-Rayleigh), and
    // the drop pinching off the top of each jet.
    std::vector<SprayDrop> drops;

    void clear() {
        vertices.clear();
        indices.clear();
        drops.clear();
    }
    // Appends one sheet (all its vertices if any triangle is drawn, none otherwise).
    // A triangle stretched to more than tear_stretch times its size at rest (an edge
    // longer, or its area more than the square) has torn into spray and is left out. The sheet must be consistent (WaterView::validate).
    // A sheet that says where it rests (SheetView::centre_xz) has its jet drawn as a
    // column standing in the water at sea_level_m (kJetSqueeze).
    void append(const SheetView& sheet, float tear_stretch, float sea_level_m);

    // The sim throws the jet (a heavy object's second splash) as a dome of film lifted
    // straight up from a patch as wide as the stone: from the side a hood whose edge
    // hangs in the air. A real jet is a solid column of water narrower than the stone,
    // rounded on top, standing in the water. So a vertex that has risen with almost no
    // sideways travel from its rest (the crown's fly out at least half as fast as they
    // rise) is drawn this share of its distance from the sheet's centre, and the
    // column's edge is carried down below the water. The squeeze comes in between
    // kJetLowM and kJetHighM above the sea: lower down, a slow skirt vertex of a crown
    // can hover near its rest on a passing wave.
    static constexpr float kJetSqueeze = 0.3f;
    static constexpr float kJetMaxLean = 0.25f;  // sideways travel over height, at most
    static constexpr float kJetLowM = 0.15f, kJetHighM = 0.35f;
    static constexpr float kJetFootDepthM = 0.15f;  // how far below sea level its side goes
    static constexpr float kJetFootFlare = 1.8f;    // its side's bottom, over the outline's distance from the axis
    // Beads along the film's free edges (the edges of one drawn triangle), one about every
    // kBeadSpacingM (a few times the rolled-up rim's width, as Plateau-Rayleigh breakup
    // spaces them), of radius kBeadMinM..kBeadMaxM, placed and sized by a hash of the
    // edge's vertices so they ride along with the film.
    static constexpr float kBeadSpacingM = 0.035f;
    static constexpr float kBeadMinM = 0.005f, kBeadMaxM = 0.011f;
    // The jet's top drop: this share of the column's radius at its top, at least kTopDropMinM.
    static constexpr float kTopDropShare = 0.75f, kTopDropMinM = 0.012f;
    static constexpr float kTopDropJetM = 0.4f;  // the jet must stand this high to pinch one off

private:
    void add_drops(const SheetView& sheet, float sea_level_m, uint32_t base, size_t first_index, size_t end_index);

    std::vector<glm::vec3> shown_;  // scratch: the sheet's positions as drawn
    std::vector<uint8_t> jet_, drawn_;
    std::vector<uint64_t> edges_;  // scratch: the sheet's triangle edges
    std::vector<std::pair<size_t, size_t>> foot_;  // scratch: the jet's outline, as vertex pairs
};

}  // namespace effects
