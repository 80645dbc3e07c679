#include "game/capture/FrameCompare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace game {
namespace {

bool well_formed(const ImageRGBA8& image) {
    return image.width >= 0 && image.height >= 0 &&
           image.pixels.size() == std::size_t(image.width) * std::size_t(image.height) * 4;
}

std::string size_text(const ImageRGBA8& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

int pixel_diff(const std::uint8_t* a, const std::uint8_t* b) {
    int diff = 0;
    for (int c = 0; c < 4; ++c) diff = std::max(diff, std::abs(int(a[c]) - int(b[c])));
    return diff;
}

double luma(const std::uint8_t* p) {
    return (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 255.0;
}

CompareResult refused(std::string why) {
    CompareResult result;
    result.passed = false;
    result.fraction = 1.0;
    result.summary = std::move(why);
    return result;
}

}  // namespace

CompareResult compare_frames(const ImageRGBA8& actual, const ImageRGBA8& golden,
                             Tolerance tolerance) {
    if (tolerance.per_channel < 0 || tolerance.max_fraction < 0.0 ||
        !std::isfinite(tolerance.max_fraction))
        throw std::invalid_argument("compare_frames: negative or invalid tolerance");
    if (!well_formed(actual))
        return refused("actual image malformed: " + std::to_string(actual.pixels.size()) +
                       " bytes for " + size_text(actual));
    if (!well_formed(golden))
        return refused("golden image malformed: " + std::to_string(golden.pixels.size()) +
                       " bytes for " + size_text(golden));
    if (actual.width != golden.width || actual.height != golden.height)
        return refused("size mismatch: actual " + size_text(actual) + ", golden " +
                       size_text(golden));
    if (actual.pixels.empty()) return refused("both images are empty");

    CompareResult result;
    const std::size_t pixel_count = actual.pixels.size() / 4;
    for (std::size_t i = 0; i < pixel_count; ++i) {
        const int diff = pixel_diff(&actual.pixels[i * 4], &golden.pixels[i * 4]);
        result.max_diff = std::max(result.max_diff, diff);
        if (diff > tolerance.per_channel) ++result.failing_pixels;
    }
    result.fraction = double(result.failing_pixels) / double(pixel_count);
    result.passed = result.fraction <= tolerance.max_fraction;
    char text[160];
    std::snprintf(text, sizeof text, "%zu of %zu pixels (%.2f%%) differ by more than %d/255, max %d",
                  result.failing_pixels, pixel_count, result.fraction * 100.0,
                  tolerance.per_channel, result.max_diff);
    result.summary = text;
    return result;
}

ImageRGBA8 difference_image(const ImageRGBA8& actual, const ImageRGBA8& golden,
                            Tolerance tolerance) {
    // A malformed image contributes no pixels (shown as magenta) rather than a crash.
    const bool actual_ok = well_formed(actual);
    const bool golden_ok = well_formed(golden);
    const int aw = actual_ok ? actual.width : 0, ah = actual_ok ? actual.height : 0;
    const int gw = golden_ok ? golden.width : 0, gh = golden_ok ? golden.height : 0;

    ImageRGBA8 out;
    out.width = std::max(aw, gw);
    out.height = std::max(ah, gh);
    out.pixels.resize(std::size_t(out.width) * std::size_t(out.height) * 4);
    const int amplify_over = std::max(tolerance.per_channel, 1);

    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            std::uint8_t* d = &out.pixels[(std::size_t(y) * std::size_t(out.width) + std::size_t(x)) * 4];
            d[3] = 255;
            if (x >= aw || y >= ah || x >= gw || y >= gh) {
                d[0] = 255, d[1] = 0, d[2] = 255;
                continue;
            }
            const std::uint8_t* a = &actual.pixels[(std::size_t(y) * std::size_t(aw) + std::size_t(x)) * 4];
            const std::uint8_t* g = &golden.pixels[(std::size_t(y) * std::size_t(gw) + std::size_t(x)) * 4];
            const int diff = pixel_diff(a, g);
            const auto grey = static_cast<std::uint8_t>(std::lround(luma(g) * 255.0 * 0.3));
            if (diff > tolerance.per_channel) {
                d[0] = 255, d[1] = 0, d[2] = 0;
            } else if (diff > 0) {
                // Small differences scaled up so they are visible next to the grey.
                const int level = std::min(255, 96 + diff * 159 / amplify_over);
                d[0] = d[1] = static_cast<std::uint8_t>(std::max<int>(level, grey));
                d[2] = grey;
            } else {
                d[0] = d[1] = d[2] = grey;
            }
        }
    }
    return out;
}

ImageStats image_stats(const ImageRGBA8& image) {
    if (!well_formed(image) || image.pixels.empty())
        throw std::invalid_argument("image_stats: empty or malformed " + size_text(image) +
                                    " image (" + std::to_string(image.pixels.size()) + " bytes)");
    const std::size_t pixel_count = image.pixels.size() / 4;
    double sum = 0.0, sum_squares = 0.0;
    for (std::size_t i = 0; i < pixel_count; ++i) {
        const double l = luma(&image.pixels[i * 4]);
        sum += l;
        sum_squares += l * l;
    }
    ImageStats stats;
    stats.mean_luma = sum / double(pixel_count);
    stats.luma_stddev =
        std::sqrt(std::max(0.0, sum_squares / double(pixel_count) - stats.mean_luma * stats.mean_luma));
    return stats;
}

}  // namespace game
