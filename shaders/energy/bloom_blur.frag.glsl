#version 450 core
// One direction of a separable 9-tap Gaussian over the low-resolution glow: the
// energy's bloom, so the light bleeds past the beam's own falloff. Taps 1-2 and 3-4
// each come from one linear fetch between them (weighted offsets), five fetches in all.
in vec2 v_uv;
uniform sampler2D u_source;
uniform vec2 u_step;  // one texel along the blur direction, in texture coordinates
out vec4 o_colour;

const float kCentre = 0.227027;
const float kWeights[2] = float[](0.3162162, 0.0702703);  // 0.1945946 + 0.1216216, 0.054054 + 0.016216
const float kOffsets[2] = float[](1.3846154, 3.2307692);  // (1 w1 + 2 w2) / (w1 + w2), (3 w3 + 4 w4) / (w3 + w4)

void main() {
    vec3 sum = texture(u_source, v_uv).rgb * kCentre;
    for (int i = 0; i < 2; ++i)
        sum += (texture(u_source, v_uv + u_step * kOffsets[i]).rgb + texture(u_source, v_uv - u_step * kOffsets[i]).rgb) *
               kWeights[i];
    o_colour = vec4(sum, 0.0);
}
