// The dust effect's CPU parts (seed 004, docs/effects/dust.md): fibre statistics from an
// image, fibre growth, where dust settles (lobe times exposure to the sources), dust
// cleared by thrown objects and shots as sim state, and bad input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "SimTestLevel.h"
#include "effects/dust/DustLook.h"
#include "effects/dust/FibreDirections.h"
#include "effects/dust/FibreTexture.h"
#include "effects/dust/FibreVolume.h"
#include "effects/dust/SkyExposure.h"
#include "game/capture/ImageFiles.h"
#include "game/dust/FibreImage.h"
#include "game/level/LevelLoader.h"
#include "sim/dust/DustAccumulation.h"
#include "sim/dust/DustField.h"
#include "sim/objects/ThrownObjects.h"
#include "sim/weapon/Weapon.h"
#include "sim/world/World.h"

namespace fs = std::filesystem;

namespace {

int direction_index(int dx, int dy, int dlayer) {
    for (int k = 0; k < effects::FibreDirections::kCount; ++k)
        if (effects::FibreDirections::offset(k) == glm::ivec3(dx, dy, dlayer)) return k;
    return -1;
}

// A white image with black pixels where `black(x, y)` says.
template <class F>
game::ImageRGBA8 image_of(int w, int h, F black) {
    game::ImageRGBA8 img{w, h, std::vector<uint8_t>(size_t(w) * size_t(h) * 4, 255)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (black(x, y)) {
                size_t i = (size_t(y) * size_t(w) + size_t(x)) * 4;
                img.pixels[i] = img.pixels[i + 1] = img.pixels[i + 2] = 0;
            }
    return img;
}

// An axis-aligned box as outward-facing triangles (4 vertices per face).
void add_box(sim::DustyPropDesc& d, glm::vec3 lo, glm::vec3 hi) {
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            int u = (axis + 1) % 3, v = (axis + 2) % 3;
            glm::vec3 n(0.0f);
            n[axis] = side ? 1.0f : -1.0f;
            auto base = uint32_t(d.positions.size());
            for (int k = 0; k < 4; ++k) {
                glm::vec3 p;
                p[axis] = side ? hi[axis] : lo[axis];
                p[u] = (k == 1 || k == 2) ? hi[u] : lo[u];
                p[v] = (k >= 2) ? hi[v] : lo[v];
                d.positions.push_back(p);
                d.normals.push_back(n);
            }
            // Wind so the geometric normal agrees with n.
            glm::vec3 g = glm::cross(d.positions[base + 1] - d.positions[base], d.positions[base + 2] - d.positions[base]);
            if (glm::dot(g, n) > 0.0f) d.indices.insert(d.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
            else d.indices.insert(d.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
        }
}

// A two-board shelf: a top board at 2 m and a lower board at 1 m under it, on the
// test level's land (y = 1).
sim::DustDesc two_board_shelf() {
    sim::DustDesc desc;
    desc.enabled = true;
    desc.sample_spacing_m = 0.1f;
    sim::DustyPropDesc shelf;
    shelf.name = "test shelf";
    add_box(shelf, {-1.0f, 2.0f, -25.5f}, {1.0f, 2.05f, -24.5f});
    add_box(shelf, {-1.0f, 1.4f, -25.5f}, {1.0f, 1.45f, -24.5f});
    desc.props.push_back(shelf);
    return desc;
}

sim::LevelDesc dusty_test_level() {
    sim::LevelDesc level = make_test_level();
    level.dust = two_board_shelf();
    return level;
}

}  // namespace

TEST(DustFibres, DirectionTableOfHorizontalLinesIsLeftAndRight) {
    game::ImageRGBA8 img = image_of(32, 32, [](int, int y) { return y % 4 == 0; });
    game::FibreImage fibres = game::binarised_fibres(img, 1, "lines");
    effects::FibreDirections t = game::fibre_directions(fibres, "lines");
    EXPECT_NEAR(t.probability[size_t(direction_index(1, 0, 0))], 0.5f, 1e-6f);
    EXPECT_NEAR(t.probability[size_t(direction_index(-1, 0, 0))], 0.5f, 1e-6f);
    float sum = std::accumulate(t.probability.begin(), t.probability.end(), 0.0f);
    EXPECT_NEAR(sum, 1.0f, 1e-5f);
}

TEST(DustFibres, DirectionTableOfDiagonalsAndOfAColumnThroughSlices) {
    // Diagonals running down-right: only (+1, +1) and (-1, -1).
    effects::FibreDirections diag =
        game::fibre_directions(game::binarised_fibres(image_of(40, 40, [](int x, int y) { return (x - y + 40) % 8 == 0; }), 1, "d"), "d");
    EXPECT_NEAR(diag.probability[size_t(direction_index(1, 1, 0))], 0.5f, 1e-6f);
    EXPECT_NEAR(diag.probability[size_t(direction_index(-1, -1, 0))], 0.5f, 1e-6f);
    // Three 16x16 slices each with one dot at the same place: straight up and down.
    effects::FibreDirections column = game::fibre_directions(
        game::binarised_fibres(image_of(16, 48, [](int x, int y) { return x == 5 && y % 16 == 7; }), 3, "c"), "c");
    EXPECT_NEAR(column.probability[size_t(direction_index(0, 0, 1))], 0.5f, 1e-6f);
    EXPECT_NEAR(column.probability[size_t(direction_index(0, 0, -1))], 0.5f, 1e-6f);
}

TEST(DustFibres, GrowthIsDeterministicForASeedAndFollowsTheTable) {
    effects::FibreDirections lines =
        game::fibre_directions(game::binarised_fibres(image_of(32, 32, [](int, int y) { return y % 4 == 0; }), 1, "l"), "l");
    effects::FibreGrowth g;
    g.size = 64;
    g.fibres = 200;
    effects::FibreVolume a = effects::grow_fibres(lines, g), b = effects::grow_fibres(lines, g);
    EXPECT_EQ(a.texels, b.texels);
    g.seed = 2;
    EXPECT_NE(effects::grow_fibres(lines, g).texels, a.texels);
    // A table of left/right steps grows fibres along rows only: no fibre changes row
    // or layer, so each fibre's texels share one row.
    size_t covered = 0, rows_with_fibre = 0;
    for (int l = 0; l < a.layers; ++l)
        for (int y = 0; y < a.size; ++y) {
            bool any = false;
            for (int x = 0; x < a.size; ++x) any |= a.coverage(x, y, l) != 0, covered += a.coverage(x, y, l) != 0;
            rows_with_fibre += any;
        }
    EXPECT_GT(covered, 200u * 10u);
    EXPECT_LE(rows_with_fibre, 200u);
    // The shipped preset: denser at the bottom layer than at the top one.
    effects::FibreVolume dust = effects::grow_fibres(
        game::fibre_directions(game::binarised_fibres(game::draw_fibre_image(64, 3, 30, 4), 3, "drawn"), "drawn"),
        effects::dust_look(sim::DustKind::Dust).growth);
    auto layer_cover = [&](int l) {
        size_t n = 0;
        for (int y = 0; y < dust.size; ++y)
            for (int x = 0; x < dust.size; ++x) n += dust.coverage(x, y, l) != 0;
        return n;
    };
    EXPECT_GT(layer_cover(0), 2 * layer_cover(dust.layers - 1));
}

TEST(DustFibres, MipLevelsKeepTheCoverage) {
    effects::FibreDirections t =
        game::fibre_directions(game::binarised_fibres(game::draw_fibre_image(64, 3, 30, 4), 3, "drawn"), "drawn");
    effects::FibreVolume v = effects::grow_fibres(t, effects::dust_look(sim::DustKind::Dust).growth);
    auto mips = effects::fibre_mips(v, 0);
    auto fraction = [](const std::vector<uint8_t>& level) {
        size_t over = 0;
        for (size_t i = 0; i < level.size(); i += 2) over += level[i] > uint8_t(effects::kFibreThreshold * 255.0f);
        return double(over) / double(level.size() / 2);
    };
    ASSERT_GE(mips.size(), 4u);
    EXPECT_NEAR(fraction(mips[2]), fraction(mips[0]), 0.05);
    EXPECT_NEAR(fraction(mips[3]), fraction(mips[0]), 0.08);
}

TEST(DustAmounts, OccludedTopGetsLessThanExposedTopAndDownFacesNone) {
    sim::DustField field(two_board_shelf());
    const float top = field.amount_near({0.0f, 2.05f, -25.0f});
    const float under = field.amount_near({0.0f, 1.45f, -25.0f});       // the lower board, under the top one
    const float down = field.amount_near({0.0f, 2.0f, -25.0f});         // the top board's underside
    const float side = field.amount_near({1.0f, 2.025f, -25.0f});       // an end face
    EXPECT_GT(top, 0.8f);
    EXPECT_LT(under, 0.6f * top);
    EXPECT_EQ(down, 0.0f);
    EXPECT_LT(side, 0.05f);
    // Lobe: thick on tops, thin on slopes, none facing down.
    EXPECT_FLOAT_EQ(sim::dust_lobe(sim::DustKind::Dust, {0, 1, 0}), 1.0f);
    float slope = sim::dust_lobe(sim::DustKind::Dust, glm::normalize(glm::vec3(1, 1, 0)));
    EXPECT_GT(slope, 0.2f);
    EXPECT_LT(slope, 0.7f);
    EXPECT_EQ(sim::dust_lobe(sim::DustKind::Dust, {0, -1, 0}), 0.0f);
    EXPECT_EQ(sim::dust_lobe(sim::DustKind::Sand, glm::normalize(glm::vec3(1, 1, 0))), 0.0f);  // beyond repose
    EXPECT_GT(sim::dust_lobe(sim::DustKind::Mould, {1, 0, 0}), 0.0f);                         // mould climbs walls
}

TEST(DustAmounts, SourcesSurroundThePropAndTheSurfaceIsFine) {
    sim::DustField field(two_board_shelf());
    const auto& prop = field.surface().props().at(0);
    ASSERT_EQ(field.sources(0).size(), 5u);
    EXPECT_NEAR(field.sources(0)[0].x, prop.centre().x, 1e-4f);  // one straight above
    for (glm::vec3 s : field.sources(0)) EXPECT_GT(s.y, prop.bounds.max.y);
    // No edge longer than the spacing (allowing the diagonal of a split quad).
    const auto& pos = field.surface().positions();
    const auto& idx = field.surface().indices();
    float longest = 0.0f;
    for (size_t t = 0; t < idx.size(); t += 3)
        for (int k = 0; k < 3; ++k) longest = std::max(longest, glm::length(pos[idx[t + size_t(k)]] - pos[idx[t + size_t((k + 1) % 3)]]));
    EXPECT_LE(longest, 0.1f * 1.001f);
}

TEST(DustClearing, AThrownStoneClearsWhereItPassedAndTheHashShowsIt) {
    sim::World plain(dusty_test_level()), hit(dusty_test_level());
    const glm::vec3 spot{0.3f, 2.05f, -25.0f};
    const float before = hit.get<sim::DustField>().amount_near(spot);
    // A stone rolling across the top board.
    hit.get<sim::ThrownObjects>().launch(sim::ThrownObjects::kHeavy, {-0.8f, 2.3f, -25.0f}, {1, 0, 0}, {-7.0f, -4.0f, 0.0f});
    for (int t = 0; t < 20; ++t) {
        plain.step({});
        hit.step({});
    }
    const sim::DustField& dust = hit.get<sim::DustField>();
    EXPECT_LT(dust.amount_near(spot), 0.5f * before);
    EXPECT_GT(dust.revision(), 0u);
    // Far from its path the dust stays.
    EXPECT_FLOAT_EQ(dust.amount_near({0.3f, 2.05f, -25.45f}), plain.get<sim::DustField>().amount_near({0.3f, 2.05f, -25.45f}));
    EXPECT_NE(hit.hash(), plain.hash());
    const auto names = hit.subsystem_names();
    const size_t i = size_t(std::find(names.begin(), names.end(), "dust") - names.begin());
    ASSERT_LT(i, names.size());
    EXPECT_NE(hit.hash().parts[i], plain.hash().parts[i]);
    // The same again gives the same hash, with any thread count.
    sim::World again(dusty_test_level(), sim::WorldOptions{2});
    again.get<sim::ThrownObjects>().launch(sim::ThrownObjects::kHeavy, {-0.8f, 2.3f, -25.0f}, {1, 0, 0}, {-7.0f, -4.0f, 0.0f});
    for (int t = 0; t < 20; ++t) again.step({});
    EXPECT_EQ(again.hash(), hit.hash());
}

TEST(DustClearing, ClearAlongLowersOnlyNearTheSegment) {
    sim::DustField field(two_board_shelf());
    const float far_before = field.amount_near({-0.9f, 2.05f, -25.0f});
    EXPECT_TRUE(field.clear_along({0.5f, 2.3f, -25.0f}, {0.5f, 2.3f, -25.0f}, 0.5f));
    EXPECT_EQ(field.amount_near({0.5f, 2.05f, -25.0f}), 0.0f);
    EXPECT_EQ(field.amount_near({-0.9f, 2.05f, -25.0f}), far_before);
    EXPECT_FALSE(field.clear_along({0.0f, 10.0f, 0.0f}, {1.0f, 10.0f, 0.0f}, 0.5f));
}

TEST(DustClearing, AShotPassingCloseClearsTheTopAndTheHashShowsIt) {
    sim::World plain(dusty_test_level()), shot(dusty_test_level());
    const glm::vec3 spot{0.0f, 2.05f, -25.0f};
    const float before = shot.get<sim::DustField>().amount_near(spot);
    ASSERT_GT(before, 0.8f);
    // Fired level along the board's length, a quarter metre over its top.
    shot.get<sim::Weapon>().fire({-4.0f, 2.3f, -25.0f}, {1.0f, 0.0f, 0.0f});
    for (int t = 0; t < 30; ++t) {
        plain.step({});
        shot.step({});
    }
    const sim::DustField& dust = shot.get<sim::DustField>();
    EXPECT_LT(dust.amount_near(spot), 0.5f * before);
    EXPECT_EQ(plain.get<sim::DustField>().amount_near(spot), before);  // nothing else moves dust
    EXPECT_GT(dust.revision(), 0u);
    const auto names = shot.subsystem_names();
    const size_t i = size_t(std::find(names.begin(), names.end(), "dust") - names.begin());
    ASSERT_LT(i, names.size());
    EXPECT_NE(shot.hash().parts[i], plain.hash().parts[i]);
}

TEST(DustAmounts, InsideTheHarboursPipeAndBarrelLessThanOnTheirTops) {
    const game::LoadedLevel level = game::load_level("harbour");
    const sim::DustField field(level.sim.dust);
    const sim::DustSurface& s = field.surface();
    for (const char* stem : {"pipe", "barrel"}) {
        SCOPED_TRACE(stem);
        const sim::DustPropRange* prop = nullptr;
        for (const sim::DustPropRange& p : s.props())
            if (p.name.rfind(stem, 0) == 0) prop = &p;
        ASSERT_NE(prop, nullptr);
        // Up-facing vertices: those in the lower half lie inside the hollow (the floor
        // of the barrel, the bottom of the pipe's bore), the others on the outside top.
        double inside = 0.0, top = 0.0;
        int n_inside = 0, n_top = 0;
        for (uint32_t v = prop->first_vertex; v < prop->first_vertex + prop->vertex_count; ++v) {
            if (s.normals()[v].y < 0.95f) continue;
            if (s.positions()[v].y < prop->centre().y) inside += field.amounts()[v], ++n_inside;
            else top += field.amounts()[v], ++n_top;
        }
        ASSERT_GT(n_inside, 5);
        ASSERT_GT(n_top, 5);
        inside /= n_inside;
        top /= n_top;
        std::printf("%s: mean amount %.3f inside (%d vertices), %.3f on top (%d)\n", stem, inside, n_inside, top, n_top);
        EXPECT_GT(top, 0.5);
        EXPECT_LT(inside, 0.6 * top);
    }
}

TEST(DustLight, TheWarehouseRoofHidesTheSkyFromTheDustInside) {
    game::LoadedLevel level = game::load_level("harbour");
    const sim::DustField field(level.sim.dust);
    const sim::DustSurface& s = field.surface();
    auto nearest = [&](glm::vec3 p) {
        size_t best = 0;
        for (size_t v = 0; v < s.positions().size(); ++v)
            if (glm::distance(s.positions()[v], p) < glm::distance(s.positions()[best], p)) best = v;
        return best;
    };
    const size_t crate_top = nearest({-49.1f, 2.43f, -46.3f}), shelf_top = nearest({-40.0f, 2.88f, -49.35f});
    const std::vector<float> roofed = effects::sky_exposure(s, level.scene);
    ASSERT_EQ(roofed.size(), s.positions().size());
    // Without the building the same tops see the open sky.
    std::erase_if(level.scene.props, [&](const effects::PropInstance& p) { return level.scene.models[size_t(p.model)].name == "warehouse"; });
    const std::vector<float> open = effects::sky_exposure(s, level.scene);
    std::printf("sky exposure: crate top %.2f under the roof, %.2f without it; shelf top %.2f, %.2f\n", roofed[crate_top],
                open[crate_top], roofed[shelf_top], open[shelf_top]);
    EXPECT_LT(roofed[crate_top], 0.2f);
    EXPECT_LT(roofed[shelf_top], 0.2f);
    EXPECT_GT(open[crate_top], 0.9f);
    EXPECT_GT(open[shelf_top], 0.9f);
}

TEST(DustBadInput, FibreImagesThatAreNotBinaryEmptyOrUnreadableAreRefused) {
    auto message = [](auto fn) {
        try {
            fn();
        } catch (const game::FibreImageError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    game::ImageRGBA8 grey = image_of(16, 16, [](int x, int) { return x == 3; });
    grey.pixels[4 * 20] = grey.pixels[4 * 20 + 1] = grey.pixels[4 * 20 + 2] = 128;
    EXPECT_NE(message([&] { game::binarised_fibres(grey, 1, "g.png"); }).find("not a binarised image: pixel (4, 1)"), std::string::npos);
    EXPECT_NE(message([&] { game::binarised_fibres(image_of(16, 16, [](int, int) { return false; }), 1, "w.png"); }).find("no black pixels"),
              std::string::npos);
    EXPECT_NE(message([&] { game::binarised_fibres(image_of(16, 16, [](int, int) { return true; }), 1, "b.png"); }).find("no background"),
              std::string::npos);
    EXPECT_NE(message([&] { game::binarised_fibres(image_of(16, 20, [](int x, int) { return x == 2; }), 3, "s.png"); }).find("3 equal slices"),
              std::string::npos);
    // Isolated dots: nothing to learn directions from.
    auto dots = game::binarised_fibres(image_of(16, 16, [](int x, int y) { return x % 4 == 0 && y % 4 == 0; }), 1, "dots.png");
    EXPECT_NE(message([&] { game::fibre_directions(dots, "dots.png"); }).find("no two fibre pixels touch"), std::string::npos);
    // Missing and garbage files.
    const fs::path dir = fs::temp_directory_path() / ("spindrift_dust_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    EXPECT_NE(message([&] { game::read_fibre_image(dir / "missing.png", 1); }).find("missing.png"), std::string::npos);
    std::ofstream(dir / "garbage.png") << "this is not a png";
    EXPECT_NE(message([&] { game::read_fibre_image(dir / "garbage.png", 1); }).find("garbage.png"), std::string::npos);
    fs::remove_all(dir);
}

TEST(DustBadInput, AbsurdParametersAreRefusedNamingThem) {
    auto refused = [](auto edit, const char* name) {
        sim::DustDesc d = two_board_shelf();
        edit(d);
        try {
            sim::DustField f(d);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what()).find(name) != std::string::npos;
        }
        return false;
    };
    EXPECT_TRUE(refused([](sim::DustDesc& d) { d.sources_per_prop = 0; }, "sources_per_prop"));
    EXPECT_TRUE(refused([](sim::DustDesc& d) { d.sample_spacing_m = 0.0f; }, "sample_spacing_m"));
    EXPECT_TRUE(refused([](sim::DustDesc& d) { d.source_distance = NAN; }, "source_distance"));
    EXPECT_TRUE(refused([](sim::DustDesc& d) { d.props[0].indices.push_back(999); d.props[0].indices.push_back(0); d.props[0].indices.push_back(1); }, "test shelf"));
    EXPECT_TRUE(refused([](sim::DustDesc& d) { d.props[0].normals.pop_back(); }, "normals"));
    // A valid table, so only the layer count can be what is refused.
    const effects::FibreDirections lines =
        game::fibre_directions(game::binarised_fibres(image_of(32, 32, [](int, int y) { return y % 4 == 0; }), 1, "l"), "l");
    effects::FibreGrowth g;
    g.layers = 0;
    try {
        effects::grow_fibres(lines, g);
        ADD_FAILURE() << "layers = 0 was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("layers 1..64"), std::string::npos) << e.what();
    }
    g.layers = 10;
    EXPECT_NO_THROW(effects::grow_fibres(lines, g));
}
