#pragma once
// The pixels an axis-aligned world box can cover, for passes that scissor their work
// to what they draw. The box is clipped against the near plane first: a box that
// straddles the eye covers its real footprint, and one behind the eye covers nothing.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace effects {

// {x0, y0, x1, y1} in pixels of a width x height viewport, x1/y1 exclusive, grown by
// `margin` and clamped to the viewport; all zero when nothing of the box is in front of
// the near plane or on screen. `near_w` is the clip-space w of the near plane (the
// near distance for a perspective projection).
glm::ivec4 screen_rect_of_box(const glm::mat4& view_proj, float near_w, glm::vec3 lo, glm::vec3 hi, int width,
                              int height, int margin);

}  // namespace effects
