#version 450 core
// A soft round droplet, premultiplied alpha: a smooth bump with no hard edge.
in vec2 v_corner;
in vec3 v_colour;
in float v_alpha;
layout(location = 0) out vec4 o_colour;
void main() {
    float d2 = dot(v_corner, v_corner);
    if (d2 >= 1.0) discard;
    float w = 1.0 - d2;
    float a = v_alpha * w * w;
    o_colour = vec4(v_colour * a, a);
}
