#pragma once
// The windshield drawn from inside the car: the rain's glass surface sampled on a
// grid in car model space, each vertex with its glass coordinates (metres) and the
// glass's tangents, so the height map lands exactly where the sim's drops are.
#include "effects/gl/Buffer.h"
#include "effects/gl/VertexArray.h"

namespace sim {
class GlassSurface;
}

namespace effects {

class WindshieldMesh {
public:
    explicit WindshieldMesh(const sim::GlassSurface& glass, int columns = 32, int rows = 12);
    void draw() const;  // triangles; attributes 0 position, 1 glass uv, 2 tangent u, 3 tangent v
    const sim::GlassSurface* glass() const { return glass_; }

private:
    const sim::GlassSurface* glass_;
    gl::Buffer vertices_, indices_;
    gl::VertexArray vao_;
    int index_count_ = 0;
};

}  // namespace effects
