#include "game/audio/SettingsVolumes.h"

#include <algorithm>

namespace game {

audio::Volumes mixer_volumes(const Settings::Volumes& volume) {
    // The file's reader keeps them in 0..1; a value set in code is held there too.
    const auto unit = [](float v) { return std::clamp(v, 0.0f, 1.0f); };
    return audio::Volumes{.master = unit(volume.master),
                          .engine = unit(volume.engine),
                          .effects = unit(volume.effects),
                          .ambience = unit(volume.ambience)};
}

}  // namespace game
