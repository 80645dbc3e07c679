#version 450 core
// Adds the blurred glow to the HDR scene (additive blending, scissored to where it is).
in vec2 v_uv;
uniform sampler2D u_bloom;
uniform float u_strength;
out vec4 o_colour;

void main() { o_colour = vec4(texture(u_bloom, v_uv).rgb * u_strength, 0.0); }
