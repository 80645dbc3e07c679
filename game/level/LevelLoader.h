#pragma once
// Level loading: a level JSON plus its glTF assets -> what the sim and the renderer need.
//
// Level file format (format 1). Units: metres, degrees; x east, y up, z south.
//
//   {
//     "format": 1,                       required, must be 1
//     "id": "harbour",                   required, 1..64 characters
//     "seed": 20261122,                  optional unsigned integer (default 1)
//     "budget_mib": 512,                 optional memory budget in MiB, 64..65536 (default
//                                          1024): the level's estimated needs (LevelMemory.h)
//                                          must fit, or it is refused before they are allocated
//     "world": {                         required
//       "half_extent_m": 160,            the world is [-h, h] in x and z; (0, 2000]
//       "land_height_m": 1.2,            land where z < shore_z_m
//       "shore_z_m": 0, "sea_level_m": 0,
//       "seabed_m": -6,                  below sea_level_m
//       "hills": [{"centre_xz": [0, -80], "radius_m": 25, "height_m": 8}]   optional;
//     },                                   radius_m (Gaussian sigma) in (0, 2000]
//     "roads": [{"min_xz": [-150, -14], "max_xz": [150, -6]}],   optional, min < max
//     "sun": {"direction": [0.45, 0.7, 0.35]},   optional; towards the sun, y > 0,
//                                                  normalised by the loader
//     "rain": {"intensity": 0.0},        optional, [0, 1]
//     "water": {                         optional: the wave grid (docs/effects/water.md)
//       "grid_origin_xz": [-40, 1],      world x, z of cell (0, 0)
//       "grid_size": 256,                cells per side, 8..2048
//       "grid_spacing_m": 0.5,           [0.01, 100]
//       "wave_speed_mps": 2.5,           (0, 100]; the grid refuses an unstable speed and spacing
//       "damping_per_s": 0.25            fraction of wave energy lost per second, [0, 1)
//     },                                   all five required
//     "car":  {"asset": "car.gltf",  "position": [x, y, z], "heading_deg": 0},    required
//     "boat": {"asset": "boat.gltf", "position": [x, y, z], "heading_deg": -90},  required
//     "tank_spot": [22, 1.5, 36],        required: where the fluid tank stands
//     "fluid": {                         optional: the glass tank (docs/effects/fluid.md)
//       "particle_count": 2400,          1..200000, must fit the tank at the rest spacing
//       "particle_radius_m": 0.04,       (0.001, 1]
//       "tank_size_m": [1.6, 1.1, 1.6],  inner size, each (0, 20] and at least 4 particle radii
//       "solver_iterations": 3,          1..20
//       "body_neighbours": 12,           fewer neighbours: splash; 1..60
//       "on": "pier",                    "pier" (at tank_spot, its panes are solids) | "boat"
//       "smoothing": {"method": "plane_fit", "kernel_size": 9, "iterations": 3}
//     },                                   method plane_fit | bilateral | narrow_range;
//                                          kernel odd 3..15; iterations 1..64
//     "dust": {                          optional: dusty props (docs/effects/dust.md)
//       "fibre_image": "dust_fibres.png",   required: a binarised fibre image among the assets
//       "fibre_slices": 3,               slices stacked in the image, 1..16 (default 1)
//       "preset": "dust",                dust | sand | mould (default dust)
//       "sources_per_prop": 5, "source_elevation_deg": 65, "source_distance": 2.5,
//       "sample_spacing_m": 0.08, "object_clear_radius_m": 0.25, "shot_clear_radius_m": 0.6
//     },
//     "courses": [                       optional, at most 8: gates to lap (README, Playing)
//       {"name": "quay",                 1..32 characters, one per course
//        "vehicle": "car",               "car" (its gates on land) | "boat" (on the sea)
//        "gates": [{"centre_xz": [-4, -10], "heading_deg": 0, "width_m": 10}, ...]}
//     ],                                   2..64 gates, passed in order moving along
//                                          heading_deg; width_m [2, 40]; gate 0 starts
//                                          and ends a lap
//     "targets": [                       optional, at most 64: hit by stones and shots
//       {"kind": "buoy", "position": [x, y, z], "radius_m": 0.8}
//     ],                                   "buoy" (on the sea) | "crate" (on land);
//                                          radius_m [0.2, 3]
//     "props": [                         optional, at most 4096
//       {"asset": "warehouse.gltf", "position": [x, y, z],
//        "heading_deg": 0,               optional (default 0)
//        "scale": 1,                     optional (default 1), (0, 1000]
//        "collision": "solid",           optional: "solid" | "deck" | "none" (default)
//        "dust": true}                   optional: true (the dust preset) or a preset name
//     ]
//   }
//
// Positions must lie inside the world in x and z. Keys starting with '_' are ignored
// (comments); any other unknown key is an error, so typos do not pass silently.
//
// Assets are paths relative to the folder named like the level file next to it
// (levels/harbour.json -> levels/harbour/), without "..". Each distinct asset is
// loaded once; props sharing it share one effects::Model.
//
// heading_deg turns about +y: 0 faces +x, positive turns from +x towards -z. A prop's
// transform is translate(position) * rotate_y(heading) * scale.
//
// Collision: "solid" makes each of the model's meshes' world AABB a sim solid, except
// meshes named "nocollide*" (so a hollow warehouse is one solid per wall); "deck" makes
// the meshes named "piling*" solids and the world AABB of the other meshes (again
// without "nocollide*") a drivable deck; "none" adds nothing.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "effects/scene/SceneDesc.h"
#include "game/dust/FibreImage.h"
#include "game/level/LevelError.h"
#include "game/level/MemoryBudget.h"
#include "sim/world/LevelDesc.h"

namespace game {

inline constexpr uint64_t kMaxLevelJsonBytes = 4ull << 20;
inline constexpr size_t kMaxLevelProps = 4096;

struct LoadedLevel {
    std::filesystem::path path;  // the .json
    sim::LevelDesc sim;          // for the simulation
    effects::SceneDesc scene;    // for the renderer
    // FNV-1a 64 over the JSON bytes, then each distinct asset in first-use order (car,
    // boat, props): its name and its file's bytes (and external buffers), each with its
    // length. Identifies the level's content in replays.
    uint64_t content_hash = 0;
    // The budget and what the level and its assets were charged against it; frames are
    // charged by whoever renders them (charge_frame_memory).
    MemoryBudget memory;
};

// A level name ("harbour" -> <data_dir>/levels/harbour.json) or a path (contains '/'
// or ends in .json). Does not check that the file exists.
std::filesystem::path resolve_level_path(std::string_view name_or_path);

// Reads the dust's fibre image into the renderer's growth statistics; throws
// FibreImageError. The sim never reads them.
using FibreImageReader = effects::FibreDirections (*)(const std::filesystem::path& image, int slices);

// Throws LevelError with one message naming the file and what is wrong. Without a
// fibre reader (the GL-free replay checker, which has no image library) the fibre
// image is not read and scene.fibre_directions stays empty; the sim and the content
// hash are the same.
LoadedLevel load_level(std::string_view name_or_path, FibreImageReader fibre_reader);
// The same for a level JSON already in memory, as if read from `path` (its assets are
// read from beside it).
LoadedLevel load_level_text(const std::filesystem::path& path, const std::string& text, FibreImageReader fibre_reader);

// With the fibre image, as everything that renders needs (read_fibre_directions is in
// the game library, with the image files).
inline LoadedLevel load_level(std::string_view name_or_path) {
    return load_level(name_or_path, &read_fibre_directions);
}
inline LoadedLevel load_level_text(const std::filesystem::path& path, const std::string& text) {
    return load_level_text(path, text, &read_fibre_directions);
}

}  // namespace game
