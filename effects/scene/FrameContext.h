#pragma once
#include "effects/Quality.h"
#include "effects/scene/Camera.h"
#include "effects/scene/FrameData.h"
#include "effects/scene/FramePoses.h"
#include "effects/scene/SceneGeometry.h"
#include "effects/scene/SceneLighting.h"
#include "effects/scene/SceneTargets.h"
#include "sim/world/World.h"

namespace effects {

// What the renderer shares between its passes for the life of a level. Set up between
// frames; during one, passes only read it.
struct RenderResources {
    const SceneDesc& desc;
    SceneGeometry geometry;
    QualitySettings quality{};  // the renderer's preset; passes follow it frame by frame
    // The tone map's (TonemapPass, or TemporalPass where it does the tone map itself).
    float exposure = 0.9f;
};

// Where the frame ends up: the window's framebuffer (0) or a capture target.
struct RenderOutput {
    GLuint framebuffer = 0;
    int width = 0, height = 0;
};

// The scene's pixels per output pixel across (below 1 on auto, or a lower preset).
inline float scene_scale(const SceneTargets& targets, const RenderOutput& output) {
    return float(targets.width()) / float(output.width > 0 ? output.width : 1);
}

// One frame: the world to draw (read only), from where, into what. Passes write only
// the lighting's maps and the targets; the pass table declares who writes which.
struct FrameContext {
    const sim::World& world;
    const Camera& camera;
    const RenderResources& resources;
    SceneLighting& lighting;
    SceneTargets& targets;
    RenderOutput output;
    double time_s = 0.0;  // sim time: frames of a replay are the same every run
    FramePoses poses;     // where the moving things are drawn (the camera is made from its view)
    const FrameData& data;  // gathered from the world once for the frame
};

}  // namespace effects
