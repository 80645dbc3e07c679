#version 450 core
in float v_alpha;
in vec3 v_colour;
layout(location = 0) out vec4 o_colour;
void main() { o_colour = vec4(v_colour, v_alpha); }
