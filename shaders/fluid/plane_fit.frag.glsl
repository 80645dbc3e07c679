#version 450 core
#include "fluid/filter.glsl"
// Local plane fitting (seed 4.3): the window's pixels back-projected to view space,
// weighted by depth likeness; the plane minimising sum w (n.p + d)^2 with |n| = 1 has
// n = the weighted covariance's eigenvector of the smallest eigenvalue. The pixel's
// new depth is where its view ray meets that plane, unless that moved it too far (a
// plane nearly along the ray).
uniform float u_sigma;       // depth weight scale, view units
uniform float u_max_move;    // larger moves keep the old depth

// Eigenvector of the smallest eigenvalue of a symmetric 3x3 (analytic eigenvalues,
// vector from the rows of C - lambda I).
vec3 smallest_eigenvector(mat3 m) {
    float p1 = m[0][1] * m[0][1] + m[0][2] * m[0][2] + m[1][2] * m[1][2];
    float q = (m[0][0] + m[1][1] + m[2][2]) / 3.0;
    float p2 = (m[0][0] - q) * (m[0][0] - q) + (m[1][1] - q) * (m[1][1] - q) + (m[2][2] - q) * (m[2][2] - q) + 2.0 * p1;
    float p = sqrt(max(p2 / 6.0, 1e-30));
    mat3 b = (m - q * mat3(1.0)) / p;
    float r = clamp(determinant(b) * 0.5, -1.0, 1.0);
    float phi = acos(r) / 3.0;
    float smallest = q + 2.0 * p * cos(phi + 2.0943951);
    mat3 a = m - smallest * mat3(1.0);
    vec3 r0 = vec3(a[0][0], a[1][0], a[2][0]), r1 = vec3(a[0][1], a[1][1], a[2][1]), r2 = vec3(a[0][2], a[1][2], a[2][2]);
    vec3 c01 = cross(r0, r1), c02 = cross(r0, r2), c12 = cross(r1, r2);
    float d01 = dot(c01, c01), d02 = dot(c02, c02), d12 = dot(c12, c12);
    vec3 n = d01 > d02 ? (d01 > d12 ? c01 : c12) : (d02 > d12 ? c02 : c12);
    return normalize(n);
}

void main() {
    ivec2 pix;
    float z;
    if (!start_filter(pix, z)) return;
    vec3 ray = view_ray(gl_FragCoord.xy);
    vec3 centre_point = ray * z;
    // Moments about the pixel's own point, for precision.
    float wsum = 0.0;
    vec3 m1 = vec3(0.0);
    mat3 m2 = mat3(0.0);
    float inv_s2 = 1.0 / (u_sigma * u_sigma);
    for (int j = -u_half; j <= u_half; ++j)
        for (int i = -u_half; i <= u_half; ++i) {
            ivec2 q = clamp_to_rect(pix + ivec2(i, j));
            float zq = texelFetch(u_depth, q, 0).r;
            if (!has_depth(zq)) continue;
            float w = exp(-(z - zq) * (z - zq) * inv_s2);
            vec3 d = view_ray(vec2(q) + 0.5) * zq - centre_point;
            wsum += w;
            m1 += w * d;
            m2 += w * outerProduct(d, d);
        }
    vec3 mean = m1 / wsum;
    mat3 cov = m2 / wsum - outerProduct(mean, mean);
    vec3 n = smallest_eigenvector(cov);
    // Plane through centre_point + mean with normal n; ray * t on it.
    float denom = dot(n, ray);
    if (abs(denom) < 1e-6) return;
    float t = dot(n, centre_point + mean) / denom;
    if (abs(t - z) <= u_max_move) o_depth = t;
}
