// Shared by the shell and fin vertex shaders: a dusty vertex (position, normal, amount),
// its light and fog from dust/light.comp.glsl, and what dust/shell.frag.glsl reads.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_amount;

layout(std430, binding = 1) readonly buffer VertexLight { vec4 vertex_light[]; };  // light, fog

uniform mat4 u_view_proj;
uniform float u_height_m;

out vec3 v_base_pos;
out vec3 v_normal;
out float v_amount;
out float v_height;
out vec2 v_fin_uv;
out float v_fin_fade;
out vec3 v_light;
out vec4 v_fog;

// Sets the outputs for this vertex at `height` (0..1) of its dust, lit as dusty vertex
// `vertex` of the light buffer, and returns that point: the surface pushed out along
// its normal by `height` of the dust's height there.
vec3 dust_point(float height, uint vertex, vec2 fin_uv, float fin_fade) {
    vec3 n = normalize(a_normal);
    v_base_pos = a_position;
    v_normal = n;
    v_amount = a_amount;
    v_height = height;
    v_fin_uv = fin_uv;
    v_fin_fade = fin_fade;
    v_light = vertex_light[2 * vertex].rgb;
    v_fog = vertex_light[2 * vertex + 1];
    return a_position + n * (height * u_height_m * a_amount);
}
