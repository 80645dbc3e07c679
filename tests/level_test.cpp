// Level loading: the harbour level, broken levels and glTF files, and the glTF -> Model
// conversion on generated and hand-built files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "LevelFiles.h"
#include "game/DataPaths.h"
#include "game/level/GltfModel.h"
#include "game/level/LevelLoader.h"
#include "game/level/LevelNames.h"
#include "game/session/GameSession.h"
#include "sim/rain/RainParams.h"
#include "sim/world/Terrain.h"

namespace {

using namespace level_files;

bool inside(const sim::Aabb& b, glm::vec3 p) {
    return p.x >= b.min.x && p.x <= b.max.x && p.y >= b.min.y && p.y <= b.max.y && p.z >= b.min.z && p.z <= b.max.z;
}
bool in_any_solid(const sim::LevelDesc& l, glm::vec3 p) {
    for (const sim::Aabb& b : l.solids)
        if (inside(b, p)) return true;
    return false;
}
const effects::MeshData* find_mesh(const effects::Model& m, const std::string& name) {
    for (const effects::MeshData& mesh : m.meshes)
        if (mesh.name == name) return &mesh;
    return nullptr;
}
void mesh_bounds(const effects::MeshData& m, glm::vec3& lo, glm::vec3& hi) {
    lo = hi = m.vertices.at(0).position;
    for (const auto& v : m.vertices) lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
}

// ---- the harbour -------------------------------------------------------------------------

TEST(LevelLoader, HarbourLoadsByNameAndByPath) {
    game::LoadedLevel a = game::load_level("harbour");
    game::LoadedLevel b = game::load_level(harbour_json().string());
    EXPECT_EQ(a.path, harbour_json());
    EXPECT_EQ(a.sim.id, "harbour");
    EXPECT_EQ(a.sim.seed, 20261122u);
    EXPECT_EQ(a.content_hash, b.content_hash);
    EXPECT_NE(a.content_hash, 0u);

    ASSERT_GE(a.scene.car_model, 0);
    ASSERT_GE(a.scene.boat_model, 0);
    EXPECT_NE(a.scene.car_model, a.scene.boat_model);
    EXPECT_EQ(a.scene.models[size_t(a.scene.car_model)].name, "car");
    EXPECT_EQ(a.scene.models[size_t(a.scene.boat_model)].name, "boat");
    EXPECT_GT(a.scene.props.size(), 10u);
    EXPECT_EQ(a.scene.models.size(), 17u);  // one per distinct asset, though 68 props use them
    for (const effects::PropInstance& p : a.scene.props) {
        ASSERT_GE(p.model, 0);
        ASSERT_LT(size_t(p.model), a.scene.models.size());
    }

    EXPECT_FLOAT_EQ(a.sim.half_extent_m, 160.0f);
    EXPECT_EQ(a.sim.hills.size(), 3u);
    EXPECT_EQ(a.sim.roads.size(), 2u);
    EXPECT_NEAR(glm::length(a.sim.sun_direction), 1.0f, 1e-6f);
    EXPECT_GT(a.sim.sun_direction.y, 0.0f);
    EXPECT_EQ(a.sim.car_spawn.position, glm::vec3(-20.0f, 1.2f, -10.0f));
    EXPECT_FLOAT_EQ(a.sim.car_spawn.heading_rad, 0.0f);
    EXPECT_FLOAT_EQ(a.sim.boat_spawn.heading_rad, -glm::half_pi<float>());
    EXPECT_EQ(a.sim.tank_spot, glm::vec3(22.0f, 1.5f, 36.0f));

    // The pier: one deck whose top is flush with the land, pilings down to the sea bed.
    ASSERT_EQ(a.sim.decks.size(), 1u);
    const sim::Aabb& deck = a.sim.decks[0];
    EXPECT_NEAR(deck.max.y, 1.2f, 1e-4f);
    EXPECT_NEAR(deck.min.x, 18.0f, 1e-4f);
    EXPECT_NEAR(deck.max.x, 26.0f, 1e-4f);
    EXPECT_NEAR(deck.min.z, -2.0f, 1e-4f);
    EXPECT_NEAR(deck.max.z, 40.0f, 1e-4f);
    EXPECT_TRUE(in_any_solid(a.sim, {18.3f, -3.0f, 1.0f}));  // a piling
    EXPECT_FALSE(in_any_solid(a.sim, {22.0f, -3.0f, 10.0f}));

    // The warehouse is hollow: walls are solids, the hall and the door opening are not.
    EXPECT_TRUE(in_any_solid(a.sim, {-54.85f, 3.0f, -40.0f}));  // west wall
    EXPECT_TRUE(in_any_solid(a.sim, {-50.0f, 3.0f, -30.15f}));  // south wall beside the door
    EXPECT_FALSE(in_any_solid(a.sim, {-40.0f, 3.0f, -30.15f}));  // door opening
    EXPECT_FALSE(in_any_solid(a.sim, {-40.0f, 3.0f, -40.0f}));  // inside the hall
    EXPECT_TRUE(in_any_solid(a.sim, {-40.0f, 8.3f, -40.0f}));  // roof
    EXPECT_TRUE(in_any_solid(a.sim, {-50.5f, 1.8f, -46.0f}));  // a crate
    // "nocollide" meshes: the warehouse floor and tree crowns add no solids.
    EXPECT_FALSE(in_any_solid(a.sim, {-40.0f, 1.21f, -45.0f}));
    EXPECT_FALSE(in_any_solid(a.sim, {0.0f, 9.2f + 4.0f, -80.0f + 1.0f}));
    EXPECT_TRUE(in_any_solid(a.sim, {0.0f, 9.2f + 1.0f, -80.0f}));  // its trunk
}

// Props stand on the sim's ground (hill tails included), and the warehouse and the
// road are flat.
TEST(LevelLoader, HarbourPropsStandOnTheGround) {
    game::LoadedLevel level = game::load_level("harbour");
    sim::Terrain terrain(level.sim);
    for (size_t i = 0; i < level.scene.props.size(); ++i) {
        const effects::PropInstance& p = level.scene.props[i];
        const std::string& model = level.scene.models[size_t(p.model)].name;
        glm::vec3 at(p.transform[3]);
        if (at.z > -1.0f || model == "crate_small") continue;  // on the pier, or stacked
        EXPECT_NEAR(at.y, terrain.ground_height({at.x, at.z}), 0.02f) << "props[" << i << "] " << model;
    }
    for (float x = -150.0f; x <= 150.0f; x += 2.5f)
        for (float z = -50.0f; z <= -6.0f; z += 2.0f) {
            bool in_warehouse = x >= -55.0f && x <= -25.0f && z <= -30.0f;
            bool on_road = level.sim.roads[0].contains({x, z}) || level.sim.roads[1].contains({x, z});
            if (in_warehouse || on_road) {
                EXPECT_NEAR(terrain.ground_height({x, z}), 1.2f, 0.03f) << x << ", " << z;
            }
        }
}

TEST(LevelLoader, ContentHashFollowsEveryByte) {
    TempDir tmp("hash");
    fs::copy(harbour_json(), tmp.path / "harbour.json");
    fs::copy(game::data_dir() / "levels" / "harbour", tmp.path / "harbour");
    uint64_t original = game::load_level(harbour_json().string()).content_hash;
    EXPECT_EQ(game::load_level((tmp.path / "harbour.json").string()).content_hash, original);

    std::string text = slurp(tmp.path / "harbour.json");
    size_t at = text.find("20261122");
    ASSERT_NE(at, std::string::npos);
    text[at + 7] = '3';
    spit(tmp.path / "harbour.json", text);
    uint64_t seed_changed = game::load_level((tmp.path / "harbour.json").string()).content_hash;
    EXPECT_NE(seed_changed, original);

    std::string pine = slurp(tmp.path / "harbour" / "pine.gltf");
    spit(tmp.path / "harbour" / "pine.gltf", pine + " ");  // still valid glTF
    EXPECT_NE(game::load_level((tmp.path / "harbour.json").string()).content_hash, seed_changed);
}

TEST(LevelLoader, ResolvesNamesAndPaths) {
    EXPECT_EQ(game::resolve_level_path("harbour"), game::data_dir() / "levels" / "harbour.json");
    EXPECT_EQ(game::resolve_level_path("some/dir/x.json"), fs::path("some/dir/x.json"));
    EXPECT_EQ(game::resolve_level_path("x.json"), fs::path("x.json"));
    expect_error([] { game::resolve_level_path(""); }, {"empty level name"});
}

// ---- broken levels -----------------------------------------------------------------------

TEST(LevelLoader, SuggestsTheNearestLevelNameForATypo) {
    const std::vector<std::string> names = {"canal", "harbour", "harbour_night"};
    EXPECT_EQ(game::nearest_level_name("harbor", names), "harbour");
    EXPECT_EQ(game::nearest_level_name("Harbour", names), "harbour");  // case ignored
    EXPECT_EQ(game::nearest_level_name("harbour_nite", names), "harbour_night");
    EXPECT_EQ(game::nearest_level_name("canl", names), "canal");
    EXPECT_FALSE(game::nearest_level_name("lighthouse", names).has_value());
    EXPECT_FALSE(game::nearest_level_name("harbor", {}).has_value());
    const std::vector<std::string> bundled = game::level_names(game::data_dir() / "levels");
    EXPECT_NE(std::find(bundled.begin(), bundled.end(), "harbour"), bundled.end());
    EXPECT_TRUE(std::is_sorted(bundled.begin(), bundled.end()));
    EXPECT_TRUE(game::level_names("/nonexistent/levels").empty());
}

TEST(LevelLoader, BrokenLevelFilesGiveOneClearError) {
    expect_error([] { game::load_level("no_such_level"); },
                 {"no level named 'no_such_level'", "looked for", "no_such_level.json", "The levels in", "harbour"});
    expect_error([] { game::load_level("/nonexistent/dir/x.json"); }, {"/nonexistent/dir/x.json", "not found"});
    auto level = [](const char* name) { return (test_levels() / name).string(); };
    struct Case {
        const char* file;
        std::vector<std::string> words;
    };
    const Case cases[] = {
        {"bad_json.json", {"bad_json.json", "invalid JSON", "line 4"}},
        {"wrong_type.json", {"wrong_type.json: props[0].position: expected an array of 3 numbers"}},
        {"missing_key.json", {"missing_key.json: missing required key 'tank_spot'"}},
        {"out_of_range.json", {"out_of_range.json: world.half_extent_m: 5000 is out of range (0, 2000]"}},
        {"missing_asset.json", {"missing_asset.json: props[1].asset: warehouse.gltf not found (looked in", "missing_asset"}},
        {"garbage_gltf.json", {"garbage_gltf.json: car.asset:", "garbage.gltf", "invalid glTF"}},
        {"accessor_oob.json", {"accessor_oob.json: car.asset:", "accessor_oob.gltf", "POSITION", "outside its bufferView"}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.file);
        expect_error([&] { game::load_level(level(c.file)); }, c.words);
    }
}

// Variations of a valid level, each with one thing wrong; JSON checks come before any
// asset is loaded, so these need no assets.
TEST(LevelLoader, OutOfRangeAndMalformedValues) {
    TempDir tmp("values");
    const json base = json::parse(slurp(harbour_json()));
    expect_each_refused("edits", base, {
        {[](json& j) { j["props"][2]["scale"] = -1; }, {"props[2].scale: -1 is out of range (0, 1000]"}},
        {[](json& j) { j["world"]["half_extent_m"] = 0; }, {"world.half_extent_m: 0 is out of range (0, 2000]"}},
        {[](json& j) { j["rain"]["intensity"] = 1.5; }, {"rain.intensity: 1.5 is out of range [0, 1]"}},
        {[](json& j) { j["sun"]["direction"] = {0.3, -0.5, 0.1}; }, {"sun.direction: must point upwards"}},
        {[](json& j) { j["world"]["seabed_m"] = 2; }, {"world.seabed_m: must be below sea_level_m"}},
        {[](json& j) { j["world"]["hills"][1]["radius_m"] = 0; }, {"world.hills[1].radius_m: 0 is out of range"}},
        {[](json& j) { j["roads"][0]["max_xz"] = {-160, 0}; }, {"roads[0].max_xz: must be greater than min_xz"}},
        {[](json& j) { j["car"]["position"] = {5000, 1, 0}; }, {"car.position[0]: 5000 is out of range [-1000, 1000]"}},
        {[](json& j) { j["boat"]["position"] = {300, 0, 0}; }, {"boat.position: lies outside the world"}},
        {[](json& j) { j["props"][0]["heading_deg"] = "north"; }, {"props[0].heading_deg: expected a number"}},
        {[](json& j) { j["props"][0]["collision"] = "bouncy"; }, {"props[0].collision: 'bouncy' is not one of"}},
        {[](json& j) { j["props"][0]["colision"] = "solid"; }, {"props[0].colision: unknown key"}},
        {[](json& j) { j["props"][1]["asset"] = "../harbour/car.gltf"; }, {"props[1].asset:", "without '..'"}},
        {[](json& j) { j["props"][1]["asset"] = "car.obj"; }, {"props[1].asset: 'car.obj' must be a .gltf or .glb"}},
        {[](json& j) { j["format"] = 2; }, {"format: unsupported format 2"}},
        {[](json& j) { j["seed"] = -4; }, {"seed: expected a non-negative integer"}},
        {[](json& j) { j["id"] = ""; }, {"id: must have 1 to 64 characters"}},
        {[](json& j) { j["props"] = json::array(); j["props"][4096] = j["car"]; }, {"props: 4097 entries, at most 4096"}},
        {[](json& j) { j["world"]["hills"][0]["height_m"] = "high"; }, {"world.hills[0].height_m: expected a number"}},
        {[](json& j) { j["world"].erase("land_height_m"); }, {"world: missing required key 'land_height_m'"}},
        {[](json& j) { j["car"].erase("asset"); }, {"car: missing required key 'asset'"}},
        {[](json& j) { j["props"][3] = 7; }, {"props[3]: expected an object"}},
        {[](json& j) { j.erase("world"); }, {"missing required key 'world'"}},
    });
    // NaN cannot be written in JSON and the parser refuses literals beyond a double, but
    // a double beyond a float is infinite once read.
    std::string text = slurp(harbour_json());
    size_t at = text.find("\"land_height_m\": 1.2");
    ASSERT_NE(at, std::string::npos);
    std::string huge_double = text, huge_float = text;
    huge_double.replace(at, 20, "\"land_height_m\": 1e999");
    huge_float.replace(at, 20, "\"land_height_m\": 1e39");
    spit(tmp.path / "inf1.json", huge_double);
    expect_error([&] { game::load_level((tmp.path / "inf1.json").string()); }, {"inf1.json: invalid JSON", "overflow"});
    spit(tmp.path / "inf2.json", huge_float);
    expect_error([&] { game::load_level((tmp.path / "inf2.json").string()); }, {"world.land_height_m: is not a finite number"});
    // Absurd nesting is refused before anything walks it recursively.
    spit(tmp.path / "deep.json", "{\"format\": " + std::string(200000, '[') + std::string(200000, ']') + "}");
    expect_error([&] { game::load_level((tmp.path / "deep.json").string()); }, {"deep.json: invalid JSON: nested deeper than 64"});
    // Not an object at all, and an oversized file.
    spit(tmp.path / "array.json", "[1, 2, 3]");
    expect_error([&] { game::load_level((tmp.path / "array.json").string()); }, {"array.json: expected an object"});
    spit(tmp.path / "huge.json", std::string(game::kMaxLevelJsonBytes + 1, ' '));
    expect_error([&] { game::load_level((tmp.path / "huge.json").string()); }, {"huge.json: too large"});
}

TEST(LevelLoader, BadDustSectionFieldsAreNamed) {
    expect_each_refused("dust", json::parse(slurp(harbour_json())), {
        {[](json& j) { j["dust"]["preset"] = "snow"; }, {"dust.preset: 'snow' is not one of dust, sand, mould"}},
        {[](json& j) { j["dust"]["sources_per_prop"] = 17; }, {"dust.sources_per_prop: expected a whole number from 1 to 16"}},
        {[](json& j) { j["dust"]["fibre_slices"] = 0; }, {"dust.fibre_slices: expected a whole number from 1 to"}},
        {[](json& j) { j["dust"]["source_elevation_deg"] = 95; }, {"dust.source_elevation_deg: 95 is out of range [0, 90]"}},
        {[](json& j) { j["dust"]["sample_spacing_m"] = "fine"; }, {"dust.sample_spacing_m: expected a number"}},
        {[](json& j) { j["dust"]["fibre_image"] = "../dust_fibres.png"; }, {"dust.fibre_image:", "without '..'"}},
        {[](json& j) { j["dust"].erase("fibre_image"); }, {"dust: missing required key 'fibre_image'"}},
        {[](json& j) { j["dust"]["sources"] = 5; }, {"dust.sources: unknown key"}},
        {[](json& j) { j["props"][1]["dust"] = 3; }, {"props[1].dust: expected true, false or a preset name"}},
        {[](json& j) { j["props"][1]["dust"] = "fur"; }, {"props[1].dust: 'fur' is not one of dust, sand, mould"}},
    });
}


// What the wave grid and the particle fluid refuse is refused at load, naming the key
// (not later, when the world is made, naming only the sim's parameter).
TEST(LevelLoader, WaterAndFluidValuesTheSimRefusesAreNamed) {
    expect_each_refused("sim_ranges", json::parse(slurp(harbour_json())), {
        {[](json& j) { j["water"]["damping_per_s"] = 1; }, {"water.damping_per_s: 1 is out of range [0, 1)"}},
        {[](json& j) { j["water"]["damping_per_s"] = 5; }, {"water.damping_per_s: 5 is out of range [0, 1)"}},
        {[](json& j) { j["fluid"]["particle_radius_m"] = 0.001; },
         {"fluid.particle_radius_m: 0.001 is out of range (0.001, 1]"}},
        {[](json& j) { j["fluid"]["particle_radius_m"] = 0; }, {"fluid.particle_radius_m: 0 is out of range (0.001, 1]"}},
        {[](json& j) { j["fluid"]["tank_size_m"] = {1.6, 0.15, 1.6}; },
         {"fluid.tank_size_m[1]: 0.15 m is less than 4 particle radii (0.16 m)"}},
        {[](json& j) { j["fluid"]["particle_radius_m"] = 0.5; },
         {"fluid.tank_size_m[0]: 1.6 m is less than 4 particle radii (2 m)"}},
    });
}

// At the edges of those ranges the loader and the sim agree: what loads, runs.
TEST(LevelLoader, ValuesAtTheSimsLimitsLoadAndRun) {
    json j = json::parse(slurp(harbour_json()));
    j["rain"]["cell_size_m"] = 0.05;  // sim::kMaxRainCell_m, the bound both use
    j["water"]["damping_per_s"] = 0.99;
    j["fluid"]["particle_radius_m"] = 0.04;
    j["fluid"]["tank_size_m"] = {0.16, 0.16, 0.16};  // exactly 4 radii
    j["fluid"]["particle_count"] = 1;
    game::LoadedLevel level = game::load_level_text(harbour_json(), j.dump(1));
    EXPECT_FLOAT_EQ(level.sim.water.damping_per_s, 0.99f);
    EXPECT_EQ(level.sim.rain.cell_size_m, sim::kMaxRainCell_m);
    EXPECT_NO_THROW(game::GameSession::start(std::move(level), 1));
}

// ---- glTF -> Model -----------------------------------------------------------------------

TEST(GltfModel, GeneratedAssetsHaveTheExpectedShape) {
    effects::Model plinth = game::load_gltf_model(harbour_asset("tank_plinth.gltf"));
    EXPECT_EQ(plinth.name, "tank_plinth");
    ASSERT_EQ(plinth.meshes.size(), 1u);
    EXPECT_EQ(plinth.meshes[0].name, "plinth");
    EXPECT_EQ(plinth.meshes[0].indices.size(), 2u * 12u * 3u);  // two boxes
    EXPECT_NEAR(plinth.bounds_min.x, -1.0f, 1e-6f);
    EXPECT_NEAR(plinth.bounds_min.y, 0.0f, 1e-6f);
    EXPECT_NEAR(plinth.bounds_max.y, 0.3f, 1e-6f);
    EXPECT_NEAR(plinth.bounds_max.z, 1.0f, 1e-6f);

    effects::Model crate = game::load_gltf_model(harbour_asset("crate_large.gltf"));
    ASSERT_EQ(crate.meshes.size(), 1u);
    EXPECT_EQ(crate.meshes[0].indices.size() / 3, 6u * 6u * 2u + 12u * 12u);  // planks + edge battens
    EXPECT_NEAR(crate.bounds_max.x - crate.bounds_min.x, 1.2f + 2 * 0.012f, 1e-5f);
    EXPECT_NEAR(crate.bounds_min.y, 0.0f, 1e-6f);  // resting on its battens

    effects::Model car = game::load_gltf_model(harbour_asset("car.gltf"));
    EXPECT_NEAR(car.bounds_min.y, 0.0f, 1e-5f);  // wheels touch the ground
    EXPECT_NEAR(car.bounds_max.y, 1.45f, 1e-5f);
    EXPECT_NEAR(car.bounds_max.x - car.bounds_min.x, 4.28f, 0.01f);
    EXPECT_NEAR(car.bounds_max.z - car.bounds_min.z, 1.8f, 0.01f);
    const effects::MeshData* ws = find_mesh(car, "windshield");
    ASSERT_NE(ws, nullptr);
    EXPECT_LT(ws->roughness, 0.1f);
    EXPECT_GT(ws->vertices.size(), 4u);  // curved: more than one quad
    const effects::MeshData* body = find_mesh(car, "body");
    ASSERT_NE(body, nullptr);
    EXPECT_NEAR(body->metallic, 0.0f, 1e-6f);  // a dielectric paint reflects the sky untinted
    EXPECT_NEAR(body->roughness, 0.38f, 1e-6f);
    EXPECT_GT(body->vertices[0].color.x, 10.0f * body->vertices[0].color.y);  // red
    // Wheels are placed by node translations, baked into the vertices.
    const effects::MeshData* wheel = find_mesh(car, "wheel_fr");
    ASSERT_NE(wheel, nullptr);
    glm::vec3 lo, hi;
    mesh_bounds(*wheel, lo, hi);
    EXPECT_NEAR((lo.x + hi.x) / 2, 1.35f, 1e-4f);
    EXPECT_NEAR((lo.y + hi.y) / 2, 0.33f, 1e-4f);
    EXPECT_NEAR((lo.z + hi.z) / 2, 0.79f, 1e-4f);

    // Every generated asset loads, and every normal faces away from its triangle's back.
    for (const auto& entry : fs::directory_iterator(game::data_dir() / "levels" / "harbour")) {
        if (entry.path().extension() != ".gltf") continue;  // e.g. the dust's fibre image
        SCOPED_TRACE(entry.path().string());
        effects::Model m = game::load_gltf_model(entry.path());
        for (const effects::MeshData& mesh : m.meshes) {
            ASSERT_EQ(mesh.indices.size() % 3, 0u);
            size_t backwards = 0;
            for (size_t t = 0; t < mesh.indices.size(); t += 3) {
                const auto& a = mesh.vertices[mesh.indices[t]];
                const auto& b = mesh.vertices[mesh.indices[t + 1]];
                const auto& c = mesh.vertices[mesh.indices[t + 2]];
                glm::vec3 g = glm::cross(b.position - a.position, c.position - a.position);
                if (glm::dot(g, a.normal + b.normal + c.normal) < 0.0f) ++backwards;
            }
            EXPECT_EQ(backwards, 0u) << mesh.name;
        }
    }
}

// Builds small glTF files with an embedded buffer.
struct GltfDoc {
    json j = {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", {0}}}}}, {"nodes", json::array()},
              {"meshes", json::array()}, {"accessors", json::array()}, {"bufferViews", json::array()}};
    std::string bin;

    template <class T>
    int view(const std::vector<T>& data) {
        while (bin.size() % 4) bin.push_back('\0');
        j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", data.size() * sizeof(T)}});
        bin.append(reinterpret_cast<const char*>(data.data()), data.size() * sizeof(T));
        return int(j["bufferViews"].size()) - 1;
    }
    template <class T>
    int accessor(const std::vector<T>& data, int component, const char* type, size_t count, bool normalized = false) {
        j["accessors"].push_back({{"bufferView", view(data)}, {"componentType", component}, {"type", type},
                                  {"count", count}, {"normalized", normalized}});
        return int(j["accessors"].size()) - 1;
    }
    // One triangle in the xz plane, counter-clockwise seen from +y.
    int triangle_positions() { return accessor(std::vector<float>{0, 0, 0, 0, 0, 1, 1, 0, 0}, 5126, "VEC3", 3); }

    std::string text() const {
        static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        std::string b64;
        for (size_t i = 0; i < bin.size(); i += 3) {
            uint32_t v = uint32_t(uint8_t(bin[i])) << 16;
            if (i + 1 < bin.size()) v |= uint32_t(uint8_t(bin[i + 1])) << 8;
            if (i + 2 < bin.size()) v |= uint32_t(uint8_t(bin[i + 2]));
            b64 += digits[(v >> 18) & 63];
            b64 += digits[(v >> 12) & 63];
            b64 += i + 1 < bin.size() ? digits[(v >> 6) & 63] : '=';
            b64 += i + 2 < bin.size() ? digits[v & 63] : '=';
        }
        json out = j;
        out["buffers"] = {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + b64}}};
        return out.dump(1);
    }
};

// The same document as a .glb: a JSON chunk and a BIN chunk holding the buffer.
std::string glb(const GltfDoc& d) {
    json j = d.j;
    j["buffers"] = {{{"byteLength", d.bin.size()}}};
    std::string text = j.dump(), bin = d.bin;
    while (text.size() % 4) text.push_back(' ');
    while (bin.size() % 4) bin.push_back('\0');
    auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    return "glTF" + u32(2) + u32(uint32_t(12 + 8 + text.size() + 8 + bin.size())) + u32(uint32_t(text.size())) +
           "JSON" + text + u32(uint32_t(bin.size())) + std::string("BIN\0", 4) + bin;
}

effects::Model load_doc(const TempDir& tmp, const GltfDoc& doc, const char* name = "model.gltf") {
    spit(tmp.path / name, doc.text());
    return game::load_gltf_model(tmp.path / name);
}

TEST(GltfModel, BakesTheNodeHierarchy) {
    TempDir tmp("hierarchy");
    GltfDoc d;
    int pos = d.triangle_positions();
    int nrm = d.accessor(std::vector<float>{0, 1, 0, 0, 1, 0, 0, 1, 0}, 5126, "VEC3", 3);
    d.j["meshes"].push_back({{"name", "tri"}, {"primitives", {{{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}}}}}});
    // Parent: translate (10, 0, 0) and turn 90 degrees about +x (y -> z). Child: matrix
    // scaling x by 2 and translating (0, 0, 1) in the parent's frame.
    float s = std::sqrt(0.5f);
    d.j["nodes"].push_back({{"name", "parent"}, {"translation", {10, 0, 0}}, {"rotation", {s, 0, 0, s}}, {"children", {1}}});
    d.j["nodes"].push_back({{"name", "child"}, {"mesh", 0}, {"matrix", {2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1}}});
    effects::Model m = load_doc(tmp, d);
    ASSERT_EQ(m.meshes.size(), 1u);
    EXPECT_EQ(m.meshes[0].name, "child");
    const auto& v = m.meshes[0].vertices;
    // (1, 0, 0) -> scale (2, 0, 0) -> +z1 (2, 0, 1) -> rotate x90 (2, -1, 0) -> (12, -1, 0).
    EXPECT_NEAR(v[2].position.x, 12.0f, 1e-5f);
    EXPECT_NEAR(v[2].position.y, -1.0f, 1e-5f);
    EXPECT_NEAR(v[2].position.z, 0.0f, 1e-5f);
    // (0, 0, 1) -> (0, 0, 2) -> (0, -2, 0) -> (10, -2, 0).
    EXPECT_NEAR(glm::length(v[1].position - glm::vec3(10, -2, 0)), 0.0f, 1e-5f);
    // The normal +y turns to +z and stays unit length.
    EXPECT_NEAR(glm::length(v[0].normal - glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
    EXPECT_NEAR(m.bounds_max.x, 12.0f, 1e-5f);
    EXPECT_NEAR(m.bounds_min.y, -2.0f, 1e-5f);
    // No material: glTF's default material.
    EXPECT_EQ(v[0].color, glm::vec4(1.0f));
    EXPECT_FLOAT_EQ(m.meshes[0].metallic, 1.0f);
}

TEST(GltfModel, ComputesNormalsAndKeepsMirroredWindingOutward) {
    TempDir tmp("normals");
    GltfDoc d;
    int pos = d.triangle_positions();
    d.j["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", pos}}}}}}});
    d.j["nodes"].push_back({{"mesh", 0}});
    effects::Model m = load_doc(tmp, d);
    for (const auto& v : m.meshes[0].vertices) EXPECT_NEAR(glm::length(v.normal - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    EXPECT_EQ(m.meshes[0].name, "node0");
    EXPECT_EQ(m.meshes[0].indices, (std::vector<uint32_t>{0, 1, 2}));

    // Mirrored upside down (scale y = -1): the surface now faces down, and the winding
    // is flipped so it still agrees with the normal.
    d.j["nodes"][0]["scale"] = {1, -1, 1};
    effects::Model mirrored = load_doc(tmp, d);
    const auto& mv = mirrored.meshes[0];
    EXPECT_EQ(mv.indices, (std::vector<uint32_t>{0, 2, 1}));
    glm::vec3 g = glm::cross(mv.vertices[mv.indices[1]].position - mv.vertices[mv.indices[0]].position,
                             mv.vertices[mv.indices[2]].position - mv.vertices[mv.indices[0]].position);
    EXPECT_GT(glm::dot(g, mv.vertices[0].normal), 0.0f);
    EXPECT_NEAR(glm::length(mv.vertices[0].normal - glm::vec3(0, -1, 0)), 0.0f, 1e-6f);
}

TEST(GltfModel, ReadsBinaryGltf) {
    TempDir tmp("glb");
    GltfDoc d;
    int pos = d.triangle_positions();
    d.j["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", pos}}}}}}});
    d.j["nodes"].push_back({{"name", "tri"}, {"mesh", 0}, {"translation", {0, 2, 0}}});
    spit(tmp.path / "tri.glb", glb(d));
    effects::Model m = game::load_gltf_model(tmp.path / "tri.glb");
    ASSERT_EQ(m.meshes.size(), 1u);
    EXPECT_EQ(m.meshes[0].name, "tri");
    EXPECT_NEAR(m.bounds_min.y, 2.0f, 1e-6f);
    EXPECT_NEAR(m.bounds_max.x, 1.0f, 1e-6f);
    // Cut inside the BIN chunk.
    std::string bytes = glb(d);
    spit(tmp.path / "cut.glb", bytes.substr(0, bytes.size() - 10));
    expect_error([&] { game::load_gltf_model(tmp.path / "cut.glb"); }, {"cut.glb: invalid glTF"});
}

TEST(GltfModel, VertexColoursTimesMaterial) {
    TempDir tmp("colours");
    GltfDoc d;
    int pos = d.triangle_positions();
    int c8 = d.accessor(std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255, 51, 51, 51, 255}, 5121, "VEC4", 3, true);
    int c16 = d.accessor(std::vector<uint16_t>{65535, 65535, 0, 0, 65535, 65535, 0, 0, 0}, 5123, "VEC3", 3, true);
    int cf = d.accessor(std::vector<float>{0.5f, 0.25f, 1, 1, 1, 1, 0, 0, 0}, 5126, "VEC3", 3);
    int i8 = d.accessor(std::vector<uint8_t>{0, 1, 2}, 5121, "SCALAR", 3);
    int i32 = d.accessor(std::vector<uint32_t>{2, 0, 1}, 5125, "SCALAR", 3);
    d.j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 1, 1, 0.5}}, {"metallicFactor", 0.25}, {"roughnessFactor", 0.75}}},
                         {"emissiveFactor", {0.125, 0.25, 0.5}}}};
    json prims = json::array();
    prims.push_back({{"attributes", {{"POSITION", pos}, {"COLOR_0", c8}}}, {"material", 0}, {"indices", i8}});
    prims.push_back({{"attributes", {{"POSITION", pos}, {"COLOR_0", c16}}}, {"indices", i32}});
    prims.push_back({{"attributes", {{"POSITION", pos}, {"COLOR_0", cf}}}, {"material", 0}});
    d.j["meshes"].push_back({{"primitives", prims}});
    d.j["nodes"].push_back({{"name", "painted"}, {"mesh", 0}});
    effects::Model m = load_doc(tmp, d);
    ASSERT_EQ(m.meshes.size(), 3u);  // one MeshData per primitive, all named after the node
    for (const auto& mesh : m.meshes) EXPECT_EQ(mesh.name, "painted");
    EXPECT_NEAR(glm::length(m.meshes[0].vertices[0].color - glm::vec4(0.5f, 0, 0, 0.5f)), 0.0f, 1e-6f);
    EXPECT_NEAR(m.meshes[0].vertices[2].color.y, 0.2f, 1e-6f);  // 51/255, linear as stored
    EXPECT_FLOAT_EQ(m.meshes[0].metallic, 0.25f);
    EXPECT_FLOAT_EQ(m.meshes[0].roughness, 0.75f);
    EXPECT_EQ(m.meshes[0].emissive, glm::vec3(0.125f, 0.25f, 0.5f));
    EXPECT_EQ(m.meshes[1].emissive, glm::vec3(0.0f));  // glTF's default material gives off no light
    EXPECT_NEAR(glm::length(m.meshes[1].vertices[1].color - glm::vec4(0, 1, 1, 1)), 0.0f, 1e-6f);
    EXPECT_EQ(m.meshes[1].indices, (std::vector<uint32_t>{2, 0, 1}));
    EXPECT_NEAR(glm::length(m.meshes[2].vertices[0].color - glm::vec4(0.25f, 0.25f, 1, 0.5f)), 0.0f, 1e-6f);
}

TEST(GltfModel, MalformedFilesAreRefused) {
    TempDir tmp("malformed");
    struct Case {
        std::function<void(GltfDoc&)> edit;
        std::vector<std::string> words;
    };
    auto prim = [](GltfDoc& d) -> json& { return d.j["meshes"][0]["primitives"][0]; };
    const std::vector<Case> cases = {
        {[&](GltfDoc& d) { prim(d)["mode"] = 1; }, {"mode 1 is not supported"}},
        {[&](GltfDoc& d) { prim(d)["indices"] = d.accessor(std::vector<uint16_t>{0, 1, 3, 0}, 5123, "SCALAR", 3); },
         {"indices: index 3", "out of range"}},
        {[&](GltfDoc& d) { prim(d)["indices"] = d.accessor(std::vector<uint16_t>{0, 1}, 5123, "SCALAR", 2); },
         {"not a multiple of 3"}},
        {[&](GltfDoc& d) { d.j["accessors"][0]["count"] = 4; }, {"POSITION", "outside its bufferView"}},
        {[&](GltfDoc& d) { d.j["accessors"][0]["byteOffset"] = 64; }, {"POSITION", "outside its bufferView"}},
        {[&](GltfDoc& d) { d.j["bufferViews"][0]["byteLength"] = 4096; }, {"lies outside its buffer"}},
        {[&](GltfDoc& d) { d.j["bufferViews"][0]["byteOffset"] = 1u << 31; }, {"outside its buffer"}},
        {[&](GltfDoc& d) { d.j["accessors"][0]["type"] = "VEC2"; }, {"POSITION: must be a float VEC3"}},
        {[&](GltfDoc& d) { d.j["accessors"][0]["type"] = "MAT4"; }, {"matrix or unknown accessor types"}},
        {[&](GltfDoc& d) { d.j["accessors"][0]["bufferView"] = 9; }, {"POSITION (accessor 0): has no valid bufferView"}},
        {[&](GltfDoc& d) { prim(d)["attributes"].erase("POSITION"); prim(d)["attributes"]["TEXCOORD_0"] = 0; }, {"has no POSITION"}},
        {[&](GltfDoc& d) { prim(d)["attributes"]["NORMAL"] = d.accessor(std::vector<float>{0, 1, 0}, 5126, "VEC3", 1); },
         {"NORMAL: count differs"}},
        {[&](GltfDoc& d) { prim(d)["attributes"]["COLOR_0"] = d.accessor(std::vector<uint8_t>{1, 2, 3, 4, 5, 6, 7, 8, 9}, 5121, "VEC3", 3); },
         {"COLOR_0: must be VEC3/VEC4 of floats or normalised u8/u16"}},
        {[&](GltfDoc& d) { prim(d)["attributes"]["NORMAL"] = d.accessor(std::vector<float>{0, 1, 0, 0, std::numeric_limits<float>::infinity(), 0, 0, 1, 0}, 5126, "VEC3", 3); },
         {"NORMAL: vertex 1 is not finite"}},
        {[&](GltfDoc& d) { d.j["nodes"][0]["children"] = {0}; }, {"node 0 is reached twice"}},
        {[&](GltfDoc& d) { d.j["scenes"][0]["nodes"] = {5}; }, {"node 5, which does not exist"}},
        {[&](GltfDoc& d) { d.j["nodes"][0]["mesh"] = 3; }, {"node 0 refers to mesh 3, which does not exist"}},
        {[&](GltfDoc& d) { d.j["scenes"][0]["nodes"] = json::array(); }, {"no triangles"}},
        {[&](GltfDoc& d) { d.j["nodes"][0]["translation"] = {1e39, 0, 0}; },
         {"not finite"}},
        {[&](GltfDoc& d) { d.j["nodes"][0]["rotation"] = {0, 0, 0, 0}; }, {"rotation is not a unit quaternion"}},
        {[&](GltfDoc& d) { prim(d)["material"] = 2; }, {"material 2 does not exist"}},
        {[&](GltfDoc& d) { d.j["materials"] = {{{"emissiveFactor", {0.1, -0.5, 0}}}}; prim(d)["material"] = 0; },
         {"emissiveFactor is negative"}},
        {[&](GltfDoc& d) { d.j["asset"]["version"] = nullptr; }, {"invalid glTF"}},
    };
    for (size_t i = 0; i < cases.size(); ++i) {
        SCOPED_TRACE("case " + std::to_string(i));
        GltfDoc d;
        int pos = d.triangle_positions();
        d.j["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", pos}}}}}}});
        d.j["nodes"].push_back({{"mesh", 0}});
        cases[i].edit(d);
        std::string name = "case" + std::to_string(i) + ".gltf";
        spit(tmp.path / name, d.text());
        std::vector<std::string> words = cases[i].words;
        words.push_back(name);
        expect_error([&] { game::load_gltf_model(tmp.path / name); }, words);
    }
    expect_error([&] { game::load_gltf_model(tmp.path / "absent.gltf"); }, {"absent.gltf: not found"});
    // tinygltf walks "extras" recursively: deep nesting must not reach it.
    GltfDoc deep;
    deep.triangle_positions();
    deep.j["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}});
    deep.j["nodes"].push_back({{"mesh", 0}, {"extras", 0}});
    std::string text = deep.text();
    size_t at = text.find("\"extras\": 0");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 11, "\"extras\": " + std::string(100000, '[') + std::string(100000, ']'));
    spit(tmp.path / "deep.gltf", text);
    expect_error([&] { game::load_gltf_model(tmp.path / "deep.gltf"); }, {"deep.gltf: invalid glTF: JSON nested deeper than 64"});
    // The same file with modest nesting loads.
    text.replace(at + 10, 200000, "[[{\"a\": \"]]]]\"}]]");
    spit(tmp.path / "extras.gltf", text);
    EXPECT_EQ(game::load_gltf_model(tmp.path / "extras.gltf").meshes.size(), 1u);
    // A .glb header that promises more than it holds.
    spit(tmp.path / "short.glb", std::string("glTF\x02\0\0\0\xff\xff\0\0", 12));
    expect_error([&] { game::load_gltf_model(tmp.path / "short.glb"); }, {"short.glb: invalid glTF"});
}

// Random damage to a valid file must end in a model or a LevelError, never a crash.
TEST(GltfModel, SurvivesDamagedFiles) {
    TempDir tmp("damage");
    const std::string valid = slurp(harbour_asset("tank_plinth.gltf"));
    uint64_t state = 0x853c49e6748fea9bull;
    auto next = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return uint32_t(state >> 33);
    };
    const char replacements[] = "0123456789-.e,:[]{}\" x";
    int loaded = 0, refused = 0;
    for (int round = 0; round < 400; ++round) {
        std::string bytes = valid;
        if (round % 4 == 0) {
            bytes.resize(next() % bytes.size());  // cut short
        } else {
            for (int k = 0, n = 1 + int(next() % 4); k < n; ++k)
                bytes[next() % bytes.size()] = replacements[next() % (sizeof replacements - 1)];
        }
        fs::path file = tmp.path / "damaged.gltf";
        spit(file, bytes);
        try {
            effects::Model m = game::load_gltf_model(file);
            ++loaded;
            for (const auto& mesh : m.meshes)
                for (uint32_t i : mesh.indices) ASSERT_LT(i, mesh.vertices.size());
        } catch (const game::LevelError& e) {
            ++refused;
            EXPECT_NE(std::string(e.what()).find("damaged.gltf"), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(loaded + refused, 400);
    EXPECT_GT(refused, 100);
}

}  // namespace
