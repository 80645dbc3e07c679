#version 450 core
// One rectangle per run of height-map tiles where water can be (DropTiles::wet), so
// the per-texel passes shade only those texels; the rest are cleared. Six vertices
// per run in one plain draw. Under llvmpipe a texel costs several times more in a
// small triangle than in one covering whole 64x64 bins, so runs beat single tiles.
layout(std430, binding = 3) readonly buffer WetRuns { uvec2 u_runs[]; };  // first tile, count
uniform int u_tile_texels, u_tile_cols;
uniform vec2 u_texels;  // the target's size
void main() {
    uvec2 run = u_runs[gl_VertexID / 6];
    int v = gl_VertexID % 6;  // (0,0) (1,0) (0,1), (0,1) (1,0) (1,1)
    vec2 corner = vec2(v == 1 || v == 4 || v == 5, v == 2 || v == 3 || v == 5);
    vec2 first = vec2(run.x % uint(u_tile_cols), run.x / uint(u_tile_cols));
    vec2 px = min((first + corner * vec2(run.y, 1.0)) * float(u_tile_texels), u_texels);
    gl_Position = vec4(px / u_texels * 2.0 - 1.0, 0.0, 1.0);
}
