// Shared by the fluid passes: the tank's screen rectangle, view rays and depth maps.
// Depths are view-space distances along -z (positive in front of the eye); a map with
// no liquid at a pixel holds kNoDepth (front maps) or 0 (back maps).
const float kNoDepth = 1.0e6;
uniform ivec4 u_rect;      // x0, y0, x1, y1 (exclusive) in pixels: the only pixels read or written
uniform mat4 u_proj;
uniform vec2 u_viewport;   // width, height in pixels

ivec2 clamp_to_rect(ivec2 p) { return clamp(p, u_rect.xy, u_rect.zw - 1); }

// View-space direction through pixel centre `p` (pixels), scaled so its z is -1: a
// point at view distance z along it is ray * z.
vec3 view_ray(vec2 p) {
    vec2 ndc = p / u_viewport * 2.0 - 1.0;
    return vec3(ndc.x / u_proj[0][0], ndc.y / u_proj[1][1], -1.0);
}

// Pixel position (not rounded) of a view-space point.
vec2 project_to_pixel(vec3 v) {
    vec4 c = u_proj * vec4(v, 1.0);
    return (c.xy / c.w * 0.5 + 0.5) * u_viewport;
}

bool has_depth(float z) { return z > 0.0 && z < 0.5 * kNoDepth; }
