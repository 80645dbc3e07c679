#pragma once
// What the level says about dust (docs/effects/dust.md): which props are dusty and with what
// deposit, where the dust sources stand, how finely amounts are kept. The loader fills
// it from the level's "dust" section and the props flagged "dust"; the prop geometry
// arrives here as world-space triangles, since the sim loads no files.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace sim {

// Deposits from the same machinery (the seed's future work): they differ in the
// accumulation lobe here and in fibre statistics and colour in the renderer.
enum class DustKind : uint8_t { Dust, Sand, Mould };

inline constexpr int kDustKindCount = 3;
const char* dust_kind_name(DustKind kind);
// "dust", "sand", "mould"; false for anything else.
bool parse_dust_kind(const std::string& name, DustKind& out);

struct DustyPropDesc {
    std::string name;  // for messages and the bench: the asset's stem and the prop index
    DustKind kind = DustKind::Dust;
    // World-space triangles of the prop: positions and normals per vertex, three
    // indices per triangle.
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<uint32_t> indices;
};

struct DustDesc {
    bool enabled = false;
    int sources_per_prop = 5;            // the seed's five; 1..16
    float source_elevation_deg = 65.0f;  // of the side sources; one stands straight above
    float source_distance = 2.5f;        // from the prop's centre, in bounding radii
    float sample_spacing_m = 0.08f;      // amounts are kept per vertex of a mesh this fine
    float object_clear_radius_m = 0.25f; // cleared around a thrown object, beyond its radius
    float shot_clear_radius_m = 0.6f;    // cleared around an energy shot's axis
    std::vector<DustyPropDesc> props;
};

}  // namespace sim
