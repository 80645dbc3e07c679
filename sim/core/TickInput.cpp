#include "sim/core/TickInput.h"

namespace sim {

std::optional<Control> control_from_name(std::string_view name) {
    for (int i = 0; i < kControlCount; ++i)
        if (kControlNames[i] == name) return static_cast<Control>(1u << i);
    return std::nullopt;
}

}  // namespace sim
