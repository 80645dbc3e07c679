#pragma once
// Where the sky-occlusion map (SkyOcclusionPass: the props drawn from straight above,
// framed by sky_occlusion_view_proj) has nothing above the ground, known without the map:
// there lighting.glsl's sky_visibility answers exactly 1, and the ground can be shaded
// without looking it up (the OPEN_SKY variant), which spares a tenth of the opaque pass.
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

namespace effects {

class OpenSky {
public:
    using Box = std::pair<glm::vec3, glm::vec3>;  // world space, lo and hi

    // `props`: the world boxes of the props the map holds; `props_min`/`props_max` their
    // bounds (which frame the map), `map_size` its texels a side.
    OpenSky(std::vector<Box> props, glm::vec3 props_min, glm::vec3 props_max, int map_size);

    // Whether the lookup answers 1 at every point of the box [lo, hi] (0.1 m off the
    // surface, bilinear, as sky_visibility takes it): every point is off the map, or two
    // texels clear of every prop's footprint and above the map's floor. False without
    // props (no map is framed then).
    bool open(glm::vec3 lo, glm::vec3 hi) const;
    // The same answers within [lo, hi], from only the props that can matter there.
    OpenSky near(glm::vec3 lo, glm::vec3 hi) const;

private:
    bool overlaps(const Box& prop, glm::vec3 lo, glm::vec3 hi) const;

    std::vector<Box> props_;
    bool framed_;
    float centre_x_ = 0.0f, centre_z_ = 0.0f, half_ = 0.0f;
    float reach_m_ = 0.0f;   // how far from a point its lookup can read: the lift and two texels
    float floor_y_ = 0.0f;   // below this a clear texel's depth test fails
};

}  // namespace effects
