#version 450 core
// The sea surface's geometry step (WaterShading): depth only. Its normal, crests and
// wake are worked out once per pixel in the sea's shading (shade_sea.frag.glsl), not
// for every pixel of every partly covered block of the dense lattice, and no colour
// target is written here.
void main() {}
