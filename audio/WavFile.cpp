#include "audio/WavFile.h"

#include <cstring>
#include <system_error>

namespace audio {

namespace {
constexpr int kChannels = 2;
constexpr uint32_t kHeaderBytes = 58;  // RIFF, fmt (18 bytes: float has a cbSize), fact, data

void put32(unsigned char* p, uint32_t v) {
    for (int i = 0; i < 4; ++i) p[i] = (unsigned char)(v >> (8 * i));
}
void put16(unsigned char* p, uint16_t v) {
    p[0] = (unsigned char)v;
    p[1] = (unsigned char)(v >> 8);
}
uint32_t get32(const unsigned char* p) { return p[0] | p[1] << 8 | p[2] << 16 | uint32_t(p[3]) << 24; }
uint16_t get16(const unsigned char* p) { return uint16_t(p[0] | p[1] << 8); }
}  // namespace

WavWriter::WavWriter(std::filesystem::path path, int sample_rate)
    : path_(std::move(path)), partial_(path_.string() + ".partial"), sample_rate_(sample_rate) {
    file_ = std::fopen(partial_.c_str(), "wb");
    if (!file_)
        throw WavError("cannot write " + partial_.string() + ": " + std::generic_category().message(errno));
    write_header();
}

WavWriter::~WavWriter() {
    if (file_) {
        std::fclose(file_);
        std::error_code ec;
        std::filesystem::remove(partial_, ec);
    }
}

void WavWriter::write_header() {
    unsigned char h[kHeaderBytes];
    const uint32_t data = uint32_t(frames_ * kChannels * sizeof(float));
    std::memcpy(h, "RIFF", 4);
    put32(h + 4, kHeaderBytes - 8 + data);
    std::memcpy(h + 8, "WAVEfmt ", 8);
    put32(h + 16, 18);
    put16(h + 20, 3);  // WAVE_FORMAT_IEEE_FLOAT
    put16(h + 22, kChannels);
    put32(h + 24, uint32_t(sample_rate_));
    put32(h + 28, uint32_t(sample_rate_ * kChannels * sizeof(float)));
    put16(h + 32, kChannels * sizeof(float));
    put16(h + 34, 32);
    put16(h + 36, 0);  // no extension
    std::memcpy(h + 38, "fact", 4);
    put32(h + 42, 4);
    put32(h + 46, uint32_t(frames_));
    std::memcpy(h + 50, "data", 4);
    put32(h + 54, data);
    if (std::fseek(file_, 0, SEEK_SET) != 0 || std::fwrite(h, 1, sizeof h, file_) != sizeof h)
        throw WavError("cannot write " + partial_.string());
}

void WavWriter::append(const float* interleaved, int frames) {
    const size_t n = size_t(frames) * kChannels;
    if (std::fwrite(interleaved, sizeof(float), n, file_) != n) throw WavError("cannot write " + partial_.string());
    frames_ += uint64_t(frames);
    if (frames_ * kChannels * sizeof(float) > 0xFFFFFFFFull - 64) throw WavError(path_.string() + ": too long for a WAV file");
}

void WavWriter::finish() {
    write_header();
    if (std::fflush(file_) != 0 || std::fclose(file_) != 0) {
        file_ = nullptr;
        throw WavError("cannot write " + partial_.string());
    }
    file_ = nullptr;
    std::error_code ec;
    std::filesystem::rename(partial_, path_, ec);
    if (ec) throw WavError("cannot rename " + partial_.string() + " to " + path_.string() + ": " + ec.message());
}

std::vector<float> read_wav(const std::filesystem::path& path, int* sample_rate) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw WavError("cannot read " + path.string());
    unsigned char h[kHeaderBytes];
    const bool header = std::fread(h, 1, sizeof h, f) == sizeof h && std::memcmp(h, "RIFF", 4) == 0 &&
                        std::memcmp(h + 8, "WAVEfmt ", 8) == 0 && get16(h + 20) == 3 && get16(h + 22) == kChannels &&
                        std::memcmp(h + 50, "data", 4) == 0;
    if (!header) {
        std::fclose(f);
        throw WavError(path.string() + " is not a float stereo WAV file");
    }
    if (sample_rate) *sample_rate = int(get32(h + 24));
    std::vector<float> samples(get32(h + 54) / sizeof(float));
    const size_t got = std::fread(samples.data(), sizeof(float), samples.size(), f);
    std::fclose(f);
    if (got != samples.size()) throw WavError(path.string() + " is cut short");
    return samples;
}

}  // namespace audio
