#pragma once
// The harbour heard: reads the world and its tick report once a tick and sets every
// sound model from the state that causes it (docs/AUDIO.md). Persistent voices (engine,
// boat motor, tyres, rain, wind, sea, wipers, shots) are updated in place; events
// (splashes, impacts, thuds, reversals, cues) start one-shots at the tick's first
// sample. Reads the sim, never writes it.
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
    int events = 0;           // one-shots started this tick
};

class Soundscape {
public:
    explicit Soundscape(Mixer& mixer);
    ~Soundscape();
    Soundscape(const Soundscape&) = delete;
    Soundscape& operator=(const Soundscape&) = delete;

    // After each tick (the mixer's mutex held by the caller when a live output runs).
    void after_tick(const sim::World& world, const Listener& listener);
    const SoundState& state() const { return state_; }

private:
    void vehicles(const sim::World& world);
    void weather(const sim::World& world, const Listener& listener);
    void wipers(const sim::World& world);
    void shots(const sim::World& world);
    void events(const sim::World& world);
    uint32_t next_seed() { return ++seeds_ * 2654435761u; }

    Mixer& mixer_;
    Gearbox gearbox_;
    EngineVoice engine_, boat_motor_;
    NoiseBed tyres_, spray_, rain_bed_, wind_, sea_;
    BubbleVoice sea_rain_;
    GlassDropsVoice glass_;
    WipersVoice wipers_;
    std::map<uint64_t, std::unique_ptr<ShotHumVoice>> shot_voices_;
    std::vector<std::pair<int, std::unique_ptr<ShotHumVoice>>> fading_shots_;  // ticks left, voice
    float boat_rpm_ = 1100.0f;
    float boat_pitch_ = 0.0f, boat_pitch_rate_ = 0.0f;
    float blade_angle_ = 0.0f, blade_turning_ = 0.0f;
    bool first_tick_ = true;
    uint64_t last_thud_tick_ = 0;
    uint32_t seeds_ = 0;
    SoundState state_;
};

}  // namespace audio
