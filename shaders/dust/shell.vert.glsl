#version 450 core
// Shell i of u_shells (i = 0 is the film on the surface itself): the dusty surface
// pushed out along its normal by i/u_shells of the dust height at this vertex's
// amount. Instances run from the top shell down, so that the fibres kept above fail
// the early depth test of the layers below instead of being shaded over. Lit per
// vertex (dust/light.comp.glsl): the tessellation is finer than the light changes.
#include "dust/dust_vertex.glsl"

uniform int u_shells;

void main() {
    float h = float(u_shells - gl_InstanceID) / float(u_shells);
    vec3 p = dust_point(h, uint(gl_VertexID), vec2(0.0), 1.0);
    gl_Position = u_view_proj * vec4(p, 1.0);
}
