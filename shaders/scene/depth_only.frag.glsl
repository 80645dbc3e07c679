#version 450 core
// Depth only: the shadow and sky-occlusion maps, and the vehicles' depth before shading.
void main() {}
