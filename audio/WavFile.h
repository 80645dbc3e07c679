#pragma once
// A 32-bit float stereo WAV written as it is rendered: to NAME.partial, renamed to NAME
// by finish(), so a killed render leaves nothing under the final name. Opening is the
// check that the path is writable, before anything is rendered.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace audio {

struct WavError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class WavWriter {
public:
    // Throws WavError naming the path when it cannot be created.
    WavWriter(std::filesystem::path path, int sample_rate);
    ~WavWriter();  // an unfinished file is removed
    WavWriter(const WavWriter&) = delete;
    WavWriter& operator=(const WavWriter&) = delete;

    void append(const float* interleaved, int frames);
    // Completes the header and renames NAME.partial to NAME. Throws WavError.
    void finish();
    uint64_t frames() const { return frames_; }
    const std::filesystem::path& partial_path() const { return partial_; }

private:
    void write_header();
    std::filesystem::path path_, partial_;
    std::FILE* file_ = nullptr;
    int sample_rate_;
    uint64_t frames_ = 0;
};

// Reads a file WavWriter wrote (float stereo): interleaved samples. Throws WavError.
std::vector<float> read_wav(const std::filesystem::path& path, int* sample_rate = nullptr);

}  // namespace audio
