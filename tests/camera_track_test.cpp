// The scripted cameras of a replay: which shot holds at a tick, the views a look and an
// orbit give, the player's own camera under a follow shot, and where the camera cuts.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "game/replay/CameraTrack.h"

namespace {

using game::CameraShot;
using game::CameraShotKind;

game::CameraTrack test_track() {
    CameraShot look{.tick = 100, .kind = CameraShotKind::Look, .point = {10.0f, 3.0f, -20.0f},
                    .target = {0.0f, 1.5f, -30.0f}, .fov_deg = 40.0f};
    // A quarter turn a second, starting on the centre's +x side.
    CameraShot orbit{.tick = 200, .kind = CameraShotKind::Orbit, .point = {0.0f, 1.0f, -30.0f},
                     .radius_m = 8.0f, .height_m = 3.0f, .deg_per_s = 90.0f, .start_deg = 0.0f};
    CameraShot follow{.tick = 400};
    return game::CameraTrack({look, orbit, follow}, 60);
}

sim::CameraView player_view() {
    sim::CameraView v;
    v.eye = {1.0f, 2.0f, 3.0f};
    v.target = {4.0f, 5.0f, 6.0f};
    v.fov_y_deg = 70.0f;
    return v;
}

void expect_near(glm::vec3 a, glm::vec3 b) { EXPECT_LT(glm::distance(a, b), 1e-4f) << a.x << " " << a.y << " " << a.z; }

TEST(CameraTrack, EachShotHoldsFromItsTickToTheNext) {
    const game::CameraTrack track = test_track();
    EXPECT_EQ(track.shot_at(0), -1);
    EXPECT_EQ(track.shot_at(99), -1);
    EXPECT_EQ(track.shot_at(100), 0);
    EXPECT_EQ(track.shot_at(199), 0);
    EXPECT_EQ(track.shot_at(200), 1);
    EXPECT_EQ(track.shot_at(400), 2);
    EXPECT_EQ(track.shot_at(1u << 30), 2);
    EXPECT_TRUE(track.cuts_between(99, 100));
    EXPECT_FALSE(track.cuts_between(100, 101));
    EXPECT_TRUE(track.cuts_between(399, 400));
    EXPECT_EQ(game::CameraTrack().shot_at(5), -1);
}

TEST(CameraTrack, TheScriptedViewReplacesThePlayersUntilAFollowShot) {
    const game::CameraTrack track = test_track();
    const sim::CameraView player = player_view();
    EXPECT_EQ(track.view_at(99, player).eye, player.eye);  // before any shot
    const sim::CameraView look = track.view_at(150, player);
    EXPECT_EQ(look.eye, glm::vec3(10.0f, 3.0f, -20.0f));
    EXPECT_EQ(look.target, glm::vec3(0.0f, 1.5f, -30.0f));
    EXPECT_EQ(look.up, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(look.fov_y_deg, 40.0f);
    const sim::CameraView follow = track.view_at(400, player);
    EXPECT_EQ(follow.eye, player.eye);
    EXPECT_EQ(follow.target, player.target);
    EXPECT_EQ(follow.fov_y_deg, 70.0f);
}

TEST(CameraTrack, AnOrbitCirclesItsCentreAnticlockwiseSeenFromAbove) {
    const game::CameraTrack track = test_track();
    const glm::vec3 centre{0.0f, 1.0f, -30.0f};
    // Its first frame, then a quarter and a half turn (60 and 120 ticks at 90 degrees a second).
    expect_near(track.view_at(200, player_view()).eye, centre + glm::vec3(8.0f, 3.0f, 0.0f));
    expect_near(track.view_at(260, player_view()).eye, centre + glm::vec3(0.0f, 3.0f, -8.0f));
    expect_near(track.view_at(320, player_view()).eye, centre + glm::vec3(-8.0f, 3.0f, 0.0f));
    EXPECT_EQ(track.view_at(260, player_view()).target, centre);
    EXPECT_EQ(track.view_at(260, player_view()).fov_y_deg, 60.0f);
}

}  // namespace
