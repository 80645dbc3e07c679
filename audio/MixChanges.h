#pragma once
// What the game side tells the mix in one tick, as a list of changes the mixing side
// applies in order at the start of its next block (Mixer::submit, Mixer::render). The
// game thread builds the list without touching any voice; the voices and the mixer are
// only ever touched by whoever renders, so neither side waits for the other.
//
// A change is move-only (it may carry a new voice), which std::function cannot hold:
// hence the small type-erased wrapper below.
#include <memory>
#include <utility>
#include <vector>

#include "audio/Listener.h"
#include "audio/Voice.h"

namespace audio {

class Mixer;

class MixChanges {
public:
    // Any change: `f(Mixer&)`, run on the mixing side. It may touch the voices it names.
    template <class F> void then(F&& f) { list_.push_back(std::make_unique<Fn<std::decay_t<F>>>(std::forward<F>(f))); }
    // The usual ones (Mixer's methods of the same names, applied later).
    void play(std::unique_ptr<Voice> voice);
    void add(Voice& voice);
    void remove(Voice& voice);
    void update_placement(const Listener& listener, float tick_s);

    bool empty() const { return list_.empty(); }
    // In order, then the list is empty.
    void apply(Mixer& mixer);

private:
    struct Change {
        virtual ~Change() = default;
        virtual void apply(Mixer& mixer) = 0;
    };
    template <class F> struct Fn final : Change {
        explicit Fn(F f) : f(std::move(f)) {}
        void apply(Mixer& mixer) override { f(mixer); }
        F f;
    };
    std::vector<std::unique_ptr<Change>> list_;
};

}  // namespace audio
