#include "game/level/LevelLoader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <nlohmann/json.hpp>

#include "game/DataPaths.h"
#include "game/dust/FibreImage.h"
#include "game/level/GltfModel.h"
#include "game/level/LevelMemory.h"
#include "game/level/LevelNames.h"
#include "game/level/LevelParser.h"
#include "game/level/LevelReader.h"
#include "sim/core/DetMath.h"
#include "sim/core/Hash.h"
#include "sim/fluid/FluidTank.h"
#include "sim/objectives/Course.h"

namespace game {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A turn about +y by the sim's own sine and cosine (glm::rotate calls libm's): props'
// transforms make the sim's solids and decks, which must be the same on every machine.
glm::mat4 rotate_y(float angle_rad) {
    float s, c;
    sim::det::sincos(angle_rad, s, c);
    glm::mat4 m(1.0f);
    m[0] = {c, 0.0f, -s, 0.0f};
    m[2] = {s, 0.0f, c, 0.0f};
    return m;
}

bool looks_like_path(std::string_view s) {
    return s.find('/') != std::string_view::npos || (s.size() >= 5 && s.substr(s.size() - 5) == ".json");
}

bool name_starts_with(const std::string& name, std::string_view prefix) {
    return name.compare(0, prefix.size(), prefix) == 0;
}

// World-space box of one mesh under a prop transform (from every vertex, so a turned
// prop gets a tight box).
sim::Aabb world_box(const effects::MeshData& mesh, const glm::mat4& transform) {
    sim::Aabb box;
    bool first = true;
    for (const effects::MeshVertex& v : mesh.vertices) {
        glm::vec3 p(transform * glm::vec4(v.position, 1.0f));
        box.min = first ? p : glm::min(box.min, p);
        box.max = first ? p : glm::max(box.max, p);
        first = false;
    }
    return box;
}

// The rain's glass from the car model's "windshield" mesh: a strip of quads across
// the car, two points (lower and upper edge) at each z, left (-z) to right. A car
// without one has no windshield rain; a mesh of another shape is refused.
void windshield_edges(const effects::Model& car, const std::string& where, const LevelReader& r, sim::RainDesc& rain) {
    const effects::MeshData* glass = nullptr;
    for (const effects::MeshData& m : car.meshes)
        if (m.name == "windshield") glass = &m;
    if (!glass) return;
    std::vector<glm::vec3> points;
    for (const effects::MeshVertex& v : glass->vertices) {
        bool seen = false;
        for (glm::vec3 q : points)
            seen = seen || (std::fabs(q.x - v.position.x) < 1e-5f && std::fabs(q.y - v.position.y) < 1e-5f &&
                            std::fabs(q.z - v.position.z) < 1e-5f);
        if (!seen) points.push_back(v.position);
        if (points.size() > 4096) r.fail(where, "the windshield mesh has more than 4096 distinct points");
    }
    std::sort(points.begin(), points.end(), [](glm::vec3 a, glm::vec3 b) { return a.z < b.z || (a.z == b.z && a.y < b.y); });
    for (size_t i = 0; i < points.size();) {
        size_t j = i;
        while (j < points.size() && points[j].z - points[i].z < 1e-4f) ++j;
        if (j - i != 2)
            r.fail(where, "the windshield mesh must be a strip of quads across the car (two points at each z), found " +
                              std::to_string(j - i) + " at z = " + std::to_string(points[i].z));
        rain.glass_lower.push_back(points[i]);
        rain.glass_upper.push_back(points[i + 1]);
        i = j;
    }
    if (rain.glass_lower.size() < 2) r.fail(where, "the windshield mesh must span at least two points across the car");
}

// A dusty prop's triangles in world space: every mesh of its model, placed.
sim::DustyPropDesc dusty_prop(const effects::Model& model, const glm::mat4& transform, std::string name,
                              sim::DustKind kind) {
    sim::DustyPropDesc d;
    d.name = std::move(name);
    d.kind = kind;
    const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(transform)));
    for (const effects::MeshData& mesh : model.meshes) {
        const auto base = uint32_t(d.positions.size());
        for (const effects::MeshVertex& v : mesh.vertices) {
            d.positions.push_back(glm::vec3(transform * glm::vec4(v.position, 1.0f)));
            glm::vec3 n = normal_matrix * v.normal;
            float len = glm::length(n);
            d.normals.push_back(len > 1e-8f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f));
        }
        for (uint32_t i : mesh.indices) d.indices.push_back(base + i);
    }
    return d;
}

}  // namespace

fs::path resolve_level_path(std::string_view name_or_path) {
    if (name_or_path.empty()) throw LevelError("empty level name");
    if (looks_like_path(name_or_path)) return fs::path(name_or_path);
    return data_dir() / "levels" / (std::string(name_or_path) + ".json");
}

LoadedLevel load_level(std::string_view name_or_path, FibreImageReader fibre_reader) {
    const fs::path path = resolve_level_path(name_or_path);
    std::error_code ec;
    if (!fs::exists(path, ec)) {
        if (looks_like_path(name_or_path)) throw LevelError(path.string() + ": level file not found");
        std::string message = "no level named '" + std::string(name_or_path) + "' (looked for " + path.string() + ")";
        const std::vector<std::string> names = level_names(path.parent_path());
        if (const std::optional<std::string> near = nearest_level_name(name_or_path, names))
            message += "; did you mean '" + *near + "'?";
        std::string list;
        for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
        message += message.back() == '?' ? " " : ". ";
        message += list.empty() ? path.parent_path().string() + " holds no levels"
                                : "The levels in " + path.parent_path().string() + ": " + list;
        throw LevelError(message);
    }
    return load_level_text(path, read_level_file(path, kMaxLevelJsonBytes), fibre_reader);
}

LoadedLevel load_level_text(const fs::path& path, const std::string& text, FibreImageReader fibre_reader) {
    LoadedLevel out;
    out.path = path;
    if (text.size() > kMaxLevelJsonBytes)
        throw LevelError(out.path.string() + ": too large (" + std::to_string(text.size()) + " bytes, at most " +
                         std::to_string(kMaxLevelJsonBytes) + ")");
    if (json_nesting_depth(text) > kMaxJsonNesting)
        throw LevelError(out.path.string() + ": invalid JSON: nested deeper than " + std::to_string(kMaxJsonNesting) +
                         " levels");
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::exception& e) {
        throw LevelError(out.path.string() + ": invalid JSON: " + e.what());
    }

    std::vector<Placement> placements;  // car, boat, then props
    uint64_t budget_mib = kDefaultLevelBudgetMib;
    DustSection dust;
    parse_level(out.path, doc, out.sim, budget_mib, placements, dust);
    LevelReader r(out.path);
    // Everything the level states is charged before the world or any asset is made.
    out.memory = MemoryBudget(out.path.string(), budget_mib * kMiB);
    charge_level_memory(out.sim, out.memory);

    sim::Hasher content;
    content.u64(text.size());
    content.bytes(text.data(), text.size());

    // Each distinct asset once, in first-use order: that order is also the hash order.
    fs::path asset_dir = out.path.parent_path() / out.path.stem();
    std::error_code ec;
    std::map<std::string, int> model_of_asset;
    for (const Placement& p : placements) {
        std::string key = fs::path(p.asset).lexically_normal().generic_string();
        if (model_of_asset.count(key)) continue;
        fs::path file = asset_dir / key;
        if (!fs::is_regular_file(file, ec))
            r.fail(p.where + ".asset", p.asset + " not found (looked in " + asset_dir.string() + ")");
        content.u64(key.size());
        content.bytes(key.data(), key.size());
        // Parsing holds the text, its JSON and the decoded buffers at once: about four
        // times the file (external buffers are bounded by the glTF loader's own limit).
        const uint64_t file_bytes = fs::file_size(file, ec);
        out.memory.require("loading " + key, ec ? 0 : 4 * file_bytes);
        try {
            out.scene.models.push_back(load_gltf_model(file, &content));
        } catch (const LevelError& e) {
            r.fail(p.where + ".asset", e.what());
        }
        out.memory.charge("model " + key, model_memory_bytes(out.scene.models.back()));
        model_of_asset[key] = int(out.scene.models.size()) - 1;
    }
    out.content_hash = content.value();

    windshield_edges(out.scene.models[size_t(model_of_asset.at(fs::path(placements[0].asset).lexically_normal().generic_string()))],
                     placements[0].where + ".asset", r, out.sim.rain);

    for (size_t i = 0; i < placements.size(); ++i) {
        const Placement& p = placements[i];
        int model = model_of_asset.at(fs::path(p.asset).lexically_normal().generic_string());
        if (i == 0) out.scene.car_model = model;
        if (i == 1) out.scene.boat_model = model;
        if (i < 2) continue;  // vehicles are drawn at their sim pose

        glm::mat4 transform = glm::translate(glm::mat4(1.0f), p.position) * rotate_y(p.heading_rad) *
                              glm::scale(glm::mat4(1.0f), glm::vec3(p.scale));
        out.scene.props.push_back({model, transform});

        bool have_deck = false;
        sim::Aabb deck;
        for (const effects::MeshData& mesh : out.scene.models[size_t(model)].meshes) {
            if (p.collision == Collision::none || name_starts_with(mesh.name, "nocollide")) continue;
            sim::Aabb box = world_box(mesh, transform);
            if (p.collision == Collision::solid || name_starts_with(mesh.name, "piling")) {
                out.sim.solids.push_back(box);
            } else {
                deck.min = have_deck ? glm::min(deck.min, box.min) : box.min;
                deck.max = have_deck ? glm::max(deck.max, box.max) : box.max;
                have_deck = true;
            }
        }
        if (p.dusty) {
            if (!dust.present) r.fail(p.where + ".dust", "the prop is dusty but the level has no \"dust\" section");
            out.sim.dust.props.push_back(dusty_prop(out.scene.models[size_t(model)], transform,
                                                    fs::path(p.asset).stem().string() + " (" + p.where + ")",
                                                    p.dust_kind.value_or(dust.preset)));
        }
        if (p.collision == Collision::deck) {
            if (!have_deck) r.fail(p.where + ".collision", "'deck' but " + p.asset + " has no meshes besides piling*/nocollide*");
            out.sim.decks.push_back(deck);
        }
    }
    if (dust.present) {
        out.sim.dust.enabled = true;
        fs::path image = asset_dir / dust.fibre_image;
        try {
            if (fibre_reader) out.scene.fibre_directions = fibre_reader(image, dust.fibre_slices);
        } catch (const FibreImageError& e) {
            r.fail("dust.fibre_image", e.what());
        }
    }
    return out;
}

}  // namespace game
