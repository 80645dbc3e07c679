#pragma once
// The harbour heard: reads the world and its tick report once a tick and sets every
// sound model from the state that causes it (docs/AUDIO.md). Persistent voices (engine,
// boat motor, tyres, rain, wind, sea, wipers, shots) are updated in place; events
// (splashes, impacts, thuds, reversals, cues) start one-shots at the tick's first
// sample. Reads the sim, never writes it.
//
// It runs on the game thread and touches no voice there: everything it sets becomes a
// change to the mix (MixChanges), submitted once at the end of the tick, which the
// mixing side applies before its next block (Mixer.h).
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "audio/Listener.h"
#include "audio/Mixer.h"
#include "audio/models/Bubbles.h"
#include "audio/models/Engine.h"
#include "audio/models/GlassDrops.h"
#include "audio/models/NoiseBed.h"
#include "audio/models/ShotHum.h"
#include "audio/models/Strike.h"
#include "audio/models/Wipers.h"

namespace sim {
class World;
struct CameraView;
}  // namespace sim

namespace audio {

// The listener for a presented camera: in the cabin when the player sits in the car's
// driver's view and the presented camera is that view (a replay's scripted shot
// elsewhere is outside).
Listener listener_for(const sim::World& world, const sim::CameraView& presented);

// What one tick set, for tests and the bench: what the sound models were told.
struct SoundState {
    float engine_rpm = 0.0f;
    int gear = 1;
    float rain_bed = 0.0f;    // the rain bed's level 0..1
    float glass_wetness = 0.0f;  // what the wipers hear of the water on the glass, 0..1
    float squeak = 0.0f;      // the wipers' squeak, 0..1
    float pushed_mg = 0.0f;   // the water the blades push
    int hull_slaps = 0;       // hull points the water slapped this tick
    float hull_rising = 0.0f; // the fastest the water rose against the hull this tick, m/s
    float slap_energy = 0.0f; // their summed strength squared
    int events = 0;           // one-shots started this tick
};

class Soundscape {
public:
    explicit Soundscape(Mixer& mixer);
    // Only once nothing renders the mixer any more (a live output stopped first): it
    // takes its voices out of the mix directly.
    ~Soundscape();
    Soundscape(const Soundscape&) = delete;
    Soundscape& operator=(const Soundscape&) = delete;

    // After each tick, on the game thread: submits the tick's changes to the mix.
    void after_tick(const sim::World& world, const Listener& listener);
    const SoundState& state() const { return state_; }

private:
    void vehicles(const sim::World& world);
    void weather(const sim::World& world, const Listener& listener);
    void wipers(const sim::World& world);
    void shots(const sim::World& world);
    void events(const sim::World& world);
    void tank(const sim::World& world);
    void hull(const sim::World& world);
    uint32_t next_seed() { return ++seeds_ * 2654435761u; }
    // `f(voice)` on the mixing side, in order with the tick's other changes.
    template <class V, class F> void tell(V& voice, F f) {
        changes_.then([v = &voice, f = std::move(f)](Mixer&) mutable { f(*v); });
    }
    void strike(const StrikeSound& sound, const Placement& place);

    Mixer& mixer_;
    Gearbox gearbox_;
    EngineVoice engine_, boat_motor_;
    NoiseBed tyres_, spray_, rain_bed_, wind_, sea_, slosh_;
    BubbleVoice sea_rain_;
    GlassDropsVoice glass_;
    WipersVoice wipers_;
    // The shots' hums, keyed by shot: owned by the mixer (played as one-shots that end
    // once released), so a shot gone is told to fade and then forgotten here.
    std::map<uint64_t, ShotHumVoice*> shot_voices_;
    MixChanges changes_;  // this tick's
    float boat_rpm_ = 1100.0f;
    float blade_water_mg_ = 0.0f;  // the water the blades meet, over about a sweep
    // Per hull point: the water's height over it last tick and how fast it rose, and the
    // ticks until it may slap again.
    std::array<float, 4> immersion_{}, rising_{};
    std::array<int, 4> slap_rest_{};
    float blade_angle_ = 0.0f, blade_turning_ = 0.0f;
    int tank_objects_ = 0;
    bool first_tick_ = true;
    uint64_t last_thud_tick_ = 0;
    uint32_t seeds_ = 0;
    SoundState state_;
};

}  // namespace audio
