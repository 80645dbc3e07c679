// Frame capture: PNG files, EXR layers, frame comparison and image statistics.
#include "ErrorMessage.h"
#include "game/capture/ExrWriter.h"
#include "game/capture/FrameCompare.h"
#include "game/capture/ImageFiles.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <gtest/gtest.h>
#include <png.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

namespace fs = std::filesystem;
using game::ImageRGBA8;

namespace {

class TempDir {
public:
    TempDir() {
        static int counter = 0;
        path_ = fs::temp_directory_path() /
                ("spindrift_capture_test_" + std::to_string(::getpid()) + "_" +
                 std::to_string(counter++));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    const fs::path& path() const { return path_; }
    std::set<std::string> entries() const {
        std::set<std::string> names;
        for (const auto& entry : fs::directory_iterator(path_))
            names.insert(entry.path().filename().string());
        return names;
    }

private:
    fs::path path_;
};

ImageRGBA8 solid(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b,
                 std::uint8_t a = 255) {
    ImageRGBA8 image{width, height, {}};
    for (int i = 0; i < width * height; ++i) image.pixels.insert(image.pixels.end(), {r, g, b, a});
    return image;
}

// Every channel varies, including alpha down to 0 under non-zero colour, so a
// premultiplying reader or writer would be caught.
ImageRGBA8 gradient(int width, int height) {
    ImageRGBA8 image{width, height, {}};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.pixels.insert(image.pixels.end(),
                                {std::uint8_t(x * 255 / (width - 1)),
                                 std::uint8_t(y * 255 / (height - 1)),
                                 std::uint8_t((x * 7 + y * 13) % 256),
                                 std::uint8_t((x + y) * 255 / (width + height - 2))});
    return image;
}

std::uint8_t* pixel(ImageRGBA8& image, int x, int y) {
    return &image.pixels[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
}

// A PNG of 1 (grey), 2 (grey + alpha) or 3 (RGB) 8-bit channels, the bytes as given,
// written by libpng directly rather than by the code under test.
void write_with_libpng(const fs::path& path, int width, int height, int channels,
                       const std::vector<std::uint8_t>& data) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = png_uint_32(width);
    png.height = png_uint_32(height);
    png.format = channels == 1 ? PNG_FORMAT_GRAY : channels == 2 ? PNG_FORMAT_GA : PNG_FORMAT_RGB;
    ASSERT_TRUE(png_image_write_to_file(&png, path.c_str(), 0, data.data(), 0, nullptr)) << png.message;
}

}  // namespace

TEST(ImageFiles, PngRoundTripKeepsEveryByteAndCreatesTheDirectory) {
    TempDir dir;
    const fs::path path = dir.path() / "nested" / "frames" / "frame.png";
    const ImageRGBA8 image = gradient(37, 19);
    game::write_png(path, image);
    const ImageRGBA8 back = game::read_png(path);
    EXPECT_EQ(back.width, 37);
    EXPECT_EQ(back.height, 19);
    EXPECT_EQ(back.pixels, image.pixels);
    // Only the final file is left: the temporary was renamed.
    EXPECT_EQ(std::set<std::string>{"frame.png"}, [&] {
        std::set<std::string> names;
        for (const auto& e : fs::directory_iterator(path.parent_path()))
            names.insert(e.path().filename().string());
        return names;
    }());
}

TEST(ImageFiles, PngIsReallyPngAndRowZeroIsTheTop) {
    TempDir dir;
    ImageRGBA8 image = solid(4, 3, 0, 0, 0);
    pixel(image, 0, 0)[0] = 200;  // top-left red
    game::write_png(dir.path() / "a.png", image);
    // The PNG signature, and the pixels as libpng itself reads them.
    std::ifstream file(dir.path() / "a.png", std::ios::binary);
    std::vector<unsigned char> signature(8);
    file.read(reinterpret_cast<char*>(signature.data()), 8);
    EXPECT_EQ(png_sig_cmp(signature.data(), 0, 8), 0);
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    ASSERT_TRUE(png_image_begin_read_from_file(&png, (dir.path() / "a.png").c_str())) << png.message;
    EXPECT_EQ(png.width, 4u);
    EXPECT_EQ(png.height, 3u);
    png.format = PNG_FORMAT_RGBA;
    std::vector<std::uint8_t> raw(4 * 3 * 4);
    ASSERT_TRUE(png_image_finish_read(&png, nullptr, raw.data(), 0, nullptr)) << png.message;
    EXPECT_EQ(raw[0], 200);
}

TEST(ImageFiles, PngOverwriteReplacesTheOldImage) {
    TempDir dir;
    game::write_png(dir.path() / "f.png", solid(8, 8, 10, 20, 30));
    game::write_png(dir.path() / "f.png", solid(8, 8, 40, 50, 60));
    EXPECT_EQ(game::read_png(dir.path() / "f.png").pixels, solid(8, 8, 40, 50, 60).pixels);
    EXPECT_EQ(dir.entries(), std::set<std::string>{"f.png"});
}

TEST(ImageFiles, ReadPngExpandsGreyGreyAlphaAndRgb) {
    TempDir dir;
    write_with_libpng(dir.path() / "grey.png", 2, 1, 1, {7, 250});
    write_with_libpng(dir.path() / "grey_alpha.png", 1, 1, 2, {9, 128});
    write_with_libpng(dir.path() / "rgb.png", 1, 1, 3, {1, 2, 3});
    EXPECT_EQ(game::read_png(dir.path() / "grey.png").pixels,
              (std::vector<std::uint8_t>{7, 7, 7, 255, 250, 250, 250, 255}));
    EXPECT_EQ(game::read_png(dir.path() / "grey_alpha.png").pixels,
              (std::vector<std::uint8_t>{9, 9, 9, 128}));
    EXPECT_EQ(game::read_png(dir.path() / "rgb.png").pixels,
              (std::vector<std::uint8_t>{1, 2, 3, 255}));
}

TEST(ImageFiles, ReadPngRefusesMissingGarbageAndHugeFilesNamingThem) {
    TempDir dir;
    const fs::path missing = dir.path() / "missing.png";
    EXPECT_THROW(game::read_png(missing), std::runtime_error);
    EXPECT_NE(message_of([&] { game::read_png(missing); }).find(missing.string()), std::string::npos);

    const fs::path garbage = dir.path() / "garbage.png";
    std::ofstream(garbage) << "this is not a PNG file";
    const std::string garbage_error = message_of([&] { game::read_png(garbage); });
    EXPECT_NE(garbage_error.find(garbage.string()), std::string::npos) << garbage_error;

    const fs::path truncated = dir.path() / "truncated.png";
    game::write_png(truncated, gradient(64, 64));
    fs::resize_file(truncated, fs::file_size(truncated) / 2);
    const std::string truncated_error = message_of([&] { game::read_png(truncated); });
    EXPECT_NE(truncated_error.find(truncated.string()), std::string::npos) << truncated_error;

    const fs::path huge = dir.path() / "huge.png";
    write_with_libpng(huge, game::kMaxImageSide + 1, 1, 1,
                      std::vector<std::uint8_t>(std::size_t(game::kMaxImageSide) + 1, 0));
    const std::string huge_error = message_of([&] { game::read_png(huge); });
    EXPECT_NE(huge_error.find(huge.string()), std::string::npos) << huge_error;
    EXPECT_NE(huge_error.find("8193x1"), std::string::npos) << huge_error;
}

TEST(ImageFiles, WriteToUnwritablePathThrowsAndLeavesNoFile) {
    TempDir dir;
    // A regular file where the parent directory should be: running as root does
    // not get around this, unlike permissions.
    std::ofstream(dir.path() / "blocker") << "x";
    const fs::path under_file = dir.path() / "blocker" / "frame.png";
    const std::string error = message_of([&] { game::write_png(under_file, solid(2, 2, 1, 2, 3)); });
    EXPECT_NE(error.find(under_file.string()), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(under_file));

    // The final name is taken by a directory: the temporary is written, the rename
    // fails, and the temporary must not be left behind.
    fs::create_directory(dir.path() / "taken.png");
    EXPECT_THROW(game::write_png(dir.path() / "taken.png", solid(2, 2, 1, 2, 3)),
                 std::runtime_error);
    EXPECT_EQ(dir.entries(), (std::set<std::string>{"blocker", "taken.png"}));
    EXPECT_TRUE(fs::is_directory(dir.path() / "taken.png"));
}

TEST(ImageFiles, WritePngRefusesMalformedImages) {
    TempDir dir;
    ImageRGBA8 short_pixels = solid(4, 4, 0, 0, 0);
    short_pixels.pixels.pop_back();
    EXPECT_THROW(game::write_png(dir.path() / "a.png", short_pixels), std::invalid_argument);
    EXPECT_THROW(game::write_png(dir.path() / "b.png", ImageRGBA8{}), std::invalid_argument);
    EXPECT_TRUE(dir.entries().empty());
}

TEST(FrameCompare, IdenticalFramesPass) {
    const ImageRGBA8 image = gradient(30, 20);
    const game::CompareResult result = game::compare_frames(image, image);
    EXPECT_TRUE(result.passed);
    EXPECT_EQ(result.failing_pixels, 0u);
    EXPECT_EQ(result.max_diff, 0);
    EXPECT_EQ(result.summary, "0 of 600 pixels (0.00%) differ by more than 5/255, max 0");
}

TEST(FrameCompare, DifferencesWithinTolerancePass) {
    const ImageRGBA8 golden = solid(16, 16, 100, 100, 100);
    ImageRGBA8 actual = golden;
    for (std::size_t i = 0; i < actual.pixels.size(); i += 4) actual.pixels[i] += 5;
    game::CompareResult result = game::compare_frames(actual, golden);
    EXPECT_TRUE(result.passed);
    EXPECT_EQ(result.max_diff, 5);
    EXPECT_EQ(result.failing_pixels, 0u);

    // One pixel over the limit in 10000 is within 0.1%; eleven are not.
    const ImageRGBA8 big_golden = solid(100, 100, 50, 50, 50);
    ImageRGBA8 big_actual = big_golden;
    pixel(big_actual, 3, 4)[1] = 150;
    result = game::compare_frames(big_actual, big_golden);
    EXPECT_TRUE(result.passed);
    EXPECT_EQ(result.failing_pixels, 1u);
    EXPECT_EQ(result.max_diff, 100);
    for (int x = 10; x < 20; ++x) pixel(big_actual, x, 50)[2] = 0;
    result = game::compare_frames(big_actual, big_golden);
    EXPECT_FALSE(result.passed);
    EXPECT_EQ(result.failing_pixels, 11u);
    EXPECT_DOUBLE_EQ(result.fraction, 0.0011);
    EXPECT_EQ(result.summary, "11 of 10000 pixels (0.11%) differ by more than 5/255, max 100");
}

TEST(FrameCompare, VeryDifferentFramesFail) {
    const game::CompareResult result =
        game::compare_frames(solid(4, 2, 0, 0, 0), solid(4, 2, 255, 255, 255));
    EXPECT_FALSE(result.passed);
    EXPECT_EQ(result.failing_pixels, 8u);
    EXPECT_DOUBLE_EQ(result.fraction, 1.0);
    EXPECT_EQ(result.max_diff, 255);
    EXPECT_EQ(result.summary, "8 of 8 pixels (100.00%) differ by more than 5/255, max 255");
}

TEST(FrameCompare, SizeMismatchAndMalformedImagesFailWithoutCrashing) {
    game::CompareResult result = game::compare_frames(solid(4, 2, 0, 0, 0), solid(2, 4, 0, 0, 0));
    EXPECT_FALSE(result.passed);
    EXPECT_EQ(result.summary, "size mismatch: actual 4x2, golden 2x4");

    ImageRGBA8 malformed = solid(4, 2, 0, 0, 0);
    malformed.width = 1000;
    result = game::compare_frames(malformed, solid(4, 2, 0, 0, 0));
    EXPECT_FALSE(result.passed);
    EXPECT_NE(result.summary.find("actual image malformed"), std::string::npos);

    result = game::compare_frames(ImageRGBA8{}, ImageRGBA8{});
    EXPECT_FALSE(result.passed);

    EXPECT_THROW(game::compare_frames(malformed, malformed, {-1, 0.001}), std::invalid_argument);
}

TEST(FrameCompare, DifferenceImageMarksFailingPixelsRed) {
    const ImageRGBA8 golden = solid(8, 6, 200, 200, 200);
    ImageRGBA8 actual = golden;
    pixel(actual, 2, 1)[0] = 0;    // fails
    pixel(actual, 5, 4)[1] += 3;   // within tolerance
    ImageRGBA8 diff = game::difference_image(actual, golden);
    ASSERT_EQ(diff.width, 8);
    ASSERT_EQ(diff.height, 6);
    ASSERT_EQ(diff.pixels.size(), 8u * 6u * 4u);

    const std::uint8_t* red = pixel(diff, 2, 1);
    EXPECT_EQ((std::vector<int>{red[0], red[1], red[2], red[3]}), (std::vector<int>{255, 0, 0, 255}));
    const std::uint8_t* same = pixel(diff, 0, 0);
    EXPECT_EQ(same[0], same[1]);
    EXPECT_EQ(same[1], same[2]);
    EXPECT_LT(same[0], 100) << "the golden should be darkened";
    const std::uint8_t* small = pixel(diff, 5, 4);
    EXPECT_EQ(small[0], small[1]);
    EXPECT_GT(small[0], small[2] + 60) << "a small difference should stand out (yellow)";

    // Different sizes: the union, magenta where only one image has pixels.
    diff = game::difference_image(solid(4, 2, 0, 0, 0), solid(2, 3, 0, 0, 0));
    ASSERT_EQ(diff.width, 4);
    ASSERT_EQ(diff.height, 3);
    const std::uint8_t* outside = pixel(diff, 3, 0);
    EXPECT_EQ((std::vector<int>{outside[0], outside[1], outside[2]}), (std::vector<int>{255, 0, 255}));
    const std::uint8_t* inside = pixel(diff, 1, 1);
    EXPECT_EQ((std::vector<int>{inside[0], inside[1], inside[2]}), (std::vector<int>{0, 0, 0}));
}

TEST(FrameCompare, ImageStatsTellBlackAndFlatFromAGradient) {
    const game::ImageStats black = game::image_stats(solid(10, 10, 0, 0, 0));
    EXPECT_DOUBLE_EQ(black.mean_luma, 0.0);
    EXPECT_DOUBLE_EQ(black.luma_stddev, 0.0);

    const game::ImageStats white = game::image_stats(solid(10, 10, 255, 255, 255));
    EXPECT_NEAR(white.mean_luma, 1.0, 1e-12);
    EXPECT_NEAR(white.luma_stddev, 0.0, 1e-6);

    ImageRGBA8 ramp{256, 1, {}};
    for (int x = 0; x < 256; ++x)
        ramp.pixels.insert(ramp.pixels.end(), {std::uint8_t(x), std::uint8_t(x), std::uint8_t(x), 255});
    const game::ImageStats stats = game::image_stats(ramp);
    EXPECT_NEAR(stats.mean_luma, 0.5, 1e-9);
    EXPECT_NEAR(stats.luma_stddev, std::sqrt((256.0 * 256.0 - 1.0) / 12.0) / 255.0, 1e-9);

    EXPECT_THROW(game::image_stats(ImageRGBA8{}), std::invalid_argument);
}

TEST(ExrWriter, LayersReadBackWithTheirChannelsAndValues) {
    TempDir dir;
    const int width = 5, height = 3;
    const std::size_t n = std::size_t(width) * height;
    game::ExrLayer colour{"", 4, {}};
    game::ExrLayer depth{"depth", 1, {}};
    game::ExrLayer normal{"normal", 3, {}};
    for (std::size_t i = 0; i < n; ++i) {
        colour.data.insert(colour.data.end(), {0.1f * float(i), 2.5f, -1.0f, 1.0f});
        depth.data.push_back(float(i) / float(n));
        normal.data.insert(normal.data.end(), {0.0f, float(i % 2), -0.5f});
    }
    const fs::path path = dir.path() / "out" / "frame.exr";
    game::write_exr(path, width, height, {colour, depth, normal});
    EXPECT_EQ(dir.entries(), std::set<std::string>{"out"});

    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    EXPECT_EQ(header.compression(), Imf::ZIP_COMPRESSION);
    std::set<std::string> names;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        names.insert(it.name());
        EXPECT_EQ(it.channel().type, Imf::HALF) << it.name();
    }
    EXPECT_EQ(names, (std::set<std::string>{"R", "G", "B", "A", "depth.Z", "normal.X", "normal.Y",
                                             "normal.Z"}));
    const Imath::Box2i window = header.dataWindow();
    ASSERT_EQ(window.max.x - window.min.x + 1, width);
    ASSERT_EQ(window.max.y - window.min.y + 1, height);

    std::map<std::string, std::vector<float>> planes;
    Imf::FrameBuffer frame;
    for (const std::string& name : names) {
        planes[name].assign(n, -99.0f);
        frame.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(planes[name].data()),
                                      sizeof(float), sizeof(float) * width));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);

    auto half_close = [](float actual, float expected) {
        return std::abs(actual - expected) <= 1e-3f * std::max(1.0f, std::abs(expected));
    };
    for (std::size_t i = 0; i < n; ++i) {  // i = y * width + x, y = 0 the top row
        EXPECT_TRUE(half_close(planes["R"][i], 0.1f * float(i))) << i << ": " << planes["R"][i];
        EXPECT_TRUE(half_close(planes["G"][i], 2.5f));
        EXPECT_TRUE(half_close(planes["B"][i], -1.0f));
        EXPECT_TRUE(half_close(planes["A"][i], 1.0f));
        EXPECT_TRUE(half_close(planes["depth.Z"][i], float(i) / float(n))) << i;
        EXPECT_TRUE(half_close(planes["normal.X"][i], 0.0f));
        EXPECT_TRUE(half_close(planes["normal.Y"][i], float(i % 2)));
        EXPECT_TRUE(half_close(planes["normal.Z"][i], -0.5f));
    }
}

TEST(ExrWriter, ChannelNamesFollowTheLayerConvention) {
    EXPECT_EQ(game::exr_channel_names({"", 3, {}}), (std::vector<std::string>{"R", "G", "B"}));
    EXPECT_EQ(game::exr_channel_names({"motion", 2, {}}),
              (std::vector<std::string>{"motion.X", "motion.Y"}));
    EXPECT_EQ(game::exr_channel_names({"albedo", 3, {}, {"R", "G", "B"}}),
              (std::vector<std::string>{"albedo.R", "albedo.G", "albedo.B"}));
}

TEST(ExrWriter, BadLayersAndUnwritablePathsThrowAndLeaveNoFile) {
    TempDir dir;
    const fs::path path = dir.path() / "bad.exr";
    EXPECT_THROW(game::write_exr(path, 2, 2, {{"depth", 1, std::vector<float>(3)}}),
                 std::invalid_argument);
    EXPECT_THROW(game::write_exr(path, 2, 2, {{"", 5, std::vector<float>(20)}}),
                 std::invalid_argument);
    EXPECT_THROW(game::write_exr(path, 2, 2,
                                 {{"n", 1, std::vector<float>(4)}, {"n", 1, std::vector<float>(4)}}),
                 std::invalid_argument);
    EXPECT_THROW(game::write_exr(path, 0, 2, {{"", 1, {}}}), std::invalid_argument);
    EXPECT_THROW(game::write_exr(path, 2, 2, {}), std::invalid_argument);
    EXPECT_TRUE(dir.entries().empty());

    std::ofstream(dir.path() / "blocker") << "x";
    const fs::path unwritable = dir.path() / "blocker" / "f.exr";
    const std::string error = message_of(
        [&] { game::write_exr(unwritable, 2, 2, {{"", 1, std::vector<float>(4, 1.0f)}}); });
    EXPECT_NE(error.find(unwritable.string()), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(unwritable));

    fs::create_directory(dir.path() / "taken.exr");
    EXPECT_THROW(game::write_exr(dir.path() / "taken.exr", 2, 2,
                                 {{"", 1, std::vector<float>(4, 1.0f)}}),
                 std::runtime_error);
    EXPECT_EQ(dir.entries(), (std::set<std::string>{"blocker", "taken.exr"}));
}
