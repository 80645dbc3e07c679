// Per-vertex light for the dust: what a white diffuse surface would reflect here (sun
// with its shadow map, the sky as far as the vertex sees it: SkyExposure.h), and the
// fog towards the eye (rgb: sky colour, a: amount).
uniform vec3 u_eye;
// The fraction of the sky's light a roofed interior still gets, bounced.
const float kBouncedSky = 0.7;

void light_vertex(vec3 p, vec3 n, float sky_seen, out vec3 light, out vec4 fog) {
    light = shade_surface(vec3(1.0), 1.0, 0.0, p, n, u_eye);
    // The sky light shade_surface added: where a roof hides the sky (sky_seen < 1) it
    // arrives instead as light bounced off the floor and walls, dimmer and no longer
    // sky blue (grey: the building's albedo is not known here).
    vec3 sky = textureLod(u_env, n, u_env_max_lod).rgb * (0.6 + 0.4 * n.y);
    vec3 bounced = vec3(dot(sky, vec3(0.2126, 0.7152, 0.0722))) * kBouncedSky;
    light += (1.0 - sky_seen) * (bounced - sky);
    vec3 d = p - u_eye;
    float dist = length(d);
    fog = vec4(sky_radiance(d / max(dist, 1e-4), false), 1.0 - exp(-dist * 0.0012));
}
