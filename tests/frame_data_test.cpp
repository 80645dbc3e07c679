// The frame's data (effects/scene/FrameData.h): made once before the passes from the
// world, the camera and the level, and the same for every pass of the frame. All but the
// last test need no GL.
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "HeadlessTest.h"
#include "RenderStage.h"
#include "SimTestLevel.h"
#include "effects/scene/FrameData.h"
#include "effects/scene/SceneLighting.h"
#include "sim/player/CameraRig.h"
#include "sim/weapon/Weapon.h"
#include "sim/weather/Weather.h"

namespace {

const glm::vec3 kSun = glm::normalize(glm::vec3(0.4f, 0.8f, 0.3f));

float luma(glm::vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

bool inside_clip_cube(const glm::mat4& view_proj, glm::vec3 p) {
    const glm::vec4 c = view_proj * glm::vec4(p, 1.0f);
    return std::abs(c.x / c.w) <= 1.0f && std::abs(c.y / c.w) <= 1.0f && std::abs(c.z / c.w) <= 1.0f;
}

effects::Camera looking(glm::vec3 eye, glm::vec3 target) {
    sim::CameraView v;
    v.eye = eye;
    v.target = target;
    return effects::make_camera(v, 16.0f / 9.0f);
}

}  // namespace

TEST(FrameData, TheSkyUnderHeavyRainIsDarkerThanUnderNone) {
    const effects::SkyState clear = effects::sky_under(effects::WeatherLook{}, kSun);
    const effects::SkyState rain = effects::sky_under(effects::weather_look(sim::Weather(1.0f)), kSun);
    EXPECT_EQ(clear.sun_radiance, effects::kClearSunRadiance);
    EXPECT_EQ(clear.overcast, 0.0f);
    EXPECT_EQ(rain.sun_dir, kSun);
    EXPECT_LT(luma(rain.sun_radiance), 0.5f * luma(clear.sun_radiance));
    EXPECT_LT(rain.sky_intensity, clear.sky_intensity);
    EXPECT_GT(rain.overcast, 0.9f);
    // The cabin's daylight follows the sky.
    EXPECT_LT(luma(effects::SceneLighting::cabin_daylight(rain)), luma(effects::SceneLighting::cabin_daylight(clear)));
}

TEST(FrameData, TheShadowMatrixHoldsTheGroundAroundTheCameraInsideTheClipCube) {
    const effects::ShadowFraming framing;
    const float ground = 1.0f;
    const effects::Camera camera = looking({10.0f, 3.0f, 20.0f}, {10.0f, 2.0f, 0.0f});  // looking down -z
    const glm::mat4 m = effects::sun_shadow_view_proj(camera, kSun, ground, 1024, framing);
    // The square's centre is `ahead_m` in front of the eye, within a step; the ground
    // within the half extent less a step of it, and up to 30 m over it, is in the map.
    const glm::vec3 centre(10.0f, ground, 20.0f - framing.ahead_m);
    const float reach = framing.half_extent_m - effects::ShadowFraming::kCentreStep_m;
    for (float dx : {-1.0f, 0.0f, 1.0f})
        for (float dz : {-1.0f, 0.0f, 1.0f})
            for (float h : {0.0f, 30.0f}) {
                const glm::vec3 p = centre + glm::vec3(dx * reach * 0.7f, h, dz * reach * 0.7f);
                EXPECT_TRUE(inside_clip_cube(m, p)) << p.x << " " << p.y << " " << p.z;
            }
    EXPECT_FALSE(inside_clip_cube(m, centre + glm::vec3(2.0f * framing.half_extent_m, 0.0f, 0.0f)));
    // Orthographic along the sun: a point and one towards the sun fall on the same texel,
    // the one towards the sun nearer.
    const glm::vec4 a = m * glm::vec4(centre, 1.0f), b = m * glm::vec4(centre + kSun * 10.0f, 1.0f);
    EXPECT_NEAR(a.x, b.x, 1e-4f);
    EXPECT_NEAR(a.y, b.y, 1e-4f);
    EXPECT_LT(b.z, a.z);
}

TEST(FrameData, TheShadowMatrixFollowsTheCameraInSteps) {
    const effects::ShadowFraming framing;
    const effects::Camera here = looking({10.0f, 3.0f, 20.0f}, {10.0f, 2.0f, 0.0f});
    const effects::Camera nudged = looking({11.0f, 3.5f, 19.0f}, {11.0f, 2.5f, -1.0f});
    const effects::Camera moved = looking({30.0f, 3.0f, 20.0f}, {30.0f, 2.0f, 0.0f});
    const glm::mat4 m = effects::sun_shadow_view_proj(here, kSun, 0.0f, 1024, framing);
    EXPECT_EQ(effects::sun_shadow_view_proj(nudged, kSun, 0.0f, 1024, framing), m);  // within the step
    EXPECT_NE(effects::sun_shadow_view_proj(moved, kSun, 0.0f, 1024, framing), m);
}

TEST(FrameData, TheSkyOcclusionMatrixLooksDownOnEveryProp) {
    const glm::vec3 lo(-40.0f, -1.0f, -60.0f), hi(20.0f, 12.0f, 10.0f);
    const glm::mat4 m = effects::sky_occlusion_view_proj(lo, hi);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
        EXPECT_TRUE(inside_clip_cube(m, p)) << corner;
    }
    // Straight down: higher is nearer, and a point straight above another is on its texel.
    const glm::vec4 low = m * glm::vec4(0.0f, 0.0f, -20.0f, 1.0f), high = m * glm::vec4(0.0f, 10.0f, -20.0f, 1.0f);
    EXPECT_NEAR(low.x, high.x, 1e-5f);
    EXPECT_NEAR(low.y, high.y, 1e-5f);
    EXPECT_LT(high.z, low.z);
    // Without props there is nothing above anything.
    EXPECT_EQ(effects::sky_occlusion_view_proj(glm::vec3(0.0f), glm::vec3(0.0f)), glm::mat4(1.0f));
}

TEST(FrameData, GatherFillsTheWeatherTheSkyTheMatricesAndTheShots) {
    sim::World world(make_test_level());
    sim::Weapon& weapon = world.get<sim::Weapon>();
    weapon.fire({-28.0f, 3.0f, -14.0f}, {1.0f, 0.0f, 0.0f});
    for (int t = 0; t < 12; ++t) world.step({});
    ASSERT_EQ(weapon.shots().size(), 1u);

    const effects::Camera camera = looking({-20.0f, 14.0f, -30.0f}, {-20.0f, 1.0f, -14.0f});
    const glm::mat4 sky_view = effects::sky_occlusion_view_proj({-5, 0, -5}, {5, 5, 5});
    effects::FrameData data;
    data.energy.segments.resize(40);  // left from another frame: replaced, not added to
    effects::gather_frame_data(world,
                               {.camera = camera,
                                .sun_dir = kSun,
                                .shadow_map_size = 512,
                                .shadow_framing = {},
                                .sky_occlusion_view_proj = sky_view},
                               data);
    effects::EnergyView shots;
    effects::gather_energy_view(world, shots);
    EXPECT_FALSE(shots.segments.empty());
    EXPECT_EQ(data.energy.segments.size(), shots.segments.size());
    EXPECT_EQ(data.energy.lights.size(), 1u);
    // The shot as one line light from its tail to its head, as bright as it is strong.
    ASSERT_EQ(data.line_lights.size(), 1u);
    const effects::BeamLighting beam_lighting;
    EXPECT_EQ(data.line_lights[0].start, shots.lights[0].tail);
    EXPECT_EQ(data.line_lights[0].end, shots.lights[0].head);
    EXPECT_EQ(data.line_lights[0].reach_m, beam_lighting.reach_m);
    EXPECT_EQ(data.line_lights[0].intensity, beam_lighting.intensity_per_strength * shots.lights[0].strength);
    EXPECT_EQ(data.weather, effects::weather_look(world));
    EXPECT_EQ(data.sky, effects::sky_under(data.weather, kSun));
    EXPECT_EQ(data.sun_shadow_view_proj,
              effects::sun_shadow_view_proj(camera, kSun, world.level().land_height_m, 512, effects::ShadowFraming{}));
    EXPECT_EQ(data.sky_occlusion_view_proj, sky_view);

    // A caller's weather gives its sky; a caller's sky its sun, and the shadow follows it.
    const effects::WeatherLook rain = effects::weather_look(sim::Weather(1.0f));
    effects::gather_frame_data(world, {.camera = camera, .sun_dir = kSun, .shadow_map_size = 512, .weather = rain},
                               data);
    EXPECT_EQ(data.weather, rain);
    EXPECT_EQ(data.sky, effects::sky_under(rain, kSun));
    effects::SkyState low_sun;
    low_sun.sun_dir = glm::normalize(glm::vec3(1.0f, 0.2f, 0.0f));
    effects::gather_frame_data(world, {.camera = camera, .sun_dir = kSun, .shadow_map_size = 512, .sky = low_sun},
                               data);
    EXPECT_EQ(data.sky, low_sun);
    EXPECT_EQ(data.sun_shadow_view_proj,
              effects::sun_shadow_view_proj(camera, low_sun.sun_dir, world.level().land_height_m, 512, {}));
    // A caller's shots (none here) replace the world's, and their lights go with them.
    effects::gather_frame_data(
        world, {.camera = camera, .sun_dir = kSun, .shadow_map_size = 512, .energy = effects::EnergyView{}}, data);
    EXPECT_TRUE(data.energy.segments.empty());
    EXPECT_TRUE(data.line_lights.empty());
}

TEST(FrameData, NoMoreBeamsLightTheSceneThanTheShadersHold) {
    effects::EnergyView view;
    for (int i = 0; i < int(effects::kMaxLineLights) + 4; ++i)
        view.lights.push_back({glm::vec3(float(i), 1.0f, 0.0f), glm::vec3(float(i), 1.0f, 5.0f), 1.0f});
    std::vector<effects::LineLight> lights(3);  // left from another frame: replaced
    effects::beam_line_lights(view, {.intensity_per_strength = 10.0f, .reach_m = 4.0f}, lights);
    ASSERT_EQ(lights.size(), effects::kMaxLineLights);
    EXPECT_EQ(lights.back().start, view.lights[effects::kMaxLineLights - 1].tail);
    EXPECT_EQ(lights.back().reach_m, 4.0f);
    EXPECT_EQ(lights.back().intensity, 10.0f);
}

class FrameDataRenderTest : public HeadlessTest {};

// Every pass of a frame gets the one FrameData the renderer gathered before them, and a
// frame's request (here the weather) reaches all of them.
TEST_F(FrameDataRenderTest, EveryPassOfTheFrameSeesTheSameData) {
    constexpr int W = 32, H = 24;
    const StagePasses held = kEnvironmentPass | kShadowPass | kSkyOcclusionPass | kOpaquePass | kTonemapPass;
    RenderStage stage("harbour", {.width = W, .height = H, .passes = held});
    const effects::WeatherLook rain = effects::weather_look(sim::Weather(1.0f));
    std::vector<const effects::FrameData*> seen;
    std::vector<effects::SkyState> skies;
    std::vector<glm::mat4> shadows;
    StageFrame frame;
    frame.weather = rain;
    frame.replaced = held;
    frame.replacement = [&](const effects::FrameContext& f) {
        seen.push_back(&f.data);
        skies.push_back(f.data.sky);
        shadows.push_back(f.data.sun_shadow_view_proj);
    };
    stage.draw(stage.camera(stage.world().get<sim::CameraRig>().view()), frame);
    ASSERT_EQ(seen.size(), 5u);
    const effects::FrameData& gathered = stage.renderer().frame_data();
    for (size_t i = 0; i < seen.size(); ++i) {
        EXPECT_EQ(seen[i], &gathered);
        EXPECT_EQ(skies[i], effects::sky_under(rain, stage.sky().sun_dir));
        EXPECT_EQ(shadows[i], gathered.sun_shadow_view_proj);
    }
    // The harbour has props: the sky-occlusion map looks down on them.
    EXPECT_NE(gathered.sky_occlusion_view_proj, glm::mat4(1.0f));
}
