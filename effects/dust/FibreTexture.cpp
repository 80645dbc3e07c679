#include "effects/dust/FibreTexture.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace effects {

namespace {

double fraction_over(const std::vector<uint8_t>& texels, float scale) {
    size_t over = 0;
    for (size_t i = 0; i < texels.size(); i += 2)
        if (float(texels[i]) / 255.0f * scale > kFibreThreshold) ++over;
    return double(over) / double(texels.size() / 2);
}

// Tiling value noise, a few octaves, in [0, 1]: the clipping luminance of seed §3.
std::vector<uint8_t> luminance_noise(int size, uint32_t seed) {
    auto lattice = [&](int x, int y, int period) {
        uint32_t h = uint32_t((x % period + period) % period) * 73856093u ^ uint32_t((y % period + period) % period) * 19349663u ^
                     (seed + uint32_t(period)) * 83492791u;
        h ^= h >> 13;
        h *= 0x5bd1e995u;
        h ^= h >> 15;
        return float(h & 0xffffu) / 65535.0f;
    };
    std::vector<float> v(size_t(size) * size_t(size), 0.0f);
    float amplitude = 0.5f, total = 0.0f;
    for (int period = 4; period <= 32 && period <= size; period *= 2) {
        float cell = float(size) / float(period);
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                float fx = float(x) / cell, fy = float(y) / cell;
                int ix = int(fx), iy = int(fy);
                float tx = fx - float(ix), ty = fy - float(iy);
                tx = tx * tx * (3.0f - 2.0f * tx);
                ty = ty * ty * (3.0f - 2.0f * ty);
                float a = lattice(ix, iy, period), b = lattice(ix + 1, iy, period);
                float c = lattice(ix, iy + 1, period), d = lattice(ix + 1, iy + 1, period);
                v[size_t(y) * size_t(size) + size_t(x)] +=
                    amplitude * ((a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty);
            }
        total += amplitude;
        amplitude *= 0.5f;
    }
    std::vector<uint8_t> out(v.size());
    for (size_t i = 0; i < v.size(); ++i) out[i] = uint8_t(std::clamp(v[i] / total, 0.0f, 1.0f) * 255.0f + 0.5f);
    return out;
}

}  // namespace

std::vector<std::vector<uint8_t>> fibre_mips(const FibreVolume& volume, int layer) {
    std::vector<std::vector<uint8_t>> levels;
    const size_t layer_bytes = size_t(volume.size) * size_t(volume.size) * 2;
    levels.emplace_back(volume.texels.begin() + std::ptrdiff_t(layer_bytes * size_t(layer)),
                        volume.texels.begin() + std::ptrdiff_t(layer_bytes * size_t(layer + 1)));
    const double target = fraction_over(levels[0], 1.0f);
    std::vector<float> coverage(levels[0].size() / 2);
    for (size_t i = 0; i < coverage.size(); ++i) coverage[i] = float(levels[0][2 * i]) / 255.0f;
    for (int size = volume.size / 2; size >= 1; size /= 2) {
        const int above = size * 2;
        std::vector<float> next(size_t(size) * size_t(size));
        std::vector<uint8_t> level(next.size() * 2);
        const std::vector<uint8_t>& prev = levels.back();
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                float c = 0.0f;
                int rank = 0;
                for (int k = 0; k < 4; ++k) {
                    size_t i = size_t(2 * y + k / 2) * size_t(above) + size_t(2 * x + k % 2);
                    c += coverage[i];
                    rank += prev[2 * i + 1];
                }
                next[size_t(y) * size_t(size) + size_t(x)] = c / 4.0f;
                level[2 * (size_t(y) * size_t(size) + size_t(x)) + 1] = uint8_t(rank / 4);
            }
        coverage = next;
        // Scale so that as many texels pass the threshold as at level 0 (bisection).
        for (size_t i = 0; i < next.size(); ++i) level[2 * i] = uint8_t(std::min(next[i], 1.0f) * 255.0f + 0.5f);
        float lo = 1.0f, hi = 16.0f;
        for (int it = 0; it < 16; ++it) {
            float mid = 0.5f * (lo + hi);
            (fraction_over(level, mid) < target ? lo : hi) = mid;
        }
        for (size_t i = 0; i < next.size(); ++i) level[2 * i] = uint8_t(std::min(next[i] * hi, 1.0f) * 255.0f + 0.5f);
        levels.push_back(std::move(level));
    }
    return levels;
}

FibreTexture::FibreTexture(const FibreVolume& volume, const char* label) {
    const int levels = gl::Texture::full_mip_levels(volume.size, volume.size);
    fibres_ = gl::Texture::create_2d_array(std::string(label) + ".fibres", GL_RG8, volume.size, volume.size,
                                           volume.layers, levels);
    for (int layer = 0; layer < volume.layers; ++layer) {
        std::vector<std::vector<uint8_t>> mips = fibre_mips(volume, layer);
        for (int level = 0; level < levels; ++level)
            fibres_.upload_layer<uint8_t>(layer, GL_RG, GL_UNSIGNED_BYTE, mips[size_t(level)], level);
    }
    fibres_.set_filter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    fibres_.set_wrap(GL_REPEAT);
    const int lum_size = 64;
    luminance_ = gl::Texture::create_2d(std::string(label) + ".luminance", GL_R8, lum_size, lum_size,
                                        gl::Texture::full_mip_levels(lum_size, lum_size));
    luminance_.upload<uint8_t>(GL_RED, GL_UNSIGNED_BYTE, luminance_noise(lum_size, 7u));
    luminance_.generate_mipmaps();
    luminance_.set_filter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    luminance_.set_wrap(GL_REPEAT);
}

}  // namespace effects
