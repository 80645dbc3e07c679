#pragma once
// The level JSON read into the sim's level description, every value checked; the
// assets it names (car, boat, props, the fibre image) are only named here, and loaded
// by load_level (LevelLoader.cpp).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "sim/dust/DustDesc.h"
#include "sim/world/LevelDesc.h"

namespace game {

enum class Collision { none, solid, deck };

struct Placement {  // a car, boat or prop entry, read but not yet loaded
    std::string where;  // JSON path of the entry, for messages
    std::string asset;
    glm::vec3 position{0.0f};
    float heading_rad = 0.0f;
    float scale = 1.0f;
    Collision collision = Collision::none;
    bool dusty = false;
    std::optional<sim::DustKind> dust_kind;  // unset: the level's dust preset
};

// The level's "dust" section as read, before the fibre image is loaded.
struct DustSection {
    bool present = false;
    sim::DustKind preset = sim::DustKind::Dust;
    std::string fibre_image;
    int fibre_slices = 1;
};

// Throws LevelError naming the file and the JSON path of what is wrong.
void parse_level(const std::filesystem::path& file, const nlohmann::json& doc, sim::LevelDesc& level,
                 uint64_t& budget_mib, std::vector<Placement>& placements, DustSection& dust);

}  // namespace game
