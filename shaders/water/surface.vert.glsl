#version 450 core
// The sea surface: lattice vertices (tile-local integer coordinates) over the wave
// grid, lifted by its heights, and the flat frame around it. On a tile edge shared
// with a coarser tile (or the frame) a vertex folds onto the coarser edge's vertex
// below it, so both sides of the edge have the same vertices and no crack opens.
layout(location = 0) in vec4 a_vertex;  // lattice coords (tile-local), or world xz if z = 1
uniform mat4 u_view_proj;
uniform float u_sea_level;
uniform sampler2D u_wave_grid;  // texel (i, j): slopes, Laplacian and height (w) of cell (i, j)
uniform vec2 u_grid_origin;
uniform float u_grid_spacing;
uniform int u_grid_size;
uniform vec2 u_lattice_origin;
uniform float u_lattice_cell_m;
uniform int u_lattice_cells;
uniform ivec2 u_tile_origin;  // lattice coordinates of the tile's corner
uniform int u_tile_cells;
uniform ivec4 u_edge_stride;  // on the tile's -z, +x, +z, -x edges
invariant gl_Position;

void main() {
    vec2 xz;
    float h = 0.0;
    if (a_vertex.z > 0.5) {
        xz = a_vertex.xy;
    } else {
        ivec2 l = ivec2(a_vertex.xy);
        int t = u_tile_cells;
        if (l.y == 0) l.x -= l.x % u_edge_stride.x;
        else if (l.y == t) l.x -= l.x % u_edge_stride.z;
        if (l.x == 0) l.y -= l.y % u_edge_stride.w;
        else if (l.x == t) l.y -= l.y % u_edge_stride.y;
        ivec2 g = u_tile_origin + l;
        xz = u_lattice_origin + vec2(g) * u_lattice_cell_m;
        // The lattice's border stays at rest, where the frame meets it.
        if (all(greaterThan(g, ivec2(0))) && all(lessThan(g, ivec2(u_lattice_cells)))) {
            vec2 cell = (xz - u_grid_origin) / u_grid_spacing;
            h = textureLod(u_wave_grid, (cell + 0.5) / float(u_grid_size), 0.0).w;
        }
    }
    gl_Position = u_view_proj * vec4(xz.x, u_sea_level + h, xz.y, 1.0);
}
