#pragma once
// Building blocks of make_assets: deterministic variation, parts (one node, one
// triangle primitive, one material) and the solids the assets are built from.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_inverse.hpp>

namespace assets {

using glm::mat4;
using glm::vec2;
using glm::vec3;
using glm::vec4;

using Shade = std::function<vec4(vec3)>;  // vertex colour (times the material) from position

struct Xf {  // where a helper's local geometry goes inside its part
    mat4 m{1.0f};
    vec3 p(vec3 v) const { return vec3(m * vec4(v, 1.0f)); }
    vec3 n(vec3 v) const { return glm::normalize(glm::inverseTranspose(glm::mat3(m)) * v); }
};

// One node with one triangle primitive and one material.
struct Part {
    std::string name;
    int material = 0;
    vec3 translation{0.0f};  // node translation (the geometry is built around the node origin)
    std::vector<vec3> pos, nrm;
    std::vector<vec4> col;
    std::vector<uint32_t> idx;

    uint32_t v(vec3 p, vec3 n, vec4 c) {
        pos.push_back(p);
        nrm.push_back(n);
        col.push_back(glm::clamp(c, 0.0f, 1.0f));
        return uint32_t(pos.size() - 1);
    }
    // Winding follows the vertex normals, so helpers need not care about vertex order.
    void tri(uint32_t a, uint32_t b, uint32_t c) {
        vec3 g = glm::cross(pos[b] - pos[a], pos[c] - pos[a]);
        if (glm::dot(g, nrm[a] + nrm[b] + nrm[c]) < 0.0f) std::swap(b, c);
        idx.insert(idx.end(), {a, b, c});
    }
    void quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
        tri(a, b, c);
        tri(a, c, d);
    }
};

struct Material {
    std::string name;
    vec4 color;
    float metallic, roughness;
    vec3 emissive{0.0f};
};

struct Asset {
    std::string name;
    std::vector<Material> materials;
    std::vector<Part> parts;

    Part& part(const std::string& part_name, const Material& mat, vec3 translation = vec3(0.0f)) {
        auto it = std::find_if(materials.begin(), materials.end(), [&](const Material& x) { return x.name == mat.name; });
        if (it == materials.end()) it = materials.insert(materials.end(), mat);
        parts.push_back({part_name, int(it - materials.begin()), translation, {}, {}, {}, {}});
        return parts.back();
    }
};

// Deterministic variation and solids; the definitions say what each one builds.
float hash01(uint32_t x);
float lattice(int x, int y, int z);
float value_noise(vec3 p);
Xf at(vec3 t, float yaw = 0.0f);
Xf turned(Xf base, float angle, vec3 axis);
Shade flat(vec4 c = vec4(1.0f));
void poly(Part& m, const Xf& x, const std::vector<vec3>& pts, vec3 normal, const Shade& s);
void box(Part& m, const Xf& x, vec3 lo, vec3 hi, const Shade& s, bool top = true);
void prism(Part& m, const Xf& x, const std::vector<vec2>& profile, float z0, float z1, const Shade& s);
void cylinder(Part& m, const Xf& x, float r0, float r1, float y0, float y1, int segments, const Shade& s,
              bool caps = true);
void ring_sector(Part& m, const Xf& x, float r_in, float r_out, float a0, float a1, float z0, float z1, int steps,
                 const Shade& s);
void corrugated(Part& m, const Xf& x, float x0, float x1, float y0, float y1, const Shade& s);
void surface(Part& m, const std::function<vec3(float, float)>& P, int nu, int nv, const Shade& s,
             vec3 centre = {0.0f, 0.1f, 0.0f});

}  // namespace assets
