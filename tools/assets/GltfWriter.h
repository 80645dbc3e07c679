#pragma once
#include <filesystem>

#include "tools/assets/AssetGeometry.h"

namespace assets {

// Writes asset.name + ".gltf" into dir: one node per part, buffers embedded as base64.
void write_gltf(const Asset& asset, const std::filesystem::path& dir);

}  // namespace assets
