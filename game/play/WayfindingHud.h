#pragma once
// Finding the other vehicle: the HUD says when pressing E would switch vehicles, and
// while the other one is out of reach it marks where it is (over it when it is in view,
// else an arrow at the screen's edge towards it) with its distance. Pure geometry from
// the camera and the vehicles' positions; draw_wayfinding puts it on screen with ImGui.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>

#include "sim/player/CameraRig.h"
#include "sim/player/Player.h"

namespace game {

// Whether E would switch now: sim::Player's rule (the car and the boat within
// kSwitchDistance_m of each other, measured flat), named by what the player would take.
enum class SwitchPrompt { None, TakeBoat, TakeCar };

SwitchPrompt switch_prompt(sim::Vehicle aboard, const glm::vec3& car, const glm::vec3& boat);
// "E: take the boat", "E: take the car", or "" for None.
std::string switch_prompt_text(SwitchPrompt prompt);

// Where the marker of the vehicle the player is not in goes, in pixels from the top
// left of a width x height screen.
struct VehicleMarker {
    bool shown = false;      // only while the other vehicle is out of switching reach
    sim::Vehicle vehicle = sim::Vehicle::Boat;  // the one it marks
    float distance_m = 0.0f;                    // flat, from the vehicle the player is in
    bool in_view = false;    // true: drawn over the vehicle; false: at the edge, pointing
    glm::vec2 position{0.0f};  // the arrow's tip
    glm::vec2 direction{0.0f, 1.0f};  // unit, screen pixels (y down): where the arrow points
};

// How far from the screen's edges an edge arrow's tip stays, in pixels.
inline constexpr float kMarkerEdgeMargin_px = 36.0f;
// How far above a vehicle's origin its marker points (over the roof or the cabin).
inline constexpr float kMarkerHeight_m = 2.5f;

// `covered_bottom_px`: a band at the screen's foot that other UI covers (the replay
// viewer's timeline): the marker stays above it, as above the screen's edge.
VehicleMarker vehicle_marker(sim::Vehicle aboard, const glm::vec3& car, const glm::vec3& boat,
                             const sim::CameraView& camera, float width, float height, float covered_bottom_px = 0.0f);

// Draws the prompt and the marker into the current ImGui frame.
void draw_wayfinding(SwitchPrompt prompt, const VehicleMarker& marker);

}  // namespace game
