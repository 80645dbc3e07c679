#include "audio/LiveOutput.h"

#include <chrono>
#include <vector>

#include <AL/al.h>
#include <AL/alc.h>
#include <AL/alext.h>

namespace audio {

namespace {
constexpr int kBlockFrames = 512;  // 10.7 ms
constexpr int kQueued = 12;        // 128 ms ahead of the device: a busy machine may not run the thread for a while
}  // namespace

std::unique_ptr<LiveOutput> LiveOutput::open(Mixer& mixer, std::string& why) {
    ALCdevice* device = alcOpenDevice(nullptr);
    if (!device) {
        why = "no audio device";
        return nullptr;
    }
    const ALCint attrs[] = {ALC_FREQUENCY, kSampleRate, ALC_HRTF_SOFT, ALC_FALSE, 0};
    ALCcontext* context = alcCreateContext(device, attrs);
    if (!context || !alcMakeContextCurrent(context)) {
        if (context) alcDestroyContext(context);
        alcCloseDevice(device);
        why = "the audio device refused a context";
        return nullptr;
    }
    if (!alIsExtensionPresent("AL_EXT_FLOAT32") || !alIsExtensionPresent("AL_SOFT_direct_channels")) {
        alcMakeContextCurrent(nullptr);
        alcDestroyContext(context);
        alcCloseDevice(device);
        why = "OpenAL lacks AL_EXT_FLOAT32 or AL_SOFT_direct_channels";
        return nullptr;
    }
    return std::unique_ptr<LiveOutput>(new LiveOutput(mixer, device, context));
}

LiveOutput::LiveOutput(Mixer& mixer, void* device, void* context) : mixer_(mixer), device_(device), context_(context) {
    if (const ALCchar* name = alcGetString(static_cast<ALCdevice*>(device), ALC_ALL_DEVICES_SPECIFIER)) device_name_ = name;
    alGenSources(1, &source_);
    alGenBuffers(kQueued, buffers_);
    alSourcei(source_, AL_DIRECT_CHANNELS_SOFT, AL_TRUE);  // our mix, as it is: no panning of OpenAL's
    alSourcei(source_, AL_SOURCE_RELATIVE, AL_TRUE);
    std::vector<float> silence(2 * kBlockFrames, 0.0f);
    for (unsigned b : buffers_)
        alBufferData(b, AL_FORMAT_STEREO_FLOAT32, silence.data(), ALsizei(silence.size() * sizeof(float)), kSampleRate);
    alSourceQueueBuffers(source_, kQueued, buffers_);
    alSourcePlay(source_);
    thread_ = std::thread([this] { run(); });
}

LiveOutput::~LiveOutput() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    alSourceStop(source_);
    alSourcei(source_, AL_BUFFER, 0);
    alDeleteSources(1, &source_);
    alDeleteBuffers(kQueued, buffers_);
    alcMakeContextCurrent(nullptr);
    alcDestroyContext(static_cast<ALCcontext*>(context_));
    alcCloseDevice(static_cast<ALCdevice*>(device_));
}

void LiveOutput::run() {
    std::vector<float> block(2 * kBlockFrames);
    bool source_paused = false;
    while (!stop_) {
        const bool pause = paused_;
        mixer_.set_paused(pause);
        // Paused: the mixer fades out over a few blocks, then the source stops. The
        // game's changes are still taken, so that none pile up.
        if (pause && mixer_.silent()) {
            if (!source_paused) alSourcePause(source_);
            source_paused = true;
            mixer_.apply_changes();
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
            continue;
        }
        if (source_paused) {
            alSourcePlay(source_);
            source_paused = false;
        }
        ALint processed = 0;
        alGetSourcei(source_, AL_BUFFERS_PROCESSED, &processed);
        if (processed == 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(3));
            continue;
        }
        while (processed-- > 0) {
            ALuint buffer = 0;
            alSourceUnqueueBuffers(source_, 1, &buffer);
            mixer_.render(block.data(), kBlockFrames);
            alBufferData(buffer, AL_FORMAT_STEREO_FLOAT32, block.data(), ALsizei(block.size() * sizeof(float)), kSampleRate);
            alSourceQueueBuffers(source_, 1, &buffer);
        }
        ALint state = 0;
        alGetSourcei(source_, AL_SOURCE_STATE, &state);
        if (state != AL_PLAYING && !paused_) {
            ++underruns_;
            alSourcePlay(source_);
        }
    }
}

}  // namespace audio
