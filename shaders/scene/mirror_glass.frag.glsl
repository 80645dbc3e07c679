#version 450 core
// The rear-view mirror's glass showing MirrorPass's picture of the view behind.
in vec3 v_world_pos;
in vec4 v_color;

uniform sampler2D u_picture;  // from the glass looking back out of the car
uniform vec3 u_centre;        // the glass's centre
uniform vec3 u_across;        // the driver's right, over the glass's half width
uniform vec3 u_up;            // up, over its half height

layout(location = 0) out vec4 o_colour;

const float kReflectance = 0.85;  // a silvered glass mirror

void main() {
    vec3 d = v_world_pos - u_centre;
    // A mirror shows what is behind on the driver's right on its right; the camera looking
    // back has it on its left, so the picture is read right to left.
    vec2 uv = vec2(0.5 - 0.5 * dot(d, u_across), 0.5 + 0.5 * dot(d, u_up));
    o_colour = vec4(texture(u_picture, uv).rgb * kReflectance, 1.0);
}
