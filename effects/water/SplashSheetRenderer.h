#pragma once
// Draws the airborne splash sheets' geometry step (WaterShading; shaders/water/
// sheet.*.glsl): normals facing the eye and how white the torn film is. The mesh is
// rebuilt each frame.
#include "effects/gl/Buffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/VertexArray.h"
#include "effects/water/SplashSheetMesh.h"

namespace effects {

class SplashSheetRenderer {
public:
    SplashSheetRenderer();

    // Builds and uploads this frame's mesh (see SplashSheetMesh::append for the tear);
    // returns whether there is anything to draw.
    bool update(const WaterView& view, float tear_stretch);
    // Draws with the program's uniforms (camera, sea level, foam) already set.
    void draw() const;

    const gl::Program& program() const { return program_; }
    const SplashSheetMesh& mesh() const { return mesh_; }

private:
    gl::Program program_;
    SplashSheetMesh mesh_;
    gl::Buffer vertices_, indices_;
    gl::VertexArray vao_;
};

}  // namespace effects
