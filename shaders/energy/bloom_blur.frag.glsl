#version 450 core
// One direction of a separable Gaussian (9 taps) over the low-resolution glow: the
// energy's bloom, so the light bleeds past the beam's own falloff.
in vec2 v_uv;
uniform sampler2D u_source;
uniform vec2 u_step;  // one texel along the blur direction, in texture coordinates
out vec4 o_colour;

const float kWeights[5] = float[](0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216);

void main() {
    vec3 sum = texture(u_source, v_uv).rgb * kWeights[0];
    for (int i = 1; i < 5; ++i)
        sum += (texture(u_source, v_uv + u_step * float(i)).rgb + texture(u_source, v_uv - u_step * float(i)).rgb) *
               kWeights[i];
    o_colour = vec4(sum, 0.0);
}
