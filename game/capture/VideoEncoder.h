#pragma once
// H.264 video with an AAC sound track in an MP4 (or MOV or Matroska) file, encoded as
// the frames and the sound are rendered, through Debian's libavformat, libavcodec (its
// libx264) and libswscale. Written to NAME.partial and renamed to NAME by finish(), so a
// killed export leaves nothing under the final name; opening is the check that the path
// is writable, before anything is rendered.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "game/capture/Image.h"

namespace game {

struct VideoError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct VideoFormat {
    int width = 1280, height = 720;  // even (4:2:0 chroma), kMinVideoSide..kMaxVideoSide
    int fps = 60;
    int crf = 18;         // x264's constant rate factor: 0 lossless .. 51 worst
    int sample_rate = 0;  // the sound track's rate (stereo); 0: no sound track
};

inline constexpr int kMinVideoSide = 16, kMaxVideoSide = 4096;

class VideoEncoder {
public:
    // The container libavformat writes for the file's name (".mp4", ".mov", ".mkv"), or
    // nullptr for any other name.
    static const char* container_for(const std::filesystem::path& path);

    // Throws VideoError saying why the file cannot be written or the encoders opened.
    VideoEncoder(std::filesystem::path path, const VideoFormat& format);
    ~VideoEncoder();  // an unfinished file is removed
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // The next frame, at the format's size (rows top-down, sRGB). Throws VideoError.
    void add_frame(const ImageRGBA8& image);
    // Interleaved stereo at the format's sample rate. Throws VideoError.
    void add_sound(const float* interleaved, int frames);
    // Encodes what is left, completes the file and renames NAME.partial to NAME.
    void finish();

    int64_t frames() const;
    const std::string& video_codec() const;  // "libx264" (or the H.264 encoder found instead)
    const std::filesystem::path& partial_path() const;

private:
    struct State;
    std::unique_ptr<State> s_;
};

}  // namespace game
