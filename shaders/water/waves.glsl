// Small-scale detail shared by the water's shaders: wind ripples and foam noise.

// Small wind ripples the wave grid is too coarse to carry; they fade with distance,
// where finer than a pixel they would only alias.
vec2 ripple_slope(vec2 p, float t, float dist) {
    vec2 s = vec2(0.0);
    const vec3 waves[4] = vec3[](vec3(0.9, 0.3, 0.35), vec3(-0.4, 0.9, 0.55), vec3(0.2, -1.0, 0.9), vec3(-0.8, -0.5, 1.6));
    for (int i = 0; i < 4; ++i) {
        vec2 dir = normalize(waves[i].xy);
        float k = waves[i].z * 2.0;
        float phase = dot(dir, p) * k - t * sqrt(9.81 * k);
        s += dir * (0.024 * cos(phase));
    }
    return s * exp(-dist / 60.0);
}

// Value noise on a lattice of hashed values. The hash is arithmetic only (Hoskins'
// "hash without sine", for the four corners at once): llvmpipe evaluates sin as a
// range reduction and a polynomial, and the foam is read up to four times a pixel.
float foam_noise(vec2 p) {
    vec2 i = floor(p), f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    vec4 a = fract((i.x + vec4(0.0, 1.0, 0.0, 1.0)) * 0.1031);
    vec4 b = fract((i.y + vec4(0.0, 0.0, 1.0, 1.0)) * 0.1031);
    vec4 d = a * (b + 33.33) + b * (a + 33.33) + a * (a + 33.33);
    vec4 h = fract((a + b + 2.0 * d) * (a + d));
    return mix(mix(h.x, h.y, u.x), mix(h.z, h.w, u.x), u.y);
}
