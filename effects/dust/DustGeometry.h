#pragma once
// The dusty props' surfaces on the GPU: the sim's tessellated vertices and how much
// sky each sees (static), their dust amounts (re-uploaded when the sim's revision
// changes), and, rebuilt with them, the triangles that hold any dust and the fins
// standing on their edges.
#include <cstdint>
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

    // Uploads what changed since the last call; cheap when nothing did.
    void update(const sim::DustField& field, const SceneDesc& scene);

    const gl::Buffer& vertices() const { return vertices_; }  // position, normal per vertex
    const gl::Buffer& vertex_light() const { return vertex_light_; }  // two vec4 per vertex
    const gl::Buffer& sky_exposure() const { return sky_exposure_; }  // float per vertex
    const gl::Buffer& lit_vertices() const { return lit_vertices_; }  // uint: dusty vertices only
    const gl::VertexArray& shells() const { return shell_vao_; }
    const gl::VertexArray& fins() const { return fin_vao_; }
    const std::vector<DustDrawRange>& ranges() const { return ranges_; }  // per sim prop
    size_t dusty_triangles() const { return dusty_triangles_; }
    size_t fin_quads() const { return fin_quads_; }

private:
    struct FinVertex {
        float position[3];
        float normal[3];
        float amount;
        float along_m;  // distance along the edge
        float height;   // 0 at the base, 1 at the top
        uint32_t vertex; // the dusty vertex it stands on (for its light)
    };

    void upload_static(const sim::DustField& field, const SceneDesc& scene);
    void rebuild(const sim::DustField& field);

    const sim::DustField* field_ = nullptr;
    uint64_t revision_ = ~0ull;
    gl::Buffer vertices_, vertex_light_, sky_exposure_, lit_vertices_, amounts_, shell_indices_, fin_vertices_, fin_indices_;
    gl::VertexArray shell_vao_, fin_vao_;
    std::vector<DustDrawRange> ranges_;
    std::vector<uint32_t> scratch_indices_, scratch_fin_indices_, scratch_lit_;
    std::vector<FinVertex> scratch_fins_;
    size_t dusty_triangles_ = 0, fin_quads_ = 0;
};

}  // namespace effects
