#pragma once
// The frame's named resources, what passes declare they read and write
// (PassDeclaration.h). Frame data is made before the passes run and is read-only to
// them; the rest is made by a pass.
#include <string_view>

namespace effects {

enum class FrameResource {
    // Frame data, made once before the passes (Renderer::render).
    Sky,    // the weather's look, the sky under it, the shadow maps' views (FrameData but the shots)
    Shots,  // the energy shots in flight, gathered from the world once (FrameData::energy)
    LineLights,  // the shots as lights (FrameData::line_lights), in SceneLighting's line-light block
    // Made by passes.
    EnvironmentCube,  // SceneLighting::env_cube
    ShadowMap,        // SceneLighting::shadow_map, drawn from FrameData::sun_shadow_view_proj
    SkyOcclusion,     // SceneLighting::sky_map, drawn from FrameData::sky_occlusion_view_proj
    SceneColour,      // SceneTargets::colour()
    Normals,          // SceneTargets::normal()
    Depth,            // SceneTargets::depth()
    SceneCopy,        // SceneTargets::colour_copy(), depth_copy(); the colour refreshed by passes
    Display,          // the tone-mapped image: SceneTargets::display(), or the output itself at scale 1
    Output,           // RenderOutput
};

// Made before the passes run, so no pass may write it.
constexpr bool is_frame_data(FrameResource r) {
    return r == FrameResource::Sky || r == FrameResource::Shots || r == FrameResource::LineLights;
}

// A copy another pass may refresh (PassDeclaration's Refresh): what it is copied from
// again. Only the scene copy's colour is refreshed.
constexpr bool is_copy(FrameResource r) { return r == FrameResource::SceneCopy; }
constexpr FrameResource copied_from(FrameResource copy) {
    return copy == FrameResource::SceneCopy ? FrameResource::SceneColour : copy;
}

constexpr std::string_view name_of(FrameResource r) {
    switch (r) {
        case FrameResource::Sky: return "sky";
        case FrameResource::Shots: return "shots";
        case FrameResource::LineLights: return "line lights";
        case FrameResource::EnvironmentCube: return "environment cube";
        case FrameResource::ShadowMap: return "shadow map";
        case FrameResource::SkyOcclusion: return "sky occlusion";
        case FrameResource::SceneColour: return "scene colour";
        case FrameResource::Normals: return "normals";
        case FrameResource::Depth: return "depth";
        case FrameResource::SceneCopy: return "scene copy";
        case FrameResource::Display: return "display";
        case FrameResource::Output: return "output";
    }
    return "?";
}

}  // namespace effects
