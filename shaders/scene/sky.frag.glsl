#version 450 core
#include "common/sky.glsl"
// The sky behind everything: drawn where nothing else wrote depth.
in vec2 v_uv;
uniform mat4 u_inv_view_proj;
layout(location = 0) out vec4 o_colour;
#ifdef SCENE_NORMALS  // only when SceneTargets draws them
layout(location = 1) out vec4 o_normal;
#endif
void main() {
    vec4 far = u_inv_view_proj * vec4(v_uv * 2.0 - 1.0, 1.0, 1.0);
    vec4 near = u_inv_view_proj * vec4(v_uv * 2.0 - 1.0, -1.0, 1.0);
    vec3 dir = far.xyz / far.w - near.xyz / near.w;
    o_colour = vec4(sky_radiance(dir, true), 1.0);
#ifdef SCENE_NORMALS
    o_normal = vec4(0.0);
#endif
}
