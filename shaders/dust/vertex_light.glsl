// Per-vertex light for the dust: what a white diffuse surface would reflect here (sun
// with its shadow map, the sky as far as the vertex sees it: SkyExposure.h), and the
// fog towards the eye (rgb: sky colour, a: amount).
uniform vec3 u_eye;

void light_vertex(vec3 p, vec3 n, float sky_seen, out vec3 light, out vec4 fog) {
    // The dust's own sky exposure (a hemisphere of the props above it), finer than the
    // top-down map's yes or no.
    light = shade_surface_seeing_sky(vec3(1.0), 1.0, 0.0, p, n, u_eye, sky_seen);
    vec3 d = p - u_eye;
    float dist = length(d);
    fog = vec4(sky_radiance(d / max(dist, 1e-4), false), 1.0 - exp(-dist * 0.0012));
}
