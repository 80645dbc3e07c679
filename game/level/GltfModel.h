#pragma once
// glTF 2.0 (.gltf with embedded or external buffers, or .glb) -> effects::Model.
//
// The default scene's node hierarchy is flattened: node transforms (TRS or matrix) are
// baked into positions and normals, one MeshData per triangle primitive, named after
// its node. POSITION is required; NORMAL is computed (area-weighted) when absent;
// COLOR_0 (float, or normalised u8/u16) times the material's baseColorFactor gives the
// linear vertex colour. Textures are ignored. Everything is validated before it is
// read, so a malformed file gives a LevelError, never a crash.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "effects/scene/SceneDesc.h"
#include "game/level/LevelError.h"

namespace sim {
class Hasher;
}

namespace game {

inline constexpr uint64_t kMaxGltfFileBytes = 64ull << 20;  // also each external buffer
inline constexpr size_t kMaxGltfVertices = size_t(1) << 22;  // per model, after flattening

// Loads `file`; throws LevelError naming the file. When `content` is given, every byte
// read (the file, then any external buffers in order) is fed to it, each preceded by
// its length.
effects::Model load_gltf_model(const std::filesystem::path& file, sim::Hasher* content = nullptr);
// The same for a file's bytes already in memory (`content` gets only external buffers);
// external buffers are still read from beside `file`.
effects::Model parse_gltf_model(const std::string& bytes, const std::filesystem::path& file,
                                sim::Hasher* content = nullptr);

// Reads a whole file of at most max_bytes; throws LevelError naming it otherwise.
std::string read_level_file(const std::filesystem::path& file, uint64_t max_bytes);

// Deepest nesting of [ and { in a JSON text (outside strings). JSON code that walks
// values recursively (tinygltf's extras, dump()) would overflow the stack on absurd
// depths, so level files and glTF are refused beyond kMaxJsonNesting.
inline constexpr size_t kMaxJsonNesting = 64;
size_t json_nesting_depth(std::string_view text);

}  // namespace game
