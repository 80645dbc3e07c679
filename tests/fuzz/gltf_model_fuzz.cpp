// The glTF loader on any bytes (.gltf JSON or .glb): a model whose every index names a
// vertex and whose numbers are finite, or one LevelError. External buffers resolve
// beside the harbour's assets.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "game/DataPaths.h"
#include "game/level/GltfModel.h"
#include "tests/fuzz/FuzzCheck.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::filesystem::path file = game::data_dir() / "levels" / "harbour" / "fuzz.gltf";
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        const effects::Model model = game::parse_gltf_model(bytes, file);
        FUZZ_CHECK(!model.meshes.empty());
        size_t vertices = 0;
        for (const effects::MeshData& mesh : model.meshes) {
            vertices += mesh.vertices.size();
            FUZZ_CHECK(mesh.indices.size() % 3 == 0);
            for (uint32_t i : mesh.indices) FUZZ_CHECK(i < mesh.vertices.size());
            for (const effects::MeshVertex& v : mesh.vertices)
                FUZZ_CHECK(std::isfinite(v.position.x + v.position.y + v.position.z) &&
                           std::isfinite(v.normal.x + v.normal.y + v.normal.z));
        }
        FUZZ_CHECK(vertices <= game::kMaxGltfVertices);
    } catch (const game::LevelError&) {
    }
    return 0;
}
