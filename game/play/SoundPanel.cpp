#include "game/play/SoundPanel.h"

#include <imgui.h>

#include "game/play/DebugUi.h"

namespace game {

void draw_sound_panel(LiveSound& sound, Settings::Volumes& volume) {
    // The same window as the debug panel: ImGui appends to it.
    if (ImGui::Begin(kDebugPanelTitle)) {
        ImGui::Separator();
        ImGui::TextUnformatted("sound");
        bool muted = sound.muted();
        if (ImGui::Checkbox("mute (M)", &muted)) sound.toggle_mute();
        ImGui::SliderFloat("master", &volume.master, 0.0f, 1.0f);
        ImGui::SliderFloat("engine", &volume.engine, 0.0f, 1.0f);
        ImGui::SliderFloat("effects", &volume.effects, 0.0f, 1.0f);
        ImGui::SliderFloat("ambience", &volume.ambience, 0.0f, 1.0f);
        ImGui::Text("device ran dry: %d", sound.underruns());
    }
    ImGui::End();
}

}  // namespace game
