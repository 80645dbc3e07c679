#pragma once
// The airborne part of the splash sheets as one triangle list: each sheet's vertices
// with normals from their neighbours, and the triangles whose three corners are all
// above the water (the rest of the sheet stays hidden under the surface).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "effects/water/WaterView.h"

namespace effects {

struct SheetVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 cell{0.0f};  // (i, j) in the sheet: foam patterns stretch with the film
    float stretch = 1.0f;  // area around the vertex over its area at rest: the film thins as it grows
    float cover = 1.0f;    // share of its six triangles drawn: less where the film is torn or ends
};

struct SplashSheetMesh {
    std::vector<SheetVertex> vertices;
    std::vector<uint32_t> indices;

    void clear() {
        vertices.clear();
        indices.clear();
    }
    // Appends one sheet (all its vertices if any triangle is drawn, none otherwise).
    // A triangle stretched to more than tear_stretch times its size at rest (an edge
    // longer, or its area more than the square) has torn into spray and is left out. The sheet must be consistent (WaterView::validate).
    void append(const SheetView& sheet, float tear_stretch);
};

}  // namespace effects
