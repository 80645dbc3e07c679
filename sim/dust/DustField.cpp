#include "sim/dust/DustField.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "sim/dust/DustAccumulation.h"
#include "sim/objects/ThrownObjects.h"
#include "sim/weapon/Weapon.h"
#include "sim/world/World.h"

namespace sim {

namespace {

void check_range(const char* name, float v, float lo, float hi) {
    if (!(v >= lo && v <= hi))
        throw std::invalid_argument(std::string("dust: ") + name + " " + std::to_string(v) + " is outside [" +
                                    std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

float distance_to_segment(glm::vec3 p, glm::vec3 a, glm::vec3 b) {
    glm::vec3 ab = b - a;
    float len2 = glm::dot(ab, ab);
    float t = len2 > 1e-12f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + ab * t));
}

}  // namespace

const char* dust_kind_name(DustKind kind) {
    switch (kind) {
        case DustKind::Dust: return "dust";
        case DustKind::Sand: return "sand";
        case DustKind::Mould: return "mould";
    }
    return "?";
}

bool parse_dust_kind(const std::string& name, DustKind& out) {
    for (int k = 0; k < kDustKindCount; ++k)
        if (name == dust_kind_name(DustKind(k))) {
            out = DustKind(k);
            return true;
        }
    return false;
}

DustField::DustField(const DustDesc& desc) : desc_(desc) {
    if (desc.sources_per_prop < 1 || desc.sources_per_prop > 16)
        throw std::invalid_argument("dust: sources_per_prop " + std::to_string(desc.sources_per_prop) +
                                    " is outside [1, 16]");
    check_range("source_elevation_deg", desc.source_elevation_deg, 0.0f, 90.0f);
    check_range("source_distance", desc.source_distance, 1.2f, 100.0f);
    check_range("sample_spacing_m", desc.sample_spacing_m, 0.01f, 10.0f);
    check_range("object_clear_radius_m", desc.object_clear_radius_m, 0.0f, 10.0f);
    check_range("shot_clear_radius_m", desc.shot_clear_radius_m, 0.0f, 10.0f);
    surface_ = DustSurface(desc.props, desc.sample_spacing_m);
    amounts_.assign(surface_.positions().size(), 0.0f);
    for (size_t p = 0; p < surface_.props().size(); ++p)
        sources_.push_back(accumulate_dust(surface_, p, desc.props, desc_, amounts_));
    desc_.props.clear();  // the triangles live on in surface_
    desc_.props.shrink_to_fit();
}

bool DustField::clear_along(glm::vec3 p0, glm::vec3 p1, float radius_m) {
    if (!(radius_m > 0.0f)) return false;
    const glm::vec3 lo = glm::min(p0, p1) - glm::vec3(radius_m), hi = glm::max(p0, p1) + glm::vec3(radius_m);
    bool changed = false;
    for (const DustPropRange& prop : surface_.props()) {
        if (glm::any(glm::lessThan(hi, prop.bounds.min)) || glm::any(glm::greaterThan(lo, prop.bounds.max))) continue;
        for (uint32_t v = prop.first_vertex; v < prop.first_vertex + prop.vertex_count; ++v) {
            float& a = amounts_[v];
            if (a <= 0.0f) continue;
            float d = distance_to_segment(surface_.positions()[v], p0, p1);
            if (d >= radius_m) continue;
            float t = std::clamp((d - 0.6f * radius_m) / (0.4f * radius_m), 0.0f, 1.0f);
            float kept = a * t * t * (3.0f - 2.0f * t);
            if (kept < a) {
                a = kept;
                changed = true;
            }
        }
    }
    if (changed) ++revision_;
    return changed;
}

void DustField::connect(const SubsystemLinks& links) {
    thrown_ = &links.need<ThrownObjects>();
    weapon_ = &links.need<Weapon>();
}

void DustField::step(StepContext& ctx) {
    // Where each object went this tick: back along its velocity to where it was.
    for (const ThrownObject& o : thrown_->objects())
        clear_along(o.position - o.velocity * ctx.dt, o.position, o.radius_m + desc_.object_clear_radius_m);
    const Weapon& weapon = *weapon_;
    const float full = weapon.params().strength;
    for (const Shot& s : weapon.shots())
        for (const EnergySegment& seg : s.segments) {
            float strength = full > 0.0f ? std::min(seg.beam_strength / full, 1.0f) : 0.0f;  // 1, fading to 0
            if (seg.length_m > 0.0f && strength > 0.0f)
                clear_along(seg.start, seg.start + seg.direction * seg.length_m, desc_.shot_clear_radius_m * strength);
        }
}

float DustField::amount_near(glm::vec3 p) const {
    const auto& pos = surface_.positions();
    size_t best = 0;
    float best_d = INFINITY;
    for (size_t v = 0; v < pos.size(); ++v) {
        glm::vec3 d = pos[v] - p;
        float d2 = glm::dot(d, d);
        if (d2 < best_d) {
            best_d = d2;
            best = v;
        }
    }
    return pos.empty() ? 0.0f : amounts_[best];
}


}  // namespace sim
