#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace game {

// One layer of an EXR: `channels` floats per pixel, rows top-down.
// Channel names are "<name>.<suffix>" ("<suffix>" for the unnamed layer). Default
// suffixes: unnamed layer R,G,B,A; a named layer with 1 channel Z (e.g. "depth.Z"),
// with 2-3 channels X,Y,Z (e.g. "normal.X"), with 4 R,G,B,A. `channel_names` (one
// per channel) overrides them.
struct ExrLayer {
    std::string name;
    int channels = 0;
    std::vector<float> data;
    std::vector<std::string> channel_names = {};
};

// Writes a multi-layer OpenEXR file: HALF pixels, ZIP compression. Values beyond the
// half range (65504) become infinity. Writes a temporary beside `path` and renames
// it into place; creates the parent directory. Throws std::invalid_argument for bad
// layers and std::runtime_error naming the file for I/O failures.
void write_exr(const std::filesystem::path& path, int width, int height,
               const std::vector<ExrLayer>& layers);

// The full channel names write_exr gives a layer.
std::vector<std::string> exr_channel_names(const ExrLayer& layer);

}  // namespace game
