// From the splatted sums to the drops' surface (seed 5.2-5.4; DropHeightMap.h), shared
// by the windshield, which takes it per pixel from the sums filtered bilinearly, and
// shape.frag.glsl, which takes it per texel for the tests and the bench. A point is
// taken as one 3D metaball: the drop that dominates it (radius R, squared distance a
// in radii, both N^2-weighted means), with the strength s that gives the summed
// density n = s / (1 + a^2). That ball's field s / (1 + (a + z^2)^2) falls to T at the
// height z = sqrt(sqrt(s / T - 1) - a) radii: a lone drop's hemisphere, and exact where
// two equal drops meet.
uniform float u_threshold;
uniform float u_first_level, u_level_step, u_k;
uniform int u_steps;  // the seed's compression of n - T; 0 by default

// Sums N, N^2 R (mm), N^2 x^2, N^2 to a height in mm; 0: dry.
float drop_height_mm(vec4 s) {
    float v = s.r - u_threshold;
    if (v <= 0.0 || s.a <= 0.0) return 0.0;
    for (int i = 0; i < u_steps; ++i) {
        float v0 = u_first_level + u_level_step * float(i);
        if (v > v0) v = u_k * (v - v0) + v0;
    }
    float a = s.b / s.a, radius_mm = s.g / s.a;
    float strength = (v + u_threshold) * (1.0 + a * a);
    return radius_mm * sqrt(max(sqrt(max(strength / u_threshold - 1.0, 0.0)) - a, 0.0));
}

// The surface at a point from the sums there (s) and one map texel further along u
// (su) and v (sv), texel_mm apart: rg the normal's u and v components (z implied),
// b the height in mm, a 1 on water; all 0 on dry glass. The normal is the cross
// product of the tangents (dx, 0, dh_u) and (0, dy, dh_v).
vec4 drop_surface(vec4 s, vec4 su, vec4 sv, vec2 texel_mm) {
    float h = drop_height_mm(s);
    if (h <= 0.0) return vec4(0.0);
    float hu = drop_height_mm(su), hv = drop_height_mm(sv);
    vec3 n = normalize(vec3(-(hu - h) * texel_mm.y, -(hv - h) * texel_mm.x, texel_mm.x * texel_mm.y));
    return vec4(n.xy, h, 1.0);
}
