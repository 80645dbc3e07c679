#include "game/level/LevelParser.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "game/level/LevelLoader.h"
#include "game/level/LevelMemory.h"
#include "game/level/MemoryBudget.h"
#include "game/level/LevelReader.h"
#include "sim/fluid/FluidTank.h"
#include "sim/objectives/Course.h"
#include "sim/rain/RainParams.h"

namespace game {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr size_t kMaxHills = 256;
constexpr size_t kMaxRoads = 1024;
constexpr size_t kMaxCourses = 8;
constexpr size_t kMaxGates = 64;
constexpr size_t kMaxTargets = 64;
constexpr float kMinGateWidth_m = 2.0f;
constexpr float kMaxGateWidth_m = 40.0f;

class LevelParser {
public:
    LevelParser(const fs::path& file, const json& doc) : r_(file), doc_(doc) {}

    // Everything in the JSON, checked; assets are only named here, not loaded.
    void parse(sim::LevelDesc& level, uint64_t& budget_mib, std::vector<Placement>& placements, DustSection& dust) {
        r_.object(doc_, "", {"format", "id", "seed", "budget_mib", "world", "roads", "sun", "rain", "water", "fluid", "dust", "car", "boat", "tank_spot", "courses", "targets", "props"});
        const json& format = r_.required(doc_, "", "format");
        if (!format.is_number_unsigned() || format.get<uint64_t>() != 1)
            r_.fail("format", "unsupported format " + (format.is_primitive() ? format.dump() : std::string(format.type_name())) +
                                  " (this build reads format 1)");
        level.id = r_.string(r_.required(doc_, "", "id"), "id");
        if (level.id.empty() || level.id.size() > 64) r_.fail("id", "must have 1 to 64 characters");
        if (const json* seed = LevelReader::optional(doc_, "seed")) {
            if (!seed->is_number_unsigned()) r_.fail("seed", "expected a non-negative integer");
            level.seed = seed->get<uint64_t>();
        }
        if (const json* budget = LevelReader::optional(doc_, "budget_mib")) {
            if (!budget->is_number_unsigned() || budget->get<uint64_t>() < kMinLevelBudgetMib ||
                budget->get<uint64_t>() > kMaxLevelBudgetMib)
                r_.fail("budget_mib", "expected a whole number of MiB from " + std::to_string(kMinLevelBudgetMib) +
                                          " to " + std::to_string(kMaxLevelBudgetMib));
            budget_mib = budget->get<uint64_t>();
        }
        world(r_.required(doc_, "", "world"), level);
        if (const json* roads = LevelReader::optional(doc_, "roads")) {
            r_.array(*roads, "roads", kMaxRoads);
            for (size_t i = 0; i < roads->size(); ++i) level.roads.push_back(road((*roads)[i], index_path("roads", i)));
        }
        if (const json* sun = LevelReader::optional(doc_, "sun")) {
            r_.object(*sun, "sun", {"direction"});
            glm::vec3 d = r_.vec<3>(r_.required(*sun, "sun", "direction"), "sun.direction");
            if (!(d.y > 0.0f)) r_.fail("sun.direction", "must point upwards (y > 0)");
            level.sun_direction = glm::normalize(d);
        }
        if (const json* rain = LevelReader::optional(doc_, "rain")) {
            r_.object(*rain, "rain", {"intensity", "cell_size_m"});
            level.rain_intensity = r_.number_in(r_.required(*rain, "rain", "intensity"), "rain.intensity", 0.0f, 1.0f);
            if (const json* cell = LevelReader::optional(*rain, "cell_size_m"))
                level.rain.cell_size_m = r_.number_in(*cell, "rain.cell_size_m", sim::kMinRainCell_m, sim::kMaxRainCell_m);
        }
        if (const json* water = LevelReader::optional(doc_, "water")) water_grid(*water, level);
        if (const json* fluid = LevelReader::optional(doc_, "fluid")) fluid_tank(*fluid, level);
        if (const json* d = LevelReader::optional(doc_, "dust")) dust_section(*d, level, dust);
        if (const json* courses = LevelReader::optional(doc_, "courses")) {
            r_.array(*courses, "courses", kMaxCourses);
            for (size_t i = 0; i < courses->size(); ++i)
                level.objectives.courses.push_back(course((*courses)[i], index_path("courses", i), level));
        }
        if (const json* targets = LevelReader::optional(doc_, "targets")) {
            r_.array(*targets, "targets", kMaxTargets);
            for (size_t i = 0; i < targets->size(); ++i)
                level.objectives.targets.push_back(target((*targets)[i], index_path("targets", i), level));
        }
        placements.push_back(placement(r_.required(doc_, "", "car"), "car", false));
        placements.push_back(placement(r_.required(doc_, "", "boat"), "boat", false));
        level.car_spawn = {placements[0].position, placements[0].heading_rad};
        level.boat_spawn = {placements[1].position, placements[1].heading_rad};
        level.tank_spot = position(r_.required(doc_, "", "tank_spot"), "tank_spot");
        for (const sim::Aabb& wall : sim::tank_walls(level.fluid, level.tank_spot)) level.solids.push_back(wall);
        if (const json* props = LevelReader::optional(doc_, "props")) {
            r_.array(*props, "props", kMaxLevelProps);
            for (size_t i = 0; i < props->size(); ++i)
                placements.push_back(placement((*props)[i], index_path("props", i), true));
        }
    }

private:
    sim::DustKind dust_kind(const json& v, const std::string& where) {
        std::string name = r_.string(v, where);
        sim::DustKind kind;
        if (!sim::parse_dust_kind(name, kind)) r_.fail(where, "'" + name + "' is not one of dust, sand, mould");
        return kind;
    }

    // "dust": {"preset": "dust", "fibre_image": "dust_fibres.png", "fibre_slices": 3,
    //          "sources_per_prop": 5, "source_elevation_deg": 65, "source_distance": 2.5,
    //          "sample_spacing_m": 0.08, "object_clear_radius_m": 0.25, "shot_clear_radius_m": 0.6}
    // Props with "dust": true (the preset) or a preset name are dusty.
    void dust_section(const json& d, sim::LevelDesc& level, DustSection& out) {
        r_.object(d, "dust", {"preset", "fibre_image", "fibre_slices", "sources_per_prop", "source_elevation_deg",
                              "source_distance", "sample_spacing_m", "object_clear_radius_m", "shot_clear_radius_m"});
        out.present = true;
        sim::DustDesc& g = level.dust;
        g.enabled = true;  // known now, so the memory budget can charge it
        if (const json* p = LevelReader::optional(d, "preset")) out.preset = dust_kind(*p, "dust.preset");
        out.fibre_image = r_.string(r_.required(d, "dust", "fibre_image"), "dust.fibre_image");
        fs::path image(out.fibre_image);
        bool escapes = std::any_of(image.begin(), image.end(), [](const fs::path& part) { return part == ".."; });
        if (out.fibre_image.empty() || image.is_absolute() || escapes)
            r_.fail("dust.fibre_image", "'" + out.fibre_image + "' must be a relative path inside the level's folder, without '..'");
        if (const json* n = LevelReader::optional(d, "fibre_slices")) {
            if (!n->is_number_integer() || n->get<int64_t>() < 1 || n->get<int64_t>() > kMaxFibreSlices)
                r_.fail("dust.fibre_slices", "expected a whole number from 1 to " + std::to_string(kMaxFibreSlices));
            out.fibre_slices = int(n->get<int64_t>());
        }
        if (const json* n = LevelReader::optional(d, "sources_per_prop")) {
            if (!n->is_number_integer() || n->get<int64_t>() < 1 || n->get<int64_t>() > 16)
                r_.fail("dust.sources_per_prop", "expected a whole number from 1 to 16");
            g.sources_per_prop = int(n->get<int64_t>());
        }
        auto num = [&](const char* key, float& v, float lo, float hi, bool lo_open) {
            if (const json* n = LevelReader::optional(d, key)) v = r_.number_in(*n, key_path("dust", key), lo, hi, lo_open);
        };
        num("source_elevation_deg", g.source_elevation_deg, 0.0f, 90.0f, false);
        num("source_distance", g.source_distance, 1.2f, 100.0f, false);
        num("sample_spacing_m", g.sample_spacing_m, 0.01f, 10.0f, false);
        num("object_clear_radius_m", g.object_clear_radius_m, 0.0f, 10.0f, false);
        num("shot_clear_radius_m", g.shot_clear_radius_m, 0.0f, 10.0f, false);
    }

    // "water": {"grid_origin_xz": [x, z], "grid_size": 256, "grid_spacing_m": 0.5,
    //           "wave_speed_mps": 2.5, "damping_per_s": 0.25 (a fraction lost per second,
    //           [0, 1) as sim::WaveGrid refuses)}; the sim checks stability.
    void water_grid(const json& w, sim::LevelDesc& level) {
        r_.object(w, "water", {"grid_origin_xz", "grid_size", "grid_spacing_m", "wave_speed_mps", "damping_per_s"});
        sim::WaterGridDesc& g = level.water;
        g.enabled = true;
        g.origin_xz = r_.vec<2>(r_.required(w, "water", "grid_origin_xz"), "water.grid_origin_xz");
        const json& size = r_.required(w, "water", "grid_size");
        if (!size.is_number_integer() || size.get<int64_t>() < 8 || size.get<int64_t>() > 2048)
            r_.fail("water.grid_size", "expected a whole number from 8 to 2048");
        g.size = int(size.get<int64_t>());
        g.spacing_m = r_.number_in(r_.required(w, "water", "grid_spacing_m"), "water.grid_spacing_m", 0.01f, 100.0f);
        g.wave_speed_mps = r_.number_in(r_.required(w, "water", "wave_speed_mps"), "water.wave_speed_mps", 0.0f, 100.0f, true);
        g.damping_per_s = r_.number_in(r_.required(w, "water", "damping_per_s"), "water.damping_per_s", 0.0f, 1.0f, false, true);
    }

    int whole_in(const json& v, const std::string& where, int lo, int hi) const {
        if (!v.is_number_integer() || v.get<int64_t>() < lo || v.get<int64_t>() > hi)
            r_.fail(where, "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
        return int(v.get<int64_t>());
    }

    // "fluid": {"particle_count": 6000, "particle_radius_m": 0.03, "tank_size_m": [1.6, 1.1, 1.6],
    //           "solver_iterations": 3, "body_neighbours": 12, "on": "pier" | "boat",
    //           "smoothing": {"method": "plane_fit" | "bilateral" | "narrow_range",
    //                         "kernel_size": 9 (odd, 3..15), "iterations": 3 (1..64)}}
    // All keys optional. The radius and the tank's size are held to what sim::ParticleFluid
    // refuses (a radius in (0.001, 1] m, at least 4 radii of tank on each axis); the sim
    // checks that the particles fit the tank.
    void fluid_tank(const json& f, sim::LevelDesc& level) {
        r_.object(f, "fluid", {"particle_count", "particle_radius_m", "tank_size_m", "solver_iterations",
                               "body_neighbours", "on", "smoothing"});
        sim::FluidTankDesc& d = level.fluid;
        d.enabled = true;
        if (const json* v = LevelReader::optional(f, "particle_count")) d.particle_count = whole_in(*v, "fluid.particle_count", 1, 200000);
        if (const json* v = LevelReader::optional(f, "particle_radius_m"))
            d.particle_radius_m = r_.number_in(*v, "fluid.particle_radius_m", 0.001f, 1.0f, true);
        if (const json* v = LevelReader::optional(f, "tank_size_m")) {
            d.inner_size_m = r_.vec<3>(*v, "fluid.tank_size_m");
            const float least = 4.0f * d.particle_radius_m;
            for (int a = 0; a < 3; ++a) {
                const std::string where = index_path("fluid.tank_size_m", size_t(a));
                if (!(d.inner_size_m[a] > 0.0f && d.inner_size_m[a] <= 20.0f)) r_.fail(where, "expected a size in (0, 20] m");
                if (!(d.inner_size_m[a] >= least))
                    r_.fail(where, show(d.inner_size_m[a]) + " m is less than 4 particle radii (" + show(least) + " m)");
            }
        }
        if (const json* v = LevelReader::optional(f, "solver_iterations"))
            d.solver_iterations = whole_in(*v, "fluid.solver_iterations", 1, 20);
        if (const json* v = LevelReader::optional(f, "body_neighbours")) d.body_neighbours = whole_in(*v, "fluid.body_neighbours", 1, 60);
        if (const json* v = LevelReader::optional(f, "on")) {
            std::string on = r_.string(*v, "fluid.on");
            if (on != "pier" && on != "boat") r_.fail("fluid.on", "expected \"pier\" or \"boat\", got \"" + on + "\"");
            d.on_boat = on == "boat";
        }
        if (const json* sm = LevelReader::optional(f, "smoothing")) {
            r_.object(*sm, "fluid.smoothing", {"method", "kernel_size", "iterations"});
            if (const json* v = LevelReader::optional(*sm, "method")) {
                d.smoothing = r_.string(*v, "fluid.smoothing.method");
                if (d.smoothing != "plane_fit" && d.smoothing != "bilateral" && d.smoothing != "narrow_range")
                    r_.fail("fluid.smoothing.method",
                            "expected \"plane_fit\", \"bilateral\" or \"narrow_range\", got \"" + d.smoothing + "\"");
                // Each method's own defaults (seed: plane fitting 9x9 x3, bilateral 7x7 x22).
                if (d.smoothing == "bilateral") {
                    d.kernel_size = 7;
                    d.smoothing_iterations = 22;
                }
            }
            if (const json* v = LevelReader::optional(*sm, "kernel_size")) {
                d.kernel_size = whole_in(*v, "fluid.smoothing.kernel_size", 3, 15);
                if (d.kernel_size % 2 == 0) r_.fail("fluid.smoothing.kernel_size", "must be odd, got " + std::to_string(d.kernel_size));
            }
            if (const json* v = LevelReader::optional(*sm, "iterations"))
                d.smoothing_iterations = whole_in(*v, "fluid.smoothing.iterations", 1, 64);
        }
    }

    void world(const json& w, sim::LevelDesc& level) {
        r_.object(w, "world", {"half_extent_m", "land_height_m", "shore_z_m", "sea_level_m", "seabed_m", "hills"});
        auto num = [&](const char* key, float lo, float hi, bool lo_open = false) {
            return r_.number_in(r_.required(w, "world", key), key_path("world", key), lo, hi, lo_open);
        };
        level.half_extent_m = half_extent_ = num("half_extent_m", 0.0f, 2000.0f, true);
        level.land_height_m = num("land_height_m", -kMaxAbsCoordinate_m, kMaxAbsCoordinate_m);
        level.shore_z_m = num("shore_z_m", -half_extent_, half_extent_);
        level.sea_level_m = num("sea_level_m", -kMaxAbsCoordinate_m, kMaxAbsCoordinate_m);
        level.seabed_m = num("seabed_m", -kMaxAbsCoordinate_m, kMaxAbsCoordinate_m);
        if (!(level.seabed_m < level.sea_level_m)) r_.fail("world.seabed_m", "must be below sea_level_m");
        if (const json* hills = LevelReader::optional(w, "hills")) {
            r_.array(*hills, "world.hills", kMaxHills);
            for (size_t i = 0; i < hills->size(); ++i) {
                std::string where = index_path("world.hills", i);
                const json& h = (*hills)[i];
                r_.object(h, where, {"centre_xz", "radius_m", "height_m"});
                sim::Hill hill;
                hill.centre_xz = r_.vec<2>(r_.required(h, where, "centre_xz"), where + ".centre_xz");
                hill.radius_m = r_.number_in(r_.required(h, where, "radius_m"), where + ".radius_m", 0.0f, 2000.0f, true);
                hill.height_m = r_.number_in(r_.required(h, where, "height_m"), where + ".height_m", -kMaxAbsCoordinate_m,
                                             kMaxAbsCoordinate_m);
                level.hills.push_back(hill);
            }
        }
    }

    sim::Rect road(const json& v, const std::string& where) {
        r_.object(v, where, {"min_xz", "max_xz"});
        sim::Rect rect;
        rect.min = r_.vec<2>(r_.required(v, where, "min_xz"), where + ".min_xz");
        rect.max = r_.vec<2>(r_.required(v, where, "max_xz"), where + ".max_xz");
        if (!(rect.min.x < rect.max.x && rect.min.y < rect.max.y))
            r_.fail(where + ".max_xz", "must be greater than min_xz in x and z");
        return rect;
    }

    // A course's gates stand where its vehicle goes: a car's on land, a boat's on the sea,
    // both posts inside the world.
    sim::CourseDesc course(const json& v, const std::string& where, const sim::LevelDesc& level) {
        r_.object(v, where, {"name", "vehicle", "gates"});
        sim::CourseDesc c;
        c.name = r_.string(r_.required(v, where, "name"), where + ".name");
        if (c.name.empty() || c.name.size() > 32) r_.fail(where + ".name", "must have 1 to 32 characters");
        for (const sim::CourseDesc& other : level.objectives.courses)
            if (other.name == c.name) r_.fail(where + ".name", "'" + c.name + "' names another course too");
        const std::string vehicle = r_.string(r_.required(v, where, "vehicle"), where + ".vehicle");
        if (vehicle == "car") c.vehicle = sim::CourseVehicle::Car;
        else if (vehicle == "boat") c.vehicle = sim::CourseVehicle::Boat;
        else r_.fail(where + ".vehicle", "expected \"car\" or \"boat\", got \"" + vehicle + "\"");
        const json& gates = r_.array(r_.required(v, where, "gates"), where + ".gates", kMaxGates);
        if (gates.size() < 2) r_.fail(where + ".gates", "a course needs at least 2 gates, found " + std::to_string(gates.size()));
        for (size_t i = 0; i < gates.size(); ++i) {
            const std::string at = index_path(where + ".gates", i);
            const json& g = gates[i];
            r_.object(g, at, {"centre_xz", "heading_deg", "width_m"});
            sim::GateDesc gate;
            gate.centre_xz = r_.vec<2>(r_.required(g, at, "centre_xz"), at + ".centre_xz");
            gate.heading_rad = glm::radians(r_.number_in(r_.required(g, at, "heading_deg"), at + ".heading_deg", -720.0f, 720.0f));
            gate.width_m = r_.number_in(r_.required(g, at, "width_m"), at + ".width_m", kMinGateWidth_m, kMaxGateWidth_m);
            const sim::GatePosts posts = sim::gate_posts(gate);
            for (glm::vec2 post : {posts.left, posts.right}) {
                if (std::fabs(post.x) > half_extent_ || std::fabs(post.y) > half_extent_)
                    r_.fail(at, "a post lies outside the world (half_extent_m " + show(half_extent_) + ")");
                const bool on_land = post.y < level.shore_z_m;
                if (c.vehicle == sim::CourseVehicle::Car && !on_land)
                    r_.fail(at, "a car's gate must stand on land (z < shore_z_m " + show(level.shore_z_m) + "), a post is at z " + show(post.y));
                if (c.vehicle == sim::CourseVehicle::Boat && on_land)
                    r_.fail(at, "a boat's gate must stand on the sea (z >= shore_z_m " + show(level.shore_z_m) + "), a post is at z " + show(post.y));
            }
            c.gates.push_back(gate);
        }
        return c;
    }

    // Buoys float on the sea; crates stand on land.
    sim::TargetDesc target(const json& v, const std::string& where, const sim::LevelDesc& level) {
        r_.object(v, where, {"kind", "position", "radius_m"});
        sim::TargetDesc t;
        const std::string kind = r_.string(r_.required(v, where, "kind"), where + ".kind");
        if (kind == "buoy") t.kind = sim::TargetKind::Buoy;
        else if (kind == "crate") t.kind = sim::TargetKind::Crate;
        else r_.fail(where + ".kind", "expected \"buoy\" or \"crate\", got \"" + kind + "\"");
        t.position = position(r_.required(v, where, "position"), where + ".position");
        t.radius_m = r_.number_in(r_.required(v, where, "radius_m"), where + ".radius_m", 0.2f, 3.0f);
        const bool on_land = t.position.z < level.shore_z_m;
        if (t.kind == sim::TargetKind::Buoy && on_land) r_.fail(where + ".position", "a buoy must float on the sea (z >= shore_z_m " + show(level.shore_z_m) + ")");
        if (t.kind == sim::TargetKind::Crate && !on_land) r_.fail(where + ".position", "a crate must stand on land (z < shore_z_m " + show(level.shore_z_m) + ")");
        return t;
    }

    glm::vec3 position(const json& v, const std::string& where) {
        glm::vec3 p = r_.vec<3>(v, where);
        if (std::fabs(p.x) > half_extent_ || std::fabs(p.z) > half_extent_)
            r_.fail(where, "lies outside the world (half_extent_m " + show(half_extent_) + ")");
        return p;
    }

    Placement placement(const json& v, const std::string& where, bool is_prop) {
        if (is_prop) r_.object(v, where, {"asset", "position", "heading_deg", "scale", "collision", "dust"});
        else r_.object(v, where, {"asset", "position", "heading_deg"});
        Placement p;
        p.where = where;
        p.asset = r_.string(r_.required(v, where, "asset"), where + ".asset");
        fs::path asset(p.asset);
        bool escapes = std::any_of(asset.begin(), asset.end(), [](const fs::path& part) { return part == ".."; });
        if (p.asset.empty() || asset.is_absolute() || escapes)
            r_.fail(where + ".asset", "'" + p.asset + "' must be a relative path inside the level's folder, without '..'");
        if (asset.extension() != ".gltf" && asset.extension() != ".glb")
            r_.fail(where + ".asset", "'" + p.asset + "' must be a .gltf or .glb file");
        p.position = position(r_.required(v, where, "position"), where + ".position");
        if (const json* h = LevelReader::optional(v, "heading_deg"))
            p.heading_rad = glm::radians(r_.number_in(*h, where + ".heading_deg", -720.0f, 720.0f));
        if (!is_prop) return p;
        if (const json* s = LevelReader::optional(v, "scale"))
            p.scale = r_.number_in(*s, where + ".scale", 0.0f, 1000.0f, true);
        if (const json* c = LevelReader::optional(v, "collision")) {
            std::string mode = r_.string(*c, where + ".collision");
            if (mode == "solid") p.collision = Collision::solid;
            else if (mode == "deck") p.collision = Collision::deck;
            else if (mode != "none") r_.fail(where + ".collision", "'" + mode + "' is not one of solid, deck, none");
        }
        if (const json* d = LevelReader::optional(v, "dust")) {
            if (d->is_boolean()) p.dusty = d->get<bool>();
            else if (d->is_string()) p.dusty = true, p.dust_kind = dust_kind(*d, where + ".dust");
            else r_.fail(where + ".dust", "expected true, false or a preset name (dust, sand, mould)");
        }
        return p;
    }

    LevelReader r_;
    const json& doc_;
    float half_extent_ = 0.0f;
};

}  // namespace

void parse_level(const fs::path& file, const json& doc, sim::LevelDesc& level, uint64_t& budget_mib,
                 std::vector<Placement>& placements, DustSection& dust) {
    LevelParser(file, doc).parse(level, budget_mib, placements, dust);
}

}  // namespace game
