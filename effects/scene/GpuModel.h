#pragma once
// A model uploaded to the GPU: one vertex and one index buffer, a draw range per mesh.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

#include "effects/gl/Buffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/VertexArray.h"
#include "effects/scene/SceneDesc.h"

namespace effects {

class GpuModel {
public:
    GpuModel(const Model& model);

    // Draws every mesh, setting the material uniforms unless depth_only.
    void draw(const gl::Program& program, bool depth_only) const;
    // Every mesh, each placed by `place(mesh_name, mesh_centre)` first (moving parts: a
    // car's wheels). With `eye` (model space) the meshes nearest it come first, so that
    // the early depth test spares what they hide its shading, and those whose box holds
    // the eye last: shells around it (the car's body seen from the driver's seat), behind
    // everything inside them. Without, in the model's order.
    template <class Place>
    void draw_parts(const gl::Program& program, bool depth_only, Place&& place,
                    const std::optional<glm::vec3>& eye = std::nullopt) const {
        vao_.bind();
        for (const size_t i : part_order(eye)) {
            const Range& r = ranges_[i];
            place(r.name, r.centre);
            draw_range(program, depth_only, r);
        }
    }
    // The centre of the named mesh's box (model space; the origin if there is none).
    glm::vec3 part_centre(std::string_view mesh) const;
    const std::string& name() const { return name_; }

private:
    struct Range {
        GLsizei index_count;
        size_t first_index;
        float roughness, metallic;
        glm::vec3 emissive;
        std::string name;
        glm::vec3 centre;  // of the mesh's bounding box, model space
        glm::vec3 lo, hi;  // the bounding box
    };
    void draw_range(const gl::Program& program, bool depth_only, const Range& r) const;
    std::vector<size_t> part_order(const std::optional<glm::vec3>& eye) const;
    std::string name_;
    gl::Buffer vertices_, indices_;
    gl::VertexArray vao_;
    std::vector<Range> ranges_;
};

// A part's bounding box, in its model's space.
struct PartBox {
    glm::vec3 lo, hi;
};
// The order to draw parts in so the early depth test spares what is hidden: nearest the
// eye first; the boxes that hold the eye (a body seen from inside) last, everything inside
// them being in front of them; equals in the model's order.
std::vector<size_t> nearest_first(const std::vector<PartBox>& boxes, glm::vec3 eye);

// A vertex array reading MeshVertex attributes (0 position, 1 normal, 2 colour) from
// `vertices` and triangles from `indices`, as the scene's mesh shaders take them.
gl::VertexArray mesh_vertex_array(std::string_view label, const gl::Buffer& vertices, const gl::Buffer& indices);

// A unit sphere (radius 1) for thrown objects.
Model make_sphere_model(int rings, int segments);
// The cube [-1, 1]^3 with a flat normal per face.
Model make_box_model();

}  // namespace effects
