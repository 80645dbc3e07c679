#include "effects/scene/OpenSky.h"

#include <algorithm>

#include "effects/scene/FrameData.h"

namespace effects {

namespace {
constexpr float kSkyLookupLift_m = 0.1f;  // sky_visibility looks this far along the normal
}  // namespace

OpenSky::OpenSky(std::vector<Box> props, glm::vec3 props_min, glm::vec3 props_max, int map_size)
    : props_(std::move(props)),
      framed_(props_max.x > props_min.x && props_max.z > props_min.z && map_size > 0) {
    if (!framed_) return;
    const SkyOcclusionFraming f = sky_occlusion_framing(props_min, props_max);
    centre_x_ = f.centre.x;
    centre_z_ = f.centre.y;
    half_ = f.half;
    reach_m_ = kSkyLookupLift_m + 2.0f * (2.0f * half_ / float(map_size));
    // A clear texel holds the far depth, 1: the test passes where the point's depth, less
    // the shader's 0.002, is at most that (a centimetre spared).
    floor_y_ = f.top - f.depth_range * 1.002f + 0.01f;
}

bool OpenSky::overlaps(const Box& prop, glm::vec3 lo, glm::vec3 hi) const {
    return lo.x - reach_m_ <= prop.second.x && hi.x + reach_m_ >= prop.first.x && lo.z - reach_m_ <= prop.second.z &&
           hi.z + reach_m_ >= prop.first.z;
}

bool OpenSky::open(glm::vec3 lo, glm::vec3 hi) const {
    if (!framed_) return false;
    if (hi.x + reach_m_ < centre_x_ - half_ || lo.x - reach_m_ > centre_x_ + half_ ||
        hi.z + reach_m_ < centre_z_ - half_ || lo.z - reach_m_ > centre_z_ + half_)
        return true;  // off the map: sky_visibility answers 1 there
    for (const Box& prop : props_)
        if (overlaps(prop, lo, hi)) return false;
    return lo.y - kSkyLookupLift_m >= floor_y_;
}

OpenSky OpenSky::near(glm::vec3 lo, glm::vec3 hi) const {
    OpenSky s = *this;
    s.props_.clear();
    for (const Box& prop : props_)
        if (overlaps(prop, lo, hi)) s.props_.push_back(prop);
    return s;
}

}  // namespace effects
