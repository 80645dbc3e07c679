#version 450 core
// The water mask as depth: far (cleared) where there is no water, kSeaDepth on the sea
// and kSheetDepth on splash sheets, so the shading passes can let the depth test skip
// every other pixel before any shading runs (a discard would not spare the work).
uniform sampler2D u_kind;  // r: 0 none, 0.5 sea, 0.76..1 sheet
uniform float u_sea_depth;
uniform float u_sheet_depth;
void main() {
    float kind = texelFetch(u_kind, ivec2(gl_FragCoord.xy), 0).r;
    if (kind < 0.25) discard;
    gl_FragDepth = kind < 0.7 ? u_sea_depth : u_sheet_depth;
}
