#include "game/capture/ExrWriter.h"
#include "game/capture/CaptureError.h"

#include "game/capture/ImageFiles.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <Imath/half.h>

#include <set>
#include <stdexcept>

namespace game {
namespace {

std::string layer_title(const ExrLayer& layer) {
    return layer.name.empty() ? "the unnamed layer" : "layer '" + layer.name + "'";
}

}  // namespace

std::vector<std::string> exr_channel_names(const ExrLayer& layer) {
    std::vector<std::string> suffixes = layer.channel_names;
    if (suffixes.empty()) {
        static const char* const colour[] = {"R", "G", "B", "A"};
        static const char* const axes[] = {"X", "Y", "Z"};
        for (int c = 0; c < layer.channels && c < 4; ++c) {
            if (layer.name.empty() || layer.channels == 4)
                suffixes.emplace_back(colour[c]);
            else if (layer.channels == 1)
                suffixes.emplace_back("Z");
            else
                suffixes.emplace_back(axes[c]);
        }
    }
    std::vector<std::string> names;
    for (const std::string& suffix : suffixes)
        names.push_back(layer.name.empty() ? suffix : layer.name + "." + suffix);
    return names;
}

void write_exr(const std::filesystem::path& path, int width, int height,
               const std::vector<ExrLayer>& layers) {
    const std::string where = "cannot write " + quoted(path);
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
        throw std::invalid_argument(where + ": size " + std::to_string(width) + "x" +
                                    std::to_string(height) + " outside 1.." +
                                    std::to_string(kMaxImageSide));
    if (layers.empty()) throw std::invalid_argument(where + ": no layers");

    const std::size_t pixel_count = std::size_t(width) * std::size_t(height);
    std::set<std::string> all_names;
    for (const ExrLayer& layer : layers) {
        if (layer.channels < 1 || layer.channels > 4)
            throw std::invalid_argument(where + ": " + layer_title(layer) + " has " +
                                        std::to_string(layer.channels) + " channels, not 1-4");
        if (!layer.channel_names.empty() &&
            layer.channel_names.size() != std::size_t(layer.channels))
            throw std::invalid_argument(where + ": " + layer_title(layer) + " names " +
                                        std::to_string(layer.channel_names.size()) +
                                        " channels but has " + std::to_string(layer.channels));
        if (layer.data.size() != pixel_count * std::size_t(layer.channels))
            throw std::invalid_argument(where + ": " + layer_title(layer) + " has " +
                                        std::to_string(layer.data.size()) + " floats, needs " +
                                        std::to_string(pixel_count * std::size_t(layer.channels)));
        for (const std::string& name : exr_channel_names(layer))
            if (!all_names.insert(name).second)
                throw std::invalid_argument(where + ": channel '" + name + "' appears twice");
    }

    create_parent_directories(path);

    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    header.lineOrder() = Imf::INCREASING_Y;  // row 0 is the top, as the caller passes it
    // OpenEXR writes a slice only as its own pixel type: convert to half planes here.
    std::vector<std::vector<Imath::half>> planes;
    planes.reserve(all_names.size());
    Imf::FrameBuffer frame;
    for (const ExrLayer& layer : layers) {
        const std::vector<std::string> names = exr_channel_names(layer);
        for (int c = 0; c < layer.channels; ++c) {
            std::vector<Imath::half>& plane = planes.emplace_back(pixel_count);
            for (std::size_t i = 0; i < pixel_count; ++i)
                plane[i] = Imath::half(layer.data[i * std::size_t(layer.channels) + std::size_t(c)]);
            header.channels().insert(names[std::size_t(c)], Imf::Channel(Imf::HALF));
            frame.insert(names[std::size_t(c)],
                         Imf::Slice(Imf::HALF, reinterpret_cast<char*>(plane.data()),
                                    sizeof(Imath::half), sizeof(Imath::half) * std::size_t(width)));
        }
    }

    const std::filesystem::path temporary = temporary_path_beside(path);
    try {
        Imf::OutputFile file(temporary.c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(height);
    } catch (const std::exception& e) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw CaptureError(where + ": " + e.what());
    }
    replace_with(temporary, path);
}

}  // namespace game
