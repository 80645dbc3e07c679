// HDR scene colour to the display's encoding: exposure (by the caller), the ACES filmic
// fit (Narkowicz 2015), sRGB. Both steps rise with their input channel by channel, so
// the tone-mapped minimum of some colours is the tone map of their minimum
// (temporal.frag.glsl clamps with that).
vec3 aces(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
// The sRGB curve above its linear toe, 1.055 c^(1/2.4) - 0.055, as a sum of c's 2nd,
// 4th and 8th roots and c itself, fitted minimax over [0.0031308, 1]: within 0.012 of
// an 8-bit step everywhere. pow is a logarithm and an exponential on llvmpipe, a
// square root one instruction.
vec3 srgb_encode(vec3 c) {
    vec3 r2 = sqrt(c), r4 = sqrt(r2), r8 = sqrt(r4);
    vec3 curve = 0.64234386 * r2 + 0.71213817 * r4 - 0.33688213 * r8 - 0.01755676 * c;
    return mix(c * 12.92, curve, step(0.0031308, c));
}
vec3 tonemap(vec3 hdr_times_exposure) { return srgb_encode(aces(hdr_times_exposure)); }
