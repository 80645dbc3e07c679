#include "game/capture/ImageFiles.h"
#include "game/capture/CaptureError.h"

#include <png.h>

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace game {

// Built by appending: GCC 12 warns falsely (-Wrestrict) on "'" + std::string.
std::string quoted(const std::filesystem::path& path) {
    std::string text(1, '\'');
    text += path.string();
    text += '\'';
    return text;
}

void create_parent_directories(const std::filesystem::path& path) {
    if (!path.has_parent_path()) return;
    std::error_code error;
    std::filesystem::create_directories(path.parent_path(), error);
    if (error)
        throw CaptureError("cannot write " + quoted(path) + ": cannot create directory " + quoted(path.parent_path()) +
                           ": " + error.message());
}

namespace {

void check_image(const std::filesystem::path& path, const ImageRGBA8& image) {
    if (image.width < 1 || image.height < 1 || image.width > kMaxImageSide ||
        image.height > kMaxImageSide)
        throw std::invalid_argument("cannot write " + quoted(path) + ": image size " +
                                    std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + " outside 1.." +
                                    std::to_string(kMaxImageSide));
    const std::size_t expected = std::size_t(image.width) * std::size_t(image.height) * 4;
    if (image.pixels.size() != expected)
        throw std::invalid_argument("cannot write " + quoted(path) + ": " +
                                    std::to_string(image.pixels.size()) + " bytes for a " +
                                    std::to_string(image.width) + "x" +
                                    std::to_string(image.height) + " RGBA8 image (needs " +
                                    std::to_string(expected) + ")");
}

}  // namespace

std::filesystem::path temporary_path_beside(const std::filesystem::path& path) {
    static std::atomic<unsigned> counter{0};
    std::filesystem::path temporary = path;
    std::string name(1, '.');
    name += path.filename().string();
    name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    temporary.replace_filename(name);
    return temporary;
}

void replace_with(const std::filesystem::path& temporary, const std::filesystem::path& path) {
    std::error_code error;
    // On disk before the rename: after a power cut `path` holds the old file or the new
    // one, never a name pointing at blocks that were not written yet.
    const int fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
    const bool synced = fd >= 0 && ::fsync(fd) == 0;
    const int sync_errno = errno;
    if (fd >= 0) ::close(fd);
    if (!synced) {
        std::filesystem::remove(temporary, error);
        throw CaptureError("cannot write " + quoted(path) + ": cannot flush " + quoted(temporary) + ": " +
                           std::strerror(sync_errno));
    }
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::filesystem::remove(temporary, error);
        throw CaptureError("cannot write " + quoted(path) + ": rename failed: " + error.message());
    }
}

void write_png(const std::filesystem::path& path, const ImageRGBA8& image) {
    check_image(path, image);
    create_parent_directories(path);

    // Encoded in memory (libpng's simplified API: 8-bit RGBA stored as given, straight
    // alpha), then written with every write checked, so a failed write (a full disk)
    // never leaves a truncated PNG under `path`.
    auto fail = [&](const std::string& why) { throw CaptureError("cannot write " + quoted(path) + ": " + why); };
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = png_uint_32(image.width);
    png.height = png_uint_32(image.height);
    png.format = PNG_FORMAT_RGBA;
    png_alloc_size_t size = 0;
    if (!png_image_write_get_memory_size(png, size, 0, image.pixels.data(), 0, nullptr)) fail(png.message);
    std::vector<unsigned char> encoded(size);
    if (!png_image_write_to_memory(&png, encoded.data(), &size, 0, image.pixels.data(), 0, nullptr))
        fail(png.message);
    encoded.resize(size);
    write_file_atomically(path, encoded);
}

void write_file_atomically(const std::filesystem::path& path, std::span<const unsigned char> bytes) {
    const std::filesystem::path temporary = temporary_path_beside(path);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw CaptureError("cannot write " + quoted(path) + ": " + std::strerror(errno));
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const std::string why = n < 0 ? std::strerror(errno) : "nothing written";
            ::close(fd);
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            throw CaptureError("cannot write " + quoted(path) + ": " + why);
        }
        done += size_t(n);
    }
    if (::close(fd) != 0) {
        const std::string why = std::strerror(errno);
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw CaptureError("cannot write " + quoted(path) + ": " + why);
    }
    replace_with(temporary, path);
}

ImageRGBA8 read_png(const std::filesystem::path& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw CaptureError("cannot read image " + quoted(path) +
                                 (std::filesystem::exists(path, error) ? ": not a regular file"
                                                                       : ": no such file"));

    // libpng's simplified reader turns grey, grey + alpha, RGB and palette images into
    // RGBA8 (grey becomes R=G=B, missing alpha 255), alpha kept straight.
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, path.c_str()))
        throw CaptureError("cannot read image " + quoted(path) + ": " + png.message);
    if (png.width < 1 || png.height < 1 || png.width > png_uint_32(kMaxImageSide) ||
        png.height > png_uint_32(kMaxImageSide)) {
        png_image_free(&png);
        throw CaptureError("cannot read image " + quoted(path) + ": size " + std::to_string(png.width) + "x" +
                           std::to_string(png.height) + " outside 1.." + std::to_string(kMaxImageSide));
    }
    png.format = PNG_FORMAT_RGBA;
    ImageRGBA8 image{int(png.width), int(png.height), std::vector<std::uint8_t>(PNG_IMAGE_SIZE(png))};
    // Frees `png` whether it succeeds or not.
    if (!png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr))
        throw CaptureError("cannot read image " + quoted(path) + ": " + png.message);
    return image;
}

}  // namespace game
