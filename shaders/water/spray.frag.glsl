#version 450 core
// A soft round droplet, premultiplied alpha: a smooth bump with no hard edge.
in vec2 v_corner;
in vec3 v_colour;
in float v_alpha;
in vec2 v_glint_at;
in vec3 v_glint;
in float v_sharp;
layout(location = 0) out vec4 o_colour;
void main() {
    float d2 = dot(v_corner, v_corner);
    if (d2 >= 1.0) discard;
    float w = 1.0 - d2;
    // A drop large enough to resolve (v_sharp 1) has a firmer edge; a blurred one is a
    // soft bump.
    float a = v_alpha * mix(w * w, smoothstep(0.0, 0.3, w), 0.4 * v_sharp);
    // The highlight adds light over the drop (premultiplied: no cover of its own).
    vec2 g = (v_corner - 0.75 * v_glint_at) * 6.0;
    o_colour = vec4(v_colour * a + v_glint * exp(-dot(g, g)) * w, a);
}
