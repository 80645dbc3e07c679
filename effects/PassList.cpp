// The frame, in order. An effect adds its row here, after the passes whose output it
// reads; tests/pass_declaration_test.cpp checks the order against the declarations.
#include "effects/PassList.h"

#include <stdexcept>
#include <string>

#include "effects/dust/DustPass.h"
#include "effects/energy/EnergyPass.h"
#include "effects/fluid/FluidPass.h"
#include "effects/rain/RainPass.h"
#include "effects/rain/RainStreakPass.h"
#include "effects/scene/EnvironmentPass.h"
#include "effects/scene/FxaaPass.h"
#include "effects/scene/GhostPass.h"
#include "effects/scene/MirrorPass.h"
#include "effects/scene/OpaquePass.h"
#include "effects/scene/SceneCopyPass.h"
#include "effects/scene/ShadowPass.h"
#include "effects/scene/SkyOcclusionPass.h"
#include "effects/scene/TemporalPass.h"
#include "effects/scene/TonemapPass.h"
#include "effects/scene/UpscalePass.h"
#include "effects/water/WaterPass.h"

namespace effects {

namespace {

template <class P>
std::unique_ptr<Pass> make() {
    return std::make_unique<P>();
}

using enum FrameResource;

}  // namespace

const std::vector<PassEntry>& pass_table() {
    static const std::vector<PassEntry> table{
        {"environment", {.reads = {Sky}, .writes = {EnvironmentCube}}, make<EnvironmentPass>},
        {"shadow", {.reads = {Sky}, .writes = {ShadowMap}}, make<ShadowPass>},
        // Once: the props stay put.
        {"sky occlusion", {.writes = {SkyOcclusion}}, make<SkyOcclusionPass>},
        {"opaque",
         {.reads = {Sky, EnvironmentCube, ShadowMap, SkyOcclusion, LineLights}, .writes = {SceneColour, Normals, Depth}},
         make<OpaquePass>},
        // The view behind, on the mirror's glass: drawn into its own small target.
        {"mirror",
         {.reads = {Sky, ShadowMap, SkyOcclusion, Depth}, .onto = {{SceneColour, "the view behind on the mirror's glass"}}},
         make<MirrorPass>},
        {"dust",
         {.reads = {Sky, EnvironmentCube, ShadowMap, SkyOcclusion, LineLights},
          .onto = {{SceneColour, "shells and fins over the opaque dusty props"},
                   {Normals, "shells and fins over the opaque dusty props"},
                   {Depth, "shells and fins over the opaque dusty props"}}},
         make<DustPass>},
        {"scene_copy", {.reads = {SceneColour, Depth}, .writes = {SceneCopy}}, make<SceneCopyPass>},
        {"water",
         {.reads = {Sky, EnvironmentCube, ShadowMap, SkyOcclusion, LineLights, SceneCopy},
          .onto = {{Depth, "the sea's surface and splash sheets over what lies below"},
                   {Normals, "the splash sheets over what lies below, not the sea (its normals stay in its shading)"},
                   {SceneColour, "water pixels shaded, spray blended"}}},
         make<WaterPass>},
        {"fluid",
         {.reads = {Sky, Depth, SceneCopy},
          .onto = {{SceneColour, "the tank's liquid inside its screen rectangle"}},
          .refreshes = {{SceneCopy, "around the tank's rectangle: the water behind it, for the rays through the liquid"}}},
         make<FluidPass>},
        // A replay's vehicle raced beside the player's (play --ghost): over the water, under the glow.
        {"ghost",
         {.reads = {Sky, Depth},
          .onto = {{Depth, "the ghost's nearest surface"}, {SceneColour, "the ghost blended, see-through"}}},
         make<GhostPass>},
        // Additive; stops at the water's depth too.
        {"energy", {.reads = {Shots, Depth}, .onto = {{SceneColour, "glow and bloom added"}}}, make<EnergyPass>},
        // Under the windshield.
        {"rain_streaks", {.reads = {Sky, Depth}, .onto = {{SceneColour, "streaks blended"}}}, make<RainStreakPass>},
        // Refracts everything before it.
        {"rain",
         {.reads = {Sky, Depth, SceneCopy},
          .onto = {{SceneColour, "the windshield blended over what it refracts"}},
          .refreshes = {{SceneCopy, "whole, with mips: everything before the windshield, out of focus in the drops"}}},
         make<RainPass>},
        {"tonemap", {.reads = {SceneColour}, .writes = {Display}}, make<TonemapPass>},
        // At the scene's size: before the upscale, fewer pixels.
        {"fxaa", {.onto = {{Display, "anti-aliased when anti-aliasing is on"}}}, make<FxaaPass>},
        // At the scene's size, over the last frames (auto): the edges' coverage before the
        // upscale. Without FXAA it tone maps the scene colour itself (the tone map draws nothing).
        {"temporal",
         {.reads = {SceneColour, Depth}, .onto = {{Display, "resolved with the last frames when temporal upsampling is on"}}},
         make<TemporalPass>},
        // To the output's size (nothing at scale 1, where the display is the output); the HUD goes on after.
        {"upscale", {.reads = {Display}, .writes = {Output}}, make<UpscalePass>},
    };
    return table;
}

std::vector<DeclaredPass> declared_passes() {
    std::vector<DeclaredPass> out;
    for (const PassEntry& e : pass_table()) out.push_back({e.name, e.declaration});
    return out;
}

size_t pass_index(std::string_view name) {
    const auto& table = pass_table();
    for (size_t i = 0; i < table.size(); ++i)
        if (table[i].name == name) return i;
    throw std::invalid_argument("no pass is named \"" + std::string(name) + "\"");
}

PassSet PassSet::of(std::initializer_list<std::string_view> names) {
    uint64_t bits = 0;
    for (std::string_view name : names) bits |= uint64_t(1) << pass_index(name);
    return PassSet(bits);
}

PassSet PassSet::all() {
    if (pass_table().size() >= 64) throw std::logic_error("a PassSet holds at most 63 passes");
    return PassSet((uint64_t(1) << pass_table().size()) - 1);
}

std::vector<std::unique_ptr<Pass>> make_pass_list() { return make_passes(PassSet::all()); }

std::vector<std::unique_ptr<Pass>> make_passes(PassSet set) {
    std::vector<std::unique_ptr<Pass>> passes;
    const auto& table = pass_table();
    for (size_t i = 0; i < table.size(); ++i) {
        if (!set.contains(i)) continue;
        const PassEntry& e = table[i];
        passes.push_back(e.make());
        // The table's name is what stages pick by: it must be the pass's own.
        if (passes.back()->name() != e.name)
            throw std::logic_error("the pass table names \"" + std::string(e.name) + "\" a pass named \"" +
                                   std::string(passes.back()->name()) + "\"");
    }
    return passes;
}

}  // namespace effects
