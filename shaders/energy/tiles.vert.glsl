#version 450 core
// One quad per screen tile that some segment may cover (EnergyTiles), so the pass
// shades only those pixels. Strip of 4 vertices, one instance per tile.
layout(std430, binding = 1) readonly buffer EnergyTiles { uvec4 u_tiles[]; };  // tile x, y, first, count

uniform vec2 u_viewport;
uniform float u_tile_px;

flat out uvec2 v_list;  // first index into u_tile_segments, count

void main() {
    uvec4 t = u_tiles[gl_InstanceID];
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    vec2 px = min((vec2(t.xy) + corner) * u_tile_px, u_viewport);
    v_list = t.zw;
    gl_Position = vec4(px / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
