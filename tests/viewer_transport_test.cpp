// The replay viewer's playback (game/replay/ViewerTransport.h) and cameras
// (game/play/ViewerCamera.h) on replays/harbour_goals, frame by frame without a window.
#include <string>

#include <gtest/gtest.h>

#include "game/level/LevelLoader.h"
#include "game/play/ViewerCamera.h"
#include "game/replay/KeyframeStore.h"
#include "game/replay/ReplayMarkers.h"
#include "game/replay/ReplayReader.h"
#include "game/replay/ReplaySeeker.h"
#include "game/replay/ViewerTransport.h"
#include "game/session/GameSession.h"

namespace {

struct Viewer {
    game::Replay replay = game::read_replay(std::string(SPINDRIFT_TEST_DATA) + "/../../replays/harbour_goals.replay",
                                            game::ReadOptions{true});
    game::GameSession session = game::GameSession::start(game::load_level("harbour", nullptr), 1, replay.header.seed);
    game::KeyframeStore keyframes{session.level.content_hash};
    game::ReplaySeeker seeker{replay.inputs, *session.world, keyframes};
    game::ReplayMarkers markers;
    game::ViewerTransport transport{seeker, markers};

    uint64_t tick() const { return session.world->tick(); }
    bool on_recording() const { return tick() == 0 || session.world->hash().world == replay.tick_world_hashes[tick() - 1]; }
};

constexpr double kFrame = 1.0 / 60.0;

}  // namespace

TEST(ViewerTransport, PlaysAtItsSpeed) {
    Viewer v;
    for (int f = 0; f < 60; ++f) v.transport.advance(kFrame);
    EXPECT_NEAR(double(v.tick()), 60.0, 1.0) << "1x: a tick a frame at 60 frames a second";
    for (int i = 0; i < 3; ++i) v.transport.slower();
    EXPECT_DOUBLE_EQ(v.transport.speed(), 0.1);
    const uint64_t at = v.tick();
    for (int f = 0; f < 100; ++f) v.transport.advance(kFrame);
    EXPECT_NEAR(double(v.tick() - at), 10.0, 1.0) << "0.1x: a tick every ten frames";
    for (int i = 0; i < 10; ++i) v.transport.faster();
    EXPECT_DOUBLE_EQ(v.transport.speed(), 8.0);
    EXPECT_EQ(v.transport.advance(kFrame), 8);
    EXPECT_TRUE(v.on_recording());
}

TEST(ViewerTransport, StepsPausesAndStopsAtTheEnd) {
    Viewer v;
    v.transport.seek_to(600);
    EXPECT_TRUE(v.transport.paused());
    EXPECT_EQ(v.transport.advance(1.0), 0) << "paused";
    v.transport.step_back();
    EXPECT_EQ(v.tick(), 599u);
    EXPECT_TRUE(v.on_recording());
    v.transport.step_forward();
    v.transport.step_forward();
    EXPECT_EQ(v.tick(), 601u);
    v.transport.jump_seconds(-5.0);
    EXPECT_EQ(v.tick(), 301u);
    EXPECT_TRUE(v.on_recording());
    v.transport.jump_seconds(1000.0);
    EXPECT_EQ(v.tick(), v.seeker.ticks()) << "clamped to the end";
    v.transport.toggle_pause();
    EXPECT_EQ(v.tick(), 0u) << "playing again from the end starts over";
    EXPECT_FALSE(v.transport.paused());
}

TEST(ViewerTransport, JumpsBetweenMarkers) {
    Viewer v;
    // The markers come from watching the replay once, as the viewer does at start.
    game::ReplayMarkers& markers = v.markers;
    while (v.seeker.step()) markers.after_tick(*v.session.world);
    v.transport.seek_to(0);
    v.transport.next_marker();
    ASSERT_FALSE(markers.markers().empty());
    EXPECT_EQ(v.tick(), markers.markers().front().tick);
    v.transport.seek_to(1000);
    v.transport.previous_marker();
    EXPECT_EQ(v.tick(), markers.previous_before(1000)->tick);
    EXPECT_TRUE(v.on_recording());
}

TEST(ViewerCamera, EachModeLooksWhereItShould) {
    game::ViewerCamera cam;
    sim::CameraView recorded;
    recorded.eye = {0.0f, 5.0f, 10.0f};
    recorded.target = {0.0f, 0.0f, 0.0f};
    sim::Pose boat;
    boat.position = {20.0f, 0.0f, 30.0f};
    EXPECT_EQ(cam.view(recorded, boat, false).eye, recorded.eye);
    cam.set_mode(game::ViewerCameraMode::Orbit, recorded, boat.position);
    sim::CameraView orbit = cam.view(recorded, boat, false);
    EXPECT_EQ(orbit.target, boat.position + glm::vec3(0.0f, 1.0f, 0.0f)) << "round the vehicle";
    cam.control({.zoom_steps = 5.0f}, kFrame);
    const glm::vec3 a = orbit.eye - orbit.target, b = cam.view(recorded, boat, false).eye - orbit.target;
    EXPECT_LT(glm::dot(b, b), glm::dot(a, a)) << "zoomed in";
    cam.set_mode(game::ViewerCameraMode::FreeFly, recorded, boat.position);
    EXPECT_NEAR(cam.view(recorded, boat, false).eye.y, 5.0f, 1e-5f) << "starts where the camera was";
    cam.control({.move = {0.0f, 0.0f, 1.0f}}, 1.0f);
    const sim::CameraView flown = cam.view(recorded, boat, false);
    EXPECT_LT(flown.eye.z, 10.0f) << "forwards is towards what it looked at";
    EXPECT_LT(flown.eye.y, 5.0f);
    cam.set_mode(game::ViewerCameraMode::Chase, recorded, boat.position);
    EXPECT_LT(cam.view(recorded, boat, false).eye.x, boat.position.x) << "behind a boat facing +x";
    cam.next_mode(recorded, boat.position);
    EXPECT_EQ(cam.mode(), game::ViewerCameraMode::Driver);
}

TEST(ViewerCamera, AnOrbitFromAboardStartsBehindTheVehicle) {
    game::ViewerCamera cam;
    sim::Pose boat;
    boat.position = {20.0f, 0.0f, 30.0f};
    sim::CameraView aboard;  // the driver's view, looking along +x
    aboard.eye = boat.position + glm::vec3(0.0f, 1.5f, 0.0f);
    aboard.target = aboard.eye + glm::vec3(1.0f, 0.0f, 0.0f);
    cam.set_mode(game::ViewerCameraMode::Orbit, aboard, boat.position);
    const sim::CameraView orbit = cam.view(aboard, boat, false);
    EXPECT_LT(orbit.eye.x, boat.position.x - 5.0f) << "behind, along the view";
    EXPECT_GT(orbit.eye.y, boat.position.y + 1.0f);
    EXPECT_LT(orbit.eye.y - boat.position.y, orbit.target.x - orbit.eye.x) << "not looking straight down";
}
