#pragma once
#include "game/capture/Image.h"

#include <filesystem>
#include <span>
#include <string>

namespace game {

// Largest image read_png accepts per side: goldens are small, anything bigger is
// a wrong or hostile file.
inline constexpr int kMaxImageSide = 8192;

// Writes an RGBA8 PNG (straight alpha). Creates the parent directory. Writes a
// temporary file beside `path` and renames it, so `path` is never half-written.
// Throws std::runtime_error naming the file on failure, std::invalid_argument for an
// image whose pixel count does not match its size.
void write_png(const std::filesystem::path& path, const ImageRGBA8& image);

// Reads a PNG (libpng) of 1-4 channels or a palette as RGBA8: grey
// becomes R=G=B, missing alpha becomes 255. Throws std::runtime_error naming the file
// if it is missing, unreadable or larger than kMaxImageSide per side.
ImageRGBA8 read_png(const std::filesystem::path& path);

// For file writers' messages: the path in single quotes.
std::string quoted(const std::filesystem::path& path);
// For file writers: creates the folder `path` goes in, if it has one; throws
// CaptureError ("cannot write 'path': cannot create directory ...") if that fails.
void create_parent_directories(const std::filesystem::path& path);
// For file writers: a unique temporary name in the same directory as `path` (so the
// final rename stays on one file system), and moving it into place once it is flushed
// to disk (throws CaptureError and removes the temporary if either fails).
std::filesystem::path temporary_path_beside(const std::filesystem::path& path);
void replace_with(const std::filesystem::path& temporary, const std::filesystem::path& path);
// Writes `bytes` to a temporary beside `path`, checking every write, and moves it into
// place; throws CaptureError naming `path` (and leaves no temporary) on failure.
void write_file_atomically(const std::filesystem::path& path, std::span<const unsigned char> bytes);

}  // namespace game
