#include "audio/MixChanges.h"

#include "audio/Mixer.h"

namespace audio {

void MixChanges::play(std::unique_ptr<Voice> voice) {
    then([v = std::move(voice)](Mixer& m) mutable { m.play(std::move(v)); });
}

void MixChanges::add(Voice& voice) {
    then([v = &voice](Mixer& m) { m.add(*v); });
}

void MixChanges::remove(Voice& voice) {
    then([v = &voice](Mixer& m) { m.remove(*v); });
}

void MixChanges::update_placement(const Listener& listener, float tick_s) {
    then([listener, tick_s](Mixer& m) { m.update_placement(listener, tick_s); });
}

void MixChanges::apply(Mixer& mixer) {
    for (std::unique_ptr<Change>& c : list_) c->apply(mixer);
    list_.clear();
}

}  // namespace audio
