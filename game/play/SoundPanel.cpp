#include "game/play/SoundPanel.h"

#include <imgui.h>

#include "game/play/DebugUi.h"

namespace game {

void draw_sound_panel(LiveSound& sound) {
    // The same window as the debug panel: ImGui appends to it.
    if (ImGui::Begin(kDebugPanelTitle)) {
        ImGui::Separator();
        ImGui::TextUnformatted("sound");
        bool muted = sound.muted();
        if (ImGui::Checkbox("mute (M)", &muted)) sound.toggle_mute();
        audio::Volumes v = sound.volumes();
        bool changed = ImGui::SliderFloat("master", &v.master, 0.0f, 1.0f);
        changed |= ImGui::SliderFloat("engine", &v.engine, 0.0f, 1.0f);
        changed |= ImGui::SliderFloat("effects", &v.effects, 0.0f, 1.0f);
        changed |= ImGui::SliderFloat("ambience", &v.ambience, 0.0f, 1.0f);
        if (changed) sound.set_volumes(v);
    }
    ImGui::End();
}

}  // namespace game
