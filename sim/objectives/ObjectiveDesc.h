#pragma once
// What the level says about the objectives: courses of gates to lap (one for the car on
// the roads, one for the boat on the water) and targets to hit with stones and shots.
// The loader fills it from the level's "courses" and "targets" sections and checks it.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace sim {

enum class CourseVehicle : uint8_t { Car, Boat };

// A gate is a line between two posts, `width_m` apart, across the way through it: a
// vehicle passes it moving along `heading_rad` (0 faces +x, positive turns towards -z,
// as spawn headings), never the other way.
struct GateDesc {
    glm::vec2 centre_xz{0.0f};
    float heading_rad = 0.0f;
    float width_m = 8.0f;
};

// Gate 0 is the start and finish line: crossing it starts a lap, and crossing it again
// after every other gate in order ends that lap and starts the next.
struct CourseDesc {
    std::string name;
    CourseVehicle vehicle = CourseVehicle::Car;
    std::vector<GateDesc> gates;  // at least two
};

// Buoys float on the water and light up when hit; crates stand on land and go over.
enum class TargetKind : uint8_t { Buoy, Crate };

struct TargetDesc {
    TargetKind kind = TargetKind::Crate;
    glm::vec3 position{0.0f};  // the centre of its body
    float radius_m = 0.6f;     // a sphere around `position` is what a stone or a shot must touch
};

struct ObjectivesDesc {
    std::vector<CourseDesc> courses;
    std::vector<TargetDesc> targets;
    bool empty() const { return courses.empty() && targets.empty(); }
};

}  // namespace sim
