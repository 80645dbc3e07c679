#version 450 core
// Light and fog once per frame for each vertex under dust (dust/vertex_light.glsl),
// read by every shell and fin standing on it: the shells would otherwise light each
// vertex once per layer. Vertices without dust draw nothing and are skipped.
#include "common/sky.glsl"
#include "common/lighting.glsl"
#include "dust/vertex_light.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Vertices { float vertices[]; };  // position, normal
layout(std430, binding = 1) writeonly buffer VertexLight { vec4 vertex_light[]; };  // light, fog
layout(std430, binding = 2) readonly buffer SkyExposure { float sky_exposure[]; };
layout(std430, binding = 3) readonly buffer LitVertices { uint lit_vertices[]; };  // the dusty ones

uniform uint u_first;
uniform uint u_count;

void main() {
    if (gl_GlobalInvocationID.x >= u_count) return;
    uint k = lit_vertices[u_first + gl_GlobalInvocationID.x];
    vec3 p = vec3(vertices[6 * k], vertices[6 * k + 1], vertices[6 * k + 2]);
    vec3 n = normalize(vec3(vertices[6 * k + 3], vertices[6 * k + 4], vertices[6 * k + 5]));
    vec3 light;
    vec4 fog;
    light_vertex(p, n, sky_exposure[k], light, fog);
    vertex_light[2 * k] = vec4(light, 1.0);
    vertex_light[2 * k + 1] = fog;
}
