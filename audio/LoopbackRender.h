#pragma once
// The offline sound: the mixer's blocks through OpenAL Soft's loopback device
// (ALC_SOFT_loopback) at 48 kHz, float, stereo, rendered on demand: one tick's samples
// per call, nothing real-time. The settings that change OpenAL's output (resampler,
// CPU extensions, HRTF, limiter, dither) are pinned by a configuration file the program
// names before OpenAL first starts (pin_openal_settings), so two renders of a replay
// on one machine are bit-identical. The spatialisation is ours (Mixer): OpenAL gets a
// stereo stream on direct channels.
#include <filesystem>
#include <memory>
#include <string>

#include "audio/Mixer.h"

namespace audio {

// Points OpenAL Soft at `config` (ALSOFT_CONF); call before anything else opens OpenAL
// in this process. Returns false, saying why, if the file is not there.
bool pin_openal_settings(const std::filesystem::path& config, std::string& why);

class LoopbackRender {
public:
    // Returns nullptr, saying why, when OpenAL has no loopback device.
    static std::unique_ptr<LoopbackRender> open(Mixer& mixer, std::string& why);
    ~LoopbackRender();
    LoopbackRender(const LoopbackRender&) = delete;
    LoopbackRender& operator=(const LoopbackRender&) = delete;

    // Mixes `frames` and renders them through the device into `out` (interleaved stereo).
    void render(float* out, int frames);

private:
    LoopbackRender(Mixer& mixer, void* device, void* context);
    Mixer& mixer_;
    void* device_;
    void* context_;
    unsigned source_ = 0;
    unsigned buffers_[2] = {};
    int next_buffer_ = 0;
    std::unique_ptr<float[]> block_;
    int block_frames_ = 0;
};

}  // namespace audio
