#include "effects/gl/Sampler.h"

namespace effects::gl {

Sampler Sampler::create(std::string_view label, GLenum min_filter, GLenum mag_filter, GLenum wrap) {
    GLuint name = 0;
    glCreateSamplers(1, &name);
    Sampler sampler;
    sampler.handle_.reset(name);
    glSamplerParameteri(name, GL_TEXTURE_MIN_FILTER, GLint(min_filter));
    glSamplerParameteri(name, GL_TEXTURE_MAG_FILTER, GLint(mag_filter));
    for (GLenum axis : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glSamplerParameteri(name, axis, GLint(wrap));
    label_object(GL_SAMPLER, name, label);
    return sampler;
}

}  // namespace effects::gl
