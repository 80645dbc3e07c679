#pragma once
// The renderable content of a level as plain CPU data: models (meshes in model
// space) and where their instances stand. Filled by the game's level loader.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "effects/dust/FibreDirections.h"

namespace effects {

struct MeshVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec4 color{1.0f};  // linear base colour: material factor times COLOR_0
};

struct MeshData {
    std::string name;
    std::vector<MeshVertex> vertices;
    std::vector<uint32_t> indices;  // triangles
    float roughness = 0.8f;
    float metallic = 0.0f;
    glm::vec3 emissive{0.0f};  // HDR radiance the surface gives off (glTF emissiveFactor)
};

struct Model {
    std::string name;              // asset file stem, e.g. "warehouse"
    std::vector<MeshData> meshes;  // node transforms already applied (model space)
    glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};
};

struct PropInstance {
    int model = -1;  // index into SceneDesc::models
    glm::mat4 transform{1.0f};
};

struct SceneDesc {
    std::vector<Model> models;
    std::vector<PropInstance> props;  // static level geometry
    int car_model = -1;               // drawn at the sim's car pose
    int boat_model = -1;              // drawn at the sim's boat pose
    FibreDirections fibre_directions; // from the level's dust fibre image (empty: no dust)
};

}  // namespace effects
