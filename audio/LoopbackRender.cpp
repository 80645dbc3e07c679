#include "audio/LoopbackRender.h"

#include <cstdlib>

#define AL_ALEXT_PROTOTYPES
#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>

namespace audio {

bool pin_openal_settings(const std::filesystem::path& config, std::string& why) {
    if (!std::filesystem::is_regular_file(config)) {
        why = "OpenAL settings file " + config.string() + " is missing";
        return false;
    }
    setenv("ALSOFT_CONF", config.c_str(), 1);
    return true;
}

std::unique_ptr<LoopbackRender> LoopbackRender::open(Mixer& mixer, std::string& why) {
    if (!alcIsExtensionPresent(nullptr, "ALC_SOFT_loopback")) {
        why = "OpenAL has no ALC_SOFT_loopback";
        return nullptr;
    }
    ALCdevice* device = alcLoopbackOpenDeviceSOFT(nullptr);
    if (!device) {
        why = "OpenAL could not open a loopback device";
        return nullptr;
    }
    if (!alcIsRenderFormatSupportedSOFT(device, kSampleRate, ALC_STEREO_SOFT, ALC_FLOAT_SOFT)) {
        alcCloseDevice(device);
        why = "OpenAL's loopback device cannot render 48 kHz float stereo";
        return nullptr;
    }
    const ALCint attrs[] = {ALC_FORMAT_CHANNELS_SOFT, ALC_STEREO_SOFT, ALC_FORMAT_TYPE_SOFT, ALC_FLOAT_SOFT,
                            ALC_FREQUENCY, kSampleRate, ALC_HRTF_SOFT, ALC_FALSE,
                            ALC_OUTPUT_LIMITER_SOFT, ALC_FALSE, 0};
    ALCcontext* context = alcCreateContext(device, attrs);
    if (!context || !alcMakeContextCurrent(context)) {
        if (context) alcDestroyContext(context);
        alcCloseDevice(device);
        why = "OpenAL's loopback device refused a context";
        return nullptr;
    }
    return std::unique_ptr<LoopbackRender>(new LoopbackRender(mixer, device, context));
}

LoopbackRender::LoopbackRender(Mixer& mixer, void* device, void* context)
    : mixer_(mixer), device_(device), context_(context) {
    alGenSources(1, &source_);
    alGenBuffers(2, buffers_);
    alSourcei(source_, AL_DIRECT_CHANNELS_SOFT, AL_TRUE);
    alSourcei(source_, AL_SOURCE_RELATIVE, AL_TRUE);
    alSourcei(source_, AL_SOURCE_RESAMPLER_SOFT, 0);  // point: the stream is at the device's rate anyway
}

LoopbackRender::~LoopbackRender() {
    alSourceStop(source_);
    alSourcei(source_, AL_BUFFER, 0);
    alDeleteSources(1, &source_);
    alDeleteBuffers(2, buffers_);
    alcMakeContextCurrent(nullptr);
    alcDestroyContext(static_cast<ALCcontext*>(context_));
    alcCloseDevice(static_cast<ALCdevice*>(device_));
}

void LoopbackRender::render(float* out, int frames) {
    if (frames > block_frames_) {
        block_.reset(new float[size_t(2 * frames)]);
        block_frames_ = frames;
    }
    mixer_.render(block_.get(), frames);
    const ALuint buffer = buffers_[next_buffer_];
    next_buffer_ ^= 1;
    alBufferData(buffer, AL_FORMAT_STEREO_FLOAT32, block_.get(), ALsizei(2 * frames * sizeof(float)), kSampleRate);
    alSourceQueueBuffers(source_, 1, &buffer);
    ALint state = 0;
    alGetSourcei(source_, AL_SOURCE_STATE, &state);
    if (state != AL_PLAYING) alSourcePlay(source_);
    alcRenderSamplesSOFT(static_cast<ALCdevice*>(device_), out, frames);
    ALint processed = 0;
    alGetSourcei(source_, AL_BUFFERS_PROCESSED, &processed);
    while (processed-- > 0) {
        ALuint done = 0;
        alSourceUnqueueBuffers(source_, 1, &done);
    }
}

}  // namespace audio
