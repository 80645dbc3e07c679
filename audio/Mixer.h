#pragma once
// Sums the voices into stereo: per voice distance attenuation, equal-power panning,
// a Doppler factor from the smoothed rate at which its distance changes, and a low-pass
// when the listener is in the cabin and the voice outside; then the bus volumes and a
// soft ceiling below full scale. Positions change once a tick (update_placement()); gains
// and pitch are smoothed across each block, so nothing steps at a tick boundary.
//
// Two sides, and neither waits for the other. The mixing side (the live output's thread,
// or the one thread of an offline render) renders and owns every voice: all the methods
// below but submit() are its own. The game side never touches a voice or the mixer; it
// builds a tick's MixChanges and submit()s them through a lock-free single-producer,
// single-consumer queue (moodycamel's ReaderWriterQueue, Debian's
// libreaderwriterqueue-dev), and render() applies whatever has arrived before it mixes.
// A slow frame only means the mix keeps playing what it was last told, smoothly.
#include <array>
#include <memory>
#include <vector>

#include <readerwriterqueue/readerwriterqueue.h>

#include "audio/Dsp.h"
#include "audio/Listener.h"
#include "audio/MixChanges.h"
#include "audio/Voice.h"

namespace audio {

struct Volumes {
    float master = 1.0f, engine = 1.0f, effects = 1.0f, ambience = 1.0f;
};

class Mixer {
public:
    Mixer();
    Mixer(const Mixer&) = delete;
    Mixer& operator=(const Mixer&) = delete;

    // The game side (one thread): hands changes to the mix. Never waits; they are
    // applied, in the order submitted, at the start of the next render().
    void submit(MixChanges changes);
    // The mixing side: applies everything submitted so far (render() does it first; a
    // paused output calls it so that nothing piles up).
    void apply_changes();
    // Changes submitted and not yet applied (a mixing thread may be taking them now).
    size_t pending() const { return inbox_.size_approx(); }

    // A persistent voice, owned by the caller, which keeps it alive while it is added.
    void add(Voice& voice);
    void remove(Voice& voice);
    // A one-shot, dropped when it ends.
    void play(std::unique_ptr<Voice> voice);

    // Once a tick, after the voices' places are set: where they are heard from, and
    // how long a tick is (the Doppler rate is per sim time, never per frame time).
    void update_placement(const Listener& listener, float tick_s);

    // Interleaved stereo, `frames` of it, overwriting `out`, after applying what was submitted.
    void render(float* out, int frames);

    void set_volumes(const Volumes& v) { volumes_ = v; }
    const Volumes& volumes() const { return volumes_; }
    void set_muted(bool muted) { muted_ = muted; }
    bool muted() const { return muted_; }
    // Paused: the master fades to nothing and then every block is silence, the voices
    // standing still where they were.
    void set_paused(bool paused) { paused_ = paused; }
    bool silent() const { return paused_ && master_.value() == 0.0f; }
    // Voices now playing (persistent ones count only while audible).
    int live_voices() const;

private:
    struct Channel {
        Voice* voice = nullptr;
        std::unique_ptr<Voice> owned;  // one-shots
        Smoothed left{0.0f, 0.02f}, right{0.0f, 0.02f}, pitch{1.0f, 0.05f};
        Smoothed muffle{0.0f, 0.08f};  // 0 clear .. 1 through the cabin's walls
        OnePole wall;
        float distance_m = -1.0f;      // last tick's, -1 before the first
        float closing_mps = 0.0f;      // smoothed rate the distance shrinks
        bool placed = false;           // has had one update_placement
    };
    void place_channel(Channel& c, const Listener& l, float tick_s);
    void render_block(float* out, int frames);

    std::vector<Channel> channels_;
    Listener listener_;
    Volumes volumes_;
    bool muted_ = false;
    bool paused_ = false;
    std::array<Smoothed, kBusCount> bus_gain_;
    Smoothed master_{1.0f, 0.02f};
    std::vector<float> scratch_;
    moodycamel::ReaderWriterQueue<MixChanges> inbox_{64};
};

}  // namespace audio
