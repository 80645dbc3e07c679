#pragma once
// The dusty props' surfaces on the GPU: the sim's tessellated vertices and how much
// sky each sees (static), their dust amounts (re-uploaded when the sim's revision
// changes), and, rebuilt with them, the triangles that hold any dust and the fins
// standing on their edges, at two levels of detail: the sim's triangles, and a
// tessellation at twice its spacing over a subset of the same vertices (for props
// far enough away that the finer one only costs vertices).
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "effects/gl/Buffer.h"
#include "effects/gl/VertexArray.h"
#include "effects/scene/SceneDesc.h"
#include "sim/dust/DustField.h"

namespace effects {

struct DustDrawRange {
    uint32_t first_lit = 0;  // into lit_vertices(): the vertices the shells stand on
    uint32_t lit_count = 0;
    GLsizei shell_index_count = 0;
    size_t first_shell_index = 0;
    GLsizei fin_index_count = 0;
    size_t first_fin_index = 0;
};

class DustGeometry {
public:
    // Amounts at or below this hold no shells: shell.frag.glsl keeps nothing below
    // smoothstep(0.08, 0.85, amount) = 0.01, and amounts only interpolate between the
    // vertices, so a triangle whose vertices are all below it draws no texel.
    static constexpr float kMinAmount = 0.125f;
    // Level 0: the sim's tessellation; level 1: twice its spacing.
    static constexpr int kLevels = 2;

    // Uploads what changed since the last call; cheap when nothing did. dust is the
    // level's (the field keeps no triangles of its own, only their tessellation).
    // `restore_generation` is the world's (World::restore_generation): after a snapshot
    // is restored the field's revision may name other amounts, so they are re-uploaded.
    void update(const sim::DustField& field, uint64_t restore_generation, const sim::DustDesc& dust,
                const SceneDesc& scene);

    const gl::Buffer& vertices() const { return vertices_; }  // position, normal per vertex
    const gl::Buffer& vertex_light() const { return vertex_light_; }  // two vec4 per vertex
    const gl::Buffer& sky_exposure() const { return sky_exposure_; }  // float per vertex
    const gl::Buffer& lit_vertices() const { return lit_vertices_; }  // uint: dusty vertices only
    const gl::VertexArray& shells() const { return shell_vao_; }
    const gl::VertexArray& fins() const { return fin_vao_; }
    const std::vector<DustDrawRange>& ranges(int level = 0) const { return ranges_[size_t(level)]; }  // per sim prop
    size_t dusty_triangles(int level = 0) const { return dusty_triangles_[size_t(level)]; }
    size_t fin_quads(int level = 0) const { return fin_quads_[size_t(level)]; }

private:
    struct FinVertex {
        float position[3];
        float normal[3];
        float amount;
        float along_m;  // distance along the edge
        float height;   // 0 at the base, 1 at the top
        uint32_t vertex; // the dusty vertex it stands on (for its light)
    };

    void upload_static(const sim::DustField& field, const sim::DustDesc& dust, const SceneDesc& scene);
    void rebuild(const sim::DustField& field);
    void coarsen(const sim::DustField& field, const sim::DustDesc& dust);

    const sim::DustField* field_ = nullptr;
    uint64_t revision_ = ~0ull;
    uint64_t restore_generation_ = 0;
    gl::Buffer vertices_, vertex_light_, sky_exposure_, lit_vertices_, amounts_, shell_indices_, fin_vertices_, fin_indices_;
    gl::VertexArray shell_vao_, fin_vao_;
    // The coarse level's triangles, as the sim's vertex numbers, and where each prop's start.
    std::vector<uint32_t> coarse_indices_;
    std::vector<std::pair<uint32_t, uint32_t>> coarse_props_;  // first index, index count
    std::array<std::vector<DustDrawRange>, kLevels> ranges_;
    std::vector<uint32_t> scratch_indices_, scratch_fin_indices_, scratch_lit_;
    std::vector<FinVertex> scratch_fins_;
    std::array<size_t, kLevels> dusty_triangles_{}, fin_quads_{};
};

}  // namespace effects
