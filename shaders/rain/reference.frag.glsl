#version 450 core
// The 3D metaball reference on the GPU (ReferenceHeightMap.h): per texel, the height
// above the glass where the 3D field of the drops reaching its tile falls to T, by
// bisection, as effects/rain/MetaballReference.cpp does on the CPU.
layout(std430, binding = 0) readonly buffer Drops { vec4 u_drops[]; };  // centre u, v (m), radius (m), unused
layout(std430, binding = 1) readonly buffer Tiles { uvec2 u_tiles[]; };  // first, count in u_tile_drops
layout(std430, binding = 2) readonly buffer TileDrops { uint u_tile_drops[]; };
uniform vec2 u_texel_m;
uniform int u_tile_texels, u_tile_cols;
uniform float u_threshold, u_reach, u_ceiling_m;
uniform int u_bisections;
layout(location = 0) out float o_height_mm;  // 0: dry

// Sum over the tile's drops of N(d) = 1 / (1 + (d/R)^4), d the 3D distance (z2 = z^2).
float field(uvec2 tile, vec2 p, float z2) {
    float sum = 0.0;
    for (uint k = tile.x; k < tile.x + tile.y; ++k) {
        vec4 d = u_drops[u_tile_drops[k]];
        vec2 e = p - d.xy;
        float q = (e.x * e.x + e.y * e.y + z2) / (d.z * d.z);
        if (q < u_reach * u_reach) sum += 1.0 / (1.0 + q * q);
    }
    return sum;
}

void main() {
    ivec2 i = ivec2(gl_FragCoord.xy);
    uvec2 tile = u_tiles[(i.y / u_tile_texels) * u_tile_cols + i.x / u_tile_texels];
    vec2 p = (vec2(i) + 0.5) * u_texel_m;
    o_height_mm = 0.0;
    if (field(tile, p, 0.0) <= u_threshold) return;
    // The field falls with height above the glass.
    float lo = 0.0, hi = u_ceiling_m;
    for (int k = 0; k < u_bisections; ++k) {
        float mid = 0.5 * (lo + hi);
        if (field(tile, p, mid * mid) > u_threshold) lo = mid;
        else hi = mid;
    }
    o_height_mm = 0.5 * (lo + hi) * 1000.0;
}
