#include "effects/dust/DustLook.h"

namespace effects {

DustLook dust_look(sim::DustKind kind) {
    DustLook look;
    switch (kind) {
        case sim::DustKind::Dust:  // short grey lint lying in a felt, a few fibres climbing
            look.colour = {0.62f, 0.59f, 0.54f};
            look.deep_colour = {0.34f, 0.32f, 0.29f};
            look.height_m = 0.018f;
            look.tile_m = 0.25f;  // 2 mm texels: a fibre of 30 steps spans at most 6 cm
            look.growth = {.fibres = 1600, .steps = 30, .bend_probability = 0.08f, .direction_bias = 4.0f, .climb = 0.2f};
            break;
        case sim::DustKind::Sand:  // grains: short walks that curl up into blobs
            look.colour = {0.60f, 0.49f, 0.32f};
            look.deep_colour = {0.30f, 0.23f, 0.14f};
            look.height_m = 0.015f;
            look.tile_m = 0.2f;
            look.bumpiness = 0.5f;
            look.growth = {.fibres = 5000, .steps = 5, .bend_probability = 0.6f, .direction_bias = 0.0f, .climb = 0.6f,
                           .bottom_heavy = 3.0f};
            break;
        case sim::DustKind::Mould:  // short hyphae that climb and branch often
            look.colour = {0.30f, 0.36f, 0.22f};
            look.deep_colour = {0.05f, 0.08f, 0.04f};
            look.height_m = 0.012f;
            look.tile_m = 0.15f;
            look.bumpiness = 1.0f;
            look.growth = {.fibres = 1600, .steps = 18, .bend_probability = 0.2f, .direction_bias = 2.0f, .climb = 0.7f,
                           .bottom_heavy = 1.5f};
            break;
    }
    look.growth.seed = 0x6475737400ull + uint64_t(kind);
    return look;
}

}  // namespace effects
