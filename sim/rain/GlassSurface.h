#pragma once
// The windshield as the rain sees it (docs/effects/rain.md, "What is implemented"): a surface ruled between
// the glass's lower and upper edge, with its own 2D coordinates in metres, u across
// from the car's left to its right, v up the glass from the lower edge. It is split
// into square cells, each with a tangent frame in car model space (gravity and air
// flow are projected per cell, so curved glass steers drops) and an affinity.
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace sim {

class Rng;

struct GlassCell {
    glm::vec3 tangent_u{1.0f, 0.0f, 0.0f};  // unit, car model space
    glm::vec3 tangent_v{0.0f, 1.0f, 0.0f};
    float affinity = 0.5f;                  // 0..1: scratches and dirt drops prefer
};

class GlassSurface {
public:
    // Throws std::invalid_argument naming what is wrong: fewer than two points per edge,
    // non-finite points, a degenerate glass, a cell size that is not positive or gives
    // more than kMaxCells cells.
    GlassSurface(std::vector<glm::vec3> lower, std::vector<glm::vec3> upper, float cell_size_m, Rng& rng);

    static constexpr int kMaxCells = 1 << 20;

    float width_m() const { return width_m_; }
    float height_m() const { return height_m_; }
    float cell_m() const { return cell_m_; }
    int cols() const { return cols_; }
    int rows() const { return rows_; }
    int cell_count() const { return cols_ * rows_; }

    // Car model space point of glass coordinates (u, v) in metres.
    glm::vec3 point(glm::vec2 uv_m) const;
    bool contains(glm::vec2 uv_m) const {
        return uv_m.x >= 0.0f && uv_m.y >= 0.0f && uv_m.x < float(cols_) * cell_m_ && uv_m.y < float(rows_) * cell_m_;
    }
    // The cell holding uv (which must be inside), and a cell's centre.
    int cell_of(glm::vec2 uv_m) const;
    glm::ivec2 cell_xy(int cell) const { return {cell % cols_, cell / cols_}; }
    glm::vec2 centre(int cell) const {
        glm::ivec2 c = cell_xy(cell);
        return (glm::vec2(c) + 0.5f) * cell_m_;
    }
    const GlassCell& cell(int index) const { return cells_[size_t(index)]; }

    // A flat glass of the given size and rake (from the horizontal), facing +x and
    // rising towards -x like a windshield; for tests and benchmarks.
    static void flat_edges(float width_m, float height_m, float rake_rad, std::vector<glm::vec3>& lower,
                           std::vector<glm::vec3>& upper);

private:
    glm::vec3 edge_point(const std::vector<glm::vec3>& edge, const std::vector<float>& at, float s) const;

    std::vector<glm::vec3> lower_, upper_;
    std::vector<float> lower_at_, upper_at_;  // each point's share of its edge's length, 0..1
    float width_m_ = 0.0f, height_m_ = 0.0f, cell_m_ = 0.0f;
    int cols_ = 0, rows_ = 0;
    std::vector<GlassCell> cells_;
};

}  // namespace sim
