#version 450 core
// The ghost (effects/scene/GhostPass.cpp): the vehicle's own colours washed towards a
// pale tint, lit by the sun with a floor so its shaded side still reads, see-through
// face on and more opaque edge on, so that its outline carries it. Premultiplied.
in vec3 v_world_pos;
in vec3 v_normal;
in vec4 v_color;

uniform vec3 u_eye;
uniform vec3 u_sun_dir;
uniform vec3 u_sun_radiance;
uniform vec3 u_ghost_tint;
uniform float u_opacity;
uniform float u_rim;

layout(location = 0) out vec4 o_colour;

void main() {
    vec3 n = normalize(v_normal);
    vec3 v = normalize(u_eye - v_world_pos);
    float edge = 1.0 - clamp(abs(dot(n, v)), 0.0, 1.0);
    float rim = edge * edge;
    float sun = clamp(dot(n, u_sun_dir), 0.0, 1.0);
    vec3 albedo = mix(v_color.rgb, u_ghost_tint, 0.6);
    vec3 light = u_sun_radiance * (0.35 + 0.65 * sun) / 3.14159265;
    vec3 colour = albedo * light + u_ghost_tint * light * 2.0 * rim;
    float alpha = clamp(u_opacity + u_rim * rim, 0.0, 0.95);
    o_colour = vec4(colour * alpha, alpha);
}
