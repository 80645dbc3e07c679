#include "effects/dust/FibreDirections.h"

#include <stdexcept>
#include <string>

namespace effects {

glm::ivec3 FibreDirections::offset(int k) {
    // The 27 cells of the neighbourhood in x-fastest order, skipping the centre (13).
    int cell = k < 13 ? k : k + 1;
    return {cell % 3 - 1, (cell / 3) % 3 - 1, cell / 9 - 1};
}

bool FibreDirections::empty() const {
    float sum = 0.0f;
    for (float p : probability) sum += p;
    return !(sum > 0.0f);
}

FibreDirections analyse_fibre_pixels(int width, int slice_height, int slices, std::span<const uint8_t> fibre) {
    if (width < 1 || slice_height < 1 || slices < 1 ||
        fibre.size() != size_t(width) * size_t(slice_height) * size_t(slices))
        throw std::invalid_argument("fibre image: " + std::to_string(fibre.size()) + " pixels do not make " +
                                    std::to_string(slices) + " slices of " + std::to_string(width) + "x" +
                                    std::to_string(slice_height));
    auto at = [&](int x, int y, int s) {
        return fibre[(size_t(s) * size_t(slice_height) + size_t(y)) * size_t(width) + size_t(x)] != 0;
    };
    std::array<uint64_t, FibreDirections::kCount> counts{};
    uint64_t total = 0;
    for (int s = 0; s < slices; ++s)
        for (int y = 0; y < slice_height; ++y)
            for (int x = 0; x < width; ++x) {
                if (!at(x, y, s)) continue;
                for (int k = 0; k < FibreDirections::kCount; ++k) {
                    glm::ivec3 d = FibreDirections::offset(k);
                    int nx = x + d.x, ny = y + d.y, ns = s + d.z;
                    if (nx < 0 || ny < 0 || ns < 0 || nx >= width || ny >= slice_height || ns >= slices) continue;
                    if (at(nx, ny, ns)) {
                        ++counts[size_t(k)];
                        ++total;
                    }
                }
            }
    if (total == 0)
        throw std::invalid_argument("fibre image: no two fibre pixels touch, so there are no growth directions to learn");
    FibreDirections out;
    for (int k = 0; k < FibreDirections::kCount; ++k) out.probability[size_t(k)] = float(double(counts[size_t(k)]) / double(total));
    return out;
}

}  // namespace effects
