// Per-vertex light for the dust: what a white diffuse surface would reflect here (sun
// with its shadow map, sky), and the fog towards the eye (rgb: sky colour, a: amount).
uniform vec3 u_eye;

void light_vertex(vec3 p, vec3 n, out vec3 light, out vec4 fog) {
    light = shade_surface(vec3(1.0), 1.0, 0.0, p, n, u_eye);
    vec3 d = p - u_eye;
    float dist = length(d);
    fog = vec4(sky_radiance(d / max(dist, 1e-4), false), 1.0 - exp(-dist * 0.0012));
}
