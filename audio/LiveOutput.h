#pragma once
// The live sound: OpenAL Soft's default device, one streaming stereo source with direct
// channels, and a thread of our own that mixes 512-frame blocks and queues them ahead
// of the device. The thread never waits for the game: the game submits each tick's
// changes through the mixer's lock-free queue, and the thread applies what has arrived
// before each block and keeps mixing (Mixer.h).
// Paused, it fades the mixer out and pauses the source; no device, no thread.
#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "audio/Mixer.h"

namespace audio {

class LiveOutput {
public:
    // Opens the default device. Returns nullptr and says why in `why` when there is none.
    static std::unique_ptr<LiveOutput> open(Mixer& mixer, std::string& why);
    ~LiveOutput();
    LiveOutput(const LiveOutput&) = delete;
    LiveOutput& operator=(const LiveOutput&) = delete;

    void set_paused(bool paused) { paused_ = paused; }
    std::string device_name() const { return device_name_; }
    // Blocks the device ran dry before the thread refilled it (a click each).
    int underruns() const { return underruns_; }

private:
    LiveOutput(Mixer& mixer, void* device, void* context);
    void run();

    Mixer& mixer_;
    void* device_;   // ALCdevice
    void* context_;  // ALCcontext
    unsigned source_ = 0;
    unsigned buffers_[12] = {};
    std::string device_name_;
    std::atomic<bool> paused_{false}, stop_{false};
    std::atomic<int> underruns_{0};
    std::thread thread_;
};

}  // namespace audio
