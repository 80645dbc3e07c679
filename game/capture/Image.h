#pragma once
#include <cstdint>
#include <vector>

namespace game {

// 8-bit RGBA image, rows top-down, 4 bytes per pixel (R, G, B, A).
struct ImageRGBA8 {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;
};

// Float RGBA image, rows top-down, 4 floats per pixel.
struct ImageRGBA32F {
    int width = 0;
    int height = 0;
    std::vector<float> pixels;
};

}  // namespace game
