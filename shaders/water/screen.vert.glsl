#version 450 core
// One triangle covering the viewport at a chosen depth: the water's shading passes
// are depth-tested against the water mask, so pixels without water are never shaded.
uniform float u_window_depth;  // 0 (near) .. 1 (far)
void main() {
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(p * 2.0 - 1.0, u_window_depth * 2.0 - 1.0, 1.0);
}
