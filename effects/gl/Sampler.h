#pragma once
#include "effects/gl/Gl.h"
#include "effects/gl/Handle.h"

#include <string_view>

namespace effects::gl {

struct SamplerDeleter {
    static void destroy(GLuint name) { glDeleteSamplers(1, &name); }
};

// A sampler object: filtering and wrap apart from the texture, so that passes reading one
// shared texture each read it their own way. Bound to a unit, it overrides the state of
// whatever texture is bound there until unbound.
class Sampler {
public:
    Sampler() = default;
    static Sampler create(std::string_view label, GLenum min_filter, GLenum mag_filter, GLenum wrap);

    void bind(GLuint unit) const { glBindSampler(unit, id()); }
    // The unit's textures sample with their own state again.
    static void unbind(GLuint unit) { glBindSampler(unit, 0); }

    GLuint id() const { return handle_.get(); }

private:
    Handle<SamplerDeleter> handle_;
};

}  // namespace effects::gl
