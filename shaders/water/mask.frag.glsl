#version 450 core
// The water mask as depth, written for every pixel of the water's rectangle (so it
// needs no clear): u_sea_depth where the sea's geometry step drew (the scene's depth is
// nearer than the copy taken before the water), u_sheet_depth where a splash sheet
// did (SHEETS: its kind target), u_none_depth elsewhere. The shading passes let the
// depth test skip every other pixel before any shading runs (a discard would not spare
// the work).
uniform sampler2D u_depth;        // the scene's depth, water included
uniform sampler2D u_scene_depth;  // the copy taken before the water
uniform sampler2D u_kind;         // r: 0.76..1 on a sheet, 0 elsewhere
uniform float u_none_depth;
uniform float u_sea_depth;
uniform float u_sheet_depth;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    float d = texelFetch(u_depth, px, 0).r < texelFetch(u_scene_depth, px, 0).r ? u_sea_depth : u_none_depth;
#ifdef SHEETS
    if (texelFetch(u_kind, px, 0).r > 0.7) d = u_sheet_depth;
#endif
    gl_FragDepth = d;
}
