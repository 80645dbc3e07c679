#pragma once
// One step of the frame. The renderer runs its passes in the order of PassList.cpp,
// each inside a debug group and a timer named after it.
#include <string_view>

#include "effects/scene/FrameContext.h"
#include "effects/scene/ParamRegistry.h"

namespace effects {

class Pass {
public:
    virtual ~Pass() = default;
    virtual std::string_view name() const = 0;
    virtual void resize(int /*width*/, int /*height*/) {}
    virtual void render(const FrameContext& frame) = 0;
    virtual void register_params(ParamRegistry&) {}
};

}  // namespace effects
