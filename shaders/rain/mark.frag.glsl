#version 450 core
// Marks the wet tiles in the depth buffer (tiles.vert.glsl): no colour.
void main() {}
