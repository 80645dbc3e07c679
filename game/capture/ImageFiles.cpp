#include "game/capture/ImageFiles.h"
#include "game/capture/CaptureError.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

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

    // Encoded in memory, then written with every write checked: OpenImageIO's PNG
    // writer does not report a failed write (a full disk), which would otherwise put a
    // truncated PNG under `path`.
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    auto fail = [&](const std::string& why) { throw CaptureError("cannot write " + quoted(path) + ": " + why); };
    auto out = OIIO::ImageOutput::create("png");
    if (!out) fail("OpenImageIO has no PNG writer: " + OIIO::geterror());
    if (!out->supports("ioproxy") || !out->set_ioproxy(&memory)) fail("OpenImageIO cannot encode a PNG in memory");
    OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::UINT8);
    // Our pixels are straight alpha: without this OIIO would un-premultiply them.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!out->open(path.string(), spec)) fail(out->geterror());
    if (!out->write_image(OIIO::TypeDesc::UINT8, image.pixels.data())) {
        const std::string why = out->geterror();
        out->close();
        fail(why);
    }
    if (!out->close()) fail(out->geterror());
    out.reset();
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

    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);  // keep straight alpha as stored
    auto in = OIIO::ImageInput::open(path.string(), &config);
    if (!in) throw CaptureError("cannot read image " + quoted(path) + ": " + OIIO::geterror());

    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width < 1 || spec.height < 1 || spec.width > kMaxImageSide ||
        spec.height > kMaxImageSide || spec.depth > 1)
        throw CaptureError("cannot read image " + quoted(path) + ": size " +
                                 std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                                 " outside 1.." + std::to_string(kMaxImageSide));
    if (spec.nchannels < 1 || spec.deep)
        throw CaptureError("cannot read image " + quoted(path) + ": " +
                                 std::to_string(spec.nchannels) + " channels" +
                                 (spec.deep ? " (deep image)" : ""));

    const int channels = std::min(spec.nchannels, 4);
    const std::size_t pixel_count = std::size_t(spec.width) * std::size_t(spec.height);
    std::vector<std::uint8_t> stored(pixel_count * std::size_t(channels));
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, stored.data()))
        throw CaptureError("cannot read image " + quoted(path) + ": " + in->geterror());
    in->close();

    ImageRGBA8 image{spec.width, spec.height, std::vector<std::uint8_t>(pixel_count * 4)};
    for (std::size_t i = 0; i < pixel_count; ++i) {
        const std::uint8_t* s = &stored[i * std::size_t(channels)];
        std::uint8_t* d = &image.pixels[i * 4];
        const bool grey = channels <= 2;
        d[0] = s[0];
        d[1] = grey ? s[0] : s[1];
        d[2] = grey ? s[0] : s[2];
        d[3] = channels == 2 ? s[1] : channels == 4 ? s[3] : 255;
    }
    return image;
}

}  // namespace game
