#version 450 core
// Shell i of u_shells (i = 0 is the film on the surface itself): the dusty surface
// pushed out along its normal by i/u_shells of the dust height at this vertex's
// amount. Instances run from the top shell down, so that the fibres kept above fail
// the early depth test of the layers below instead of being shaded over. Lit per vertex (dust/light.comp.glsl): the tessellation is finer
// than the light changes.

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_amount;

layout(std430, binding = 1) readonly buffer VertexLight { vec4 vertex_light[]; };  // light, fog

uniform mat4 u_view_proj;
uniform float u_height_m;
uniform int u_shells;

out vec3 v_base_pos;
out vec3 v_normal;
out float v_amount;
out float v_height;
out vec2 v_fin_uv;
out float v_fin_fade;
out vec3 v_light;
out vec4 v_fog;

void main() {
    float h = float(u_shells - gl_InstanceID) / float(u_shells);
    vec3 n = normalize(a_normal);
    vec3 p = a_position + n * (h * u_height_m * a_amount);
    v_base_pos = a_position;
    v_normal = n;
    v_amount = a_amount;
    v_height = h;
    v_fin_uv = vec2(0.0);
    v_fin_fade = 1.0;
    v_light = vertex_light[2 * gl_VertexID].rgb;
    v_fog = vertex_light[2 * gl_VertexID + 1];
    gl_Position = u_view_proj * vec4(p, 1.0);
}
