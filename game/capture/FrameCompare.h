#pragma once
#include "game/capture/Image.h"

#include <cstddef>
#include <string>

namespace game {

// A pixel fails when any channel differs by more than per_channel (out of 255); a
// frame passes when at most max_fraction of its pixels fail. Defaults follow
// Filament's render tests.
struct Tolerance {
    int per_channel = 5;
    double max_fraction = 0.001;
};

struct CompareResult {
    bool passed = false;
    std::size_t failing_pixels = 0;
    double fraction = 0.0;  // failing_pixels / pixel count
    int max_diff = 0;       // largest channel difference anywhere
    std::string summary;    // "312 of 129600 pixels (0.24%) differ by more than 5/255, max 87"
};

// Never throws for mismatched or malformed images: they fail with a summary saying why.
// Throws std::invalid_argument for a negative tolerance.
CompareResult compare_frames(const ImageRGBA8& actual, const ImageRGBA8& golden,
                             Tolerance tolerance = {});

// A picture of where frames differ, the size of the larger of the two: failing
// pixels red over a darkened grey golden, differences within tolerance in amplified
// yellow, and magenta where only one image has pixels.
ImageRGBA8 difference_image(const ImageRGBA8& actual, const ImageRGBA8& golden,
                            Tolerance tolerance = {});

// Rec. 709 luma in [0, 1]: lets checks refuse black or flat frames.
struct ImageStats {
    double mean_luma = 0.0;
    double luma_stddev = 0.0;
};
// Throws std::invalid_argument for an empty or malformed image.
ImageStats image_stats(const ImageRGBA8& image);

}  // namespace game
