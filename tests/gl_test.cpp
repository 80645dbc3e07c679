// GL wrappers on a real headless context (Mesa llvmpipe here and in CI).
#include "ErrorMessage.h"
#include "effects/gl/Buffer.h"
#include "effects/gl/DebugGroup.h"
#include "effects/gl/DebugOutput.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/PassTimer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "effects/gl/VertexArray.h"
#include "game/capture/Readback.h"
#include "game/platform/HeadlessContext.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstring>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>

using namespace effects::gl;

namespace {

constexpr const char* kFullScreenVert = R"(#version 450 core
void main() {
    // One triangle covering the viewport: (-1,-1), (3,-1), (-1,3).
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

constexpr const char* kSolidFrag = R"(#version 450 core
uniform vec4 u_colour;
out vec4 colour;
void main() { colour = u_colour; }
)";

std::array<int, 4> rgba_at(const game::ImageRGBA8& image, int x, int y) {
    const std::uint8_t* p = &image.pixels[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
    return {p[0], p[1], p[2], p[3]};
}

// Colour target with its framebuffer, bound with the viewport set.
struct Target {
    Target(int w, int h, GLenum format = GL_RGBA8)
        : width(w), height(h),
          colour(Texture::create_2d("test colour", format, w, h)),
          fbo(Framebuffer::create("test target")) {
        fbo.attach_colour(0, colour);
        fbo.check_complete();
        fbo.bind();
        glViewport(0, 0, w, h);
    }
    int width, height;
    Texture colour;
    Framebuffer fbo;
};

}  // namespace

class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        context_ = std::make_unique<game::HeadlessContext>(game::HeadlessContext::Options{true});
        std::cout << "GL_RENDERER: " << context_->renderer() << "\nGL_VERSION: "
                  << context_->version() << "\n";
    }
    static void TearDownTestSuite() { context_.reset(); }
    void SetUp() override {
        ASSERT_TRUE(context_);
        context_->make_current();
        empty_vao_ = VertexArray::create("empty (gl_VertexID draws)");
        empty_vao_.bind();
    }
    void TearDown() override {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    }

    static void draw_full_screen() { glDrawArrays(GL_TRIANGLES, 0, 3); }

    static std::unique_ptr<game::HeadlessContext> context_;
    VertexArray empty_vao_;
};

std::unique_ptr<game::HeadlessContext> GlTest::context_;

TEST_F(GlTest, ContextIsOpenGl45Core) {
    EXPECT_FALSE(context_->renderer().empty());
    GLint major = 0, minor = 0, profile = 0, flags = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
    EXPECT_GE(major * 10 + minor, 45);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
    EXPECT_TRUE(flags & GL_CONTEXT_FLAG_DEBUG_BIT);
}

TEST_F(GlTest, ASecondContextComesAndGoesWithoutBreakingTheFirst) {
    {
        game::HeadlessContext other;
        EXPECT_FALSE(other.debug());
        EXPECT_EQ(other.renderer(), context_->renderer());
    }
    context_->make_current();
    Target target(4, 4);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    EXPECT_EQ(rgba_at(game::read_framebuffer_rgba8(target.fbo.id(), 4, 4), 1, 1),
              (std::array<int, 4>{0, 255, 0, 255}));
}

TEST_F(GlTest, SolidColourFullScreenTriangleReadsBack) {
    Target target(64, 48);
    const Program program = Program::from_sources(
        "solid", {{GL_VERTEX_SHADER, kFullScreenVert}, {GL_FRAGMENT_SHADER, kSolidFrag}});
    program.use();
    program.set("u_colour", glm::vec4(1.0f, 0.5f, 0.0f, 1.0f));
    draw_full_screen();
    const game::ImageRGBA8 image = game::read_framebuffer_rgba8(target.fbo.id(), 64, 48);
    ASSERT_EQ(image.width, 64);
    ASSERT_EQ(image.height, 48);
    ASSERT_EQ(image.pixels.size(), 64u * 48u * 4u);
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            const auto p = rgba_at(image, x, y);
            ASSERT_EQ(p[0], 255);
            ASSERT_NEAR(p[1], 128, 1);
            ASSERT_EQ(p[2], 0);
            ASSERT_EQ(p[3], 255);
        }
}

TEST_F(GlTest, TopHalfDrawnFromAVertexBufferIsRowZeroOfTheReadback) {
    Target target(16, 10);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);

    // Quad over NDC y in [0, 1]: the top half of the image.
    const std::array<float, 12> corners = {-1, 0, 1, 0, 1, 1, -1, 0, 1, 1, -1, 1};
    const Buffer vertices = Buffer::create<float>("top half quad", corners, 0);
    VertexArray vao = VertexArray::create("top half quad");
    vao.attribute(0, 0, 2, GL_FLOAT, 0);
    vao.vertex_buffer(0, vertices, 0, 2 * sizeof(float));
    vao.bind();
    const Program program = Program::from_sources("top half", {{GL_VERTEX_SHADER, R"(#version 450 core
layout(location = 0) in vec2 position;
void main() { gl_Position = vec4(position, 0.0, 1.0); }
)"}, {GL_FRAGMENT_SHADER, kSolidFrag}});
    program.use();
    program.set("u_colour", glm::vec4(1, 0, 0, 1));
    glDrawArrays(GL_TRIANGLES, 0, 6);

    const game::ImageRGBA8 image = game::read_framebuffer_rgba8(target.fbo.id(), 16, 10);
    for (int x = 0; x < 16; ++x) {
        EXPECT_EQ(rgba_at(image, x, 0), (std::array<int, 4>{255, 0, 0, 255})) << "top row, x " << x;
        EXPECT_EQ(rgba_at(image, x, 4), (std::array<int, 4>{255, 0, 0, 255}));
        EXPECT_EQ(rgba_at(image, x, 5), (std::array<int, 4>{0, 0, 255, 255}));
        EXPECT_EQ(rgba_at(image, x, 9), (std::array<int, 4>{0, 0, 255, 255})) << "bottom row";
    }
}

TEST_F(GlTest, EveryUniformSetterReachesTheShader) {
    Target target(4, 4);
    const Program program = Program::from_sources("uniforms", {{GL_VERTEX_SHADER, kFullScreenVert},
                                                               {GL_FRAGMENT_SHADER, R"(#version 450 core
uniform int u_int; uniform uint u_uint; uniform float u_float;
uniform vec2 u_vec2; uniform vec3 u_vec3; uniform vec4 u_vec4; uniform ivec2 u_ivec2;
uniform mat3 u_mat3; uniform mat4 u_mat4;
out vec4 colour;
void main() {
    colour.r = u_float * float(u_int) + float(u_uint) * 0.1 + float(u_ivec2.y) * 0.01;
    colour.g = u_vec2.y + u_vec3.z + u_vec4.w;
    colour.b = (u_mat3 * vec3(0.0, 0.0, 1.0)).x;  // column 2, row 0
    colour.a = (u_mat4 * vec4(0.0, 1.0, 0.0, 0.0)).z;  // column 1, row 2
}
)"}});
    program.set("u_int", 2);
    program.set("u_uint", 1u);
    program.set("u_float", 0.2f);
    program.set("u_ivec2", glm::ivec2(0, 5));
    program.set("u_vec2", glm::vec2(0.0f, 0.1f));
    program.set("u_vec3", glm::vec3(0.0f, 0.0f, 0.2f));
    program.set("u_vec4", glm::vec4(0.0f, 0.0f, 0.0f, 0.3f));
    glm::mat3 m3(0.0f);
    m3[2][0] = 0.8f;
    program.set("u_mat3", m3);
    glm::mat4 m4(0.0f);
    m4[1][2] = 0.4f;
    program.set("u_mat4", m4);
    // Names the compiler removed or never saw are ignored, and cached as absent.
    EXPECT_NO_THROW(program.set("u_not_there", 1.0f));
    EXPECT_EQ(program.location("u_not_there"), -1);
    EXPECT_GE(program.location("u_mat4"), 0);

    program.use();
    draw_full_screen();
    const auto p = rgba_at(game::read_framebuffer_rgba8(target.fbo.id(), 4, 4), 2, 2);
    EXPECT_NEAR(p[0], 0.55 * 255, 1);
    EXPECT_NEAR(p[1], 0.6 * 255, 1);
    EXPECT_NEAR(p[2], 0.8 * 255, 1);
    EXPECT_NEAR(p[3], 0.4 * 255, 1);
}

TEST_F(GlTest, CompileErrorNamesTheFileAndQuotesTheLog) {
    const std::string error = message_of([] {
        Program::from_sources("broken", {{GL_VERTEX_SHADER, kFullScreenVert, "test/fullscreen.vert.glsl"},
                                         {GL_FRAGMENT_SHADER, R"(#version 450 core
out vec4 colour;
void main() {
    colour = vec4(undeclared_thing, 1.0);
}
)", "test/broken.frag.glsl"}});
    });
    EXPECT_NE(error.find("shader compile failed: test/broken.frag.glsl"), std::string::npos) << error;
    EXPECT_NE(error.find("'broken'"), std::string::npos) << error;
    EXPECT_NE(error.find("undeclared_thing"), std::string::npos) << error;
    // The offending line, quoted with its number.
    EXPECT_NE(error.find("4 |     colour = vec4(undeclared_thing, 1.0);"), std::string::npos) << error;
}

TEST_F(GlTest, LinkErrorNamesTheProgramAndItsFiles) {
    const std::string error = message_of([] {
        Program::from_sources("unlinked", {{GL_VERTEX_SHADER, kFullScreenVert, "a.vert.glsl"},
                                           {GL_FRAGMENT_SHADER, R"(#version 450 core
vec4 shade();  // declared, defined nowhere
out vec4 colour;
void main() { colour = shade(); }
)", "b.frag.glsl"}});
    });
    EXPECT_NE(error.find("program link failed: 'unlinked' (a.vert.glsl, b.frag.glsl)"),
              std::string::npos)
        << error;
    EXPECT_NE(error.find("shade"), std::string::npos) << error;
}

TEST_F(GlTest, ProgramFromFilesNamesMissingShadersAndStages) {
    const std::string error = message_of(
        [] { Program::from_files("missing", {"test/does_not_exist.frag.glsl"}); });
    EXPECT_NE(error.find("shaders/test/does_not_exist.frag.glsl"), std::string::npos) << error;
    EXPECT_NE(error.find("'missing'"), std::string::npos) << error;

    EXPECT_EQ(Program::stage_from_path("scene/mesh.vert.glsl"), static_cast<GLenum>(GL_VERTEX_SHADER));
    EXPECT_EQ(Program::stage_from_path("water/step.comp.glsl"), static_cast<GLenum>(GL_COMPUTE_SHADER));
    EXPECT_EQ(Program::stage_from_path("a/b.geom"), static_cast<GLenum>(GL_GEOMETRY_SHADER));
    EXPECT_THROW(Program::stage_from_path("scene/mesh.glsl"), std::invalid_argument);
    EXPECT_THROW(Program::from_sources("none", {}), std::invalid_argument);
}

TEST_F(GlTest, MultipleColourAttachmentsAndFloatReadback) {
    const Texture hdr = Texture::create_2d("hdr", GL_RGBA32F, 8, 8);
    const Texture ldr = Texture::create_2d("ldr", GL_RGBA8, 8, 8);
    Framebuffer fbo = Framebuffer::create("two targets");
    fbo.attach_colour(0, hdr);
    fbo.attach_colour(1, ldr);
    fbo.check_complete();
    fbo.bind();
    glViewport(0, 0, 8, 8);
    const Program program = Program::from_sources("mrt", {{GL_VERTEX_SHADER, kFullScreenVert},
                                                          {GL_FRAGMENT_SHADER, R"(#version 450 core
layout(location = 0) out vec4 hdr;
layout(location = 1) out vec4 ldr;
void main() { hdr = vec4(0.25, 0.5, 1.5, 7.0); ldr = vec4(0.0, 1.0, 0.0, 1.0); }
)"}});
    program.use();
    draw_full_screen();

    const game::ImageRGBA32F floats =
        game::read_framebuffer_rgba32f(fbo.id(), GL_COLOR_ATTACHMENT0, 8, 8);
    ASSERT_EQ(floats.pixels.size(), 8u * 8u * 4u);
    EXPECT_EQ(floats.pixels[0], 0.25f);
    EXPECT_EQ(floats.pixels[1], 0.5f);
    EXPECT_EQ(floats.pixels[2], 1.5f) << "float targets are not clamped";
    EXPECT_EQ(floats.pixels[3], 7.0f);
    EXPECT_EQ(rgba_at(game::read_framebuffer_rgba8(fbo.id(), 8, 8, GL_COLOR_ATTACHMENT1), 3, 3),
              (std::array<int, 4>{0, 255, 0, 255}));
}

TEST_F(GlTest, DepthAttachmentReadsBackTopDown) {
    const Texture colour = Texture::create_2d("colour", GL_RGBA8, 6, 4);
    const Texture depth = Texture::create_2d("depth", GL_DEPTH_COMPONENT32F, 6, 4);
    Framebuffer fbo = Framebuffer::create("with depth");
    fbo.attach_colour(0, colour);
    fbo.attach_depth(depth);
    fbo.check_complete();
    fbo.bind();
    glViewport(0, 0, 6, 4);
    glEnable(GL_DEPTH_TEST);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // Top half at NDC z = 0 (window depth 0.5), the rest keeps the cleared 1.0.
    const Program program = Program::from_sources("depth", {{GL_VERTEX_SHADER, R"(#version 450 core
void main() {
    vec2 corners[6] = vec2[](vec2(-1, 0), vec2(1, 0), vec2(1, 1), vec2(-1, 0), vec2(1, 1), vec2(-1, 1));
    gl_Position = vec4(corners[gl_VertexID], 0.0, 1.0);
}
)"}, {GL_FRAGMENT_SHADER, kSolidFrag}});
    program.use();
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glDisable(GL_DEPTH_TEST);

    const std::vector<float> values = game::read_depth(fbo.id(), 6, 4);
    ASSERT_EQ(values.size(), 24u);
    EXPECT_FLOAT_EQ(values[0], 0.5f) << "row 0 is the top";
    EXPECT_FLOAT_EQ(values[6 * 1 + 5], 0.5f);
    EXPECT_FLOAT_EQ(values[6 * 2], 1.0f);
    EXPECT_FLOAT_EQ(values[6 * 3 + 5], 1.0f);

    // Reading depth from a target without depth is a clear error, not garbage.
    Target no_depth(2, 2);
    EXPECT_THROW(game::read_depth(no_depth.fbo.id(), 2, 2), std::runtime_error);
    EXPECT_THROW(game::read_framebuffer_rgba8(no_depth.fbo.id(), 0, 2), std::invalid_argument);
}

TEST_F(GlTest, IncompleteFramebufferNamesItsStatus) {
    Framebuffer empty = Framebuffer::create("nothing attached");
    const std::string error = message_of([&] { empty.check_complete(); });
    EXPECT_NE(error.find("'nothing attached'"), std::string::npos) << error;
    EXPECT_NE(error.find("GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"), std::string::npos) << error;

    const Texture colour = Texture::create_2d("rgba", GL_RGBA8, 2, 2);
    EXPECT_THROW(empty.attach_depth(colour), std::invalid_argument);
    EXPECT_THROW(empty.attach_colour(-1, colour), std::out_of_range);
    EXPECT_THROW(empty.attach_colour_layer(0, colour, 0), std::out_of_range);

    // Depth only (a shadow map) is complete with no colour at all.
    const Texture shadow = Texture::create_2d("shadow", GL_DEPTH_COMPONENT24, 16, 16);
    Framebuffer depth_only = Framebuffer::create("shadow map");
    depth_only.attach_depth(shadow);
    EXPECT_NO_THROW(depth_only.check_complete());
}

TEST_F(GlTest, TextureUploadRowZeroIsTheBottom) {
    Texture texture = Texture::create_2d("uploaded", GL_RGBA8, 3, 2);
    // GL order: first row uploaded is the bottom row.
    const std::array<std::uint8_t, 24> pixels = {
        10, 0, 0, 255, 20, 0, 0, 255, 30, 0, 0, 255,   // bottom
        0, 40, 0, 255, 0, 50, 0, 255, 0, 60, 0, 255};  // top
    texture.upload<std::uint8_t>(GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    Framebuffer fbo = Framebuffer::create("read uploaded");
    fbo.attach_colour(0, texture);
    const game::ImageRGBA8 image = game::read_framebuffer_rgba8(fbo.id(), 3, 2);
    EXPECT_EQ(rgba_at(image, 0, 0), (std::array<int, 4>{0, 40, 0, 255}));
    EXPECT_EQ(rgba_at(image, 2, 1), (std::array<int, 4>{30, 0, 0, 255}));

    EXPECT_THROW(texture.upload<std::uint8_t>(GL_RGBA, GL_UNSIGNED_BYTE,
                                              std::span(pixels).first(20)),
                 std::invalid_argument);
    EXPECT_THROW(texture.upload<std::uint8_t>(GL_RGBA, GL_UNSIGNED_BYTE, pixels, 1), std::out_of_range);
    EXPECT_THROW(Texture::create_2d("too big", GL_RGBA8, 1 << 20, 4), std::invalid_argument);
    EXPECT_THROW(Texture::create_2d("zero", GL_RGBA8, 0, 4), std::invalid_argument);
    EXPECT_THROW(Texture::create_2d("mips", GL_RGBA8, 4, 4, 4), std::invalid_argument);
    EXPECT_EQ(Texture::full_mip_levels(4, 4), 3);
    EXPECT_EQ(Texture::full_mip_levels(1024, 3), 11);
    EXPECT_THROW(Texture::create_2d("bad format", GL_RGBA, 4, 4), std::invalid_argument);
    while (glGetError() != GL_NO_ERROR) {
    }  // the refused format left a GL error behind by design
}

TEST_F(GlTest, ArrayLayersAndCubeFacesUploadAndAttach) {
    Texture array = Texture::create_2d_array("layers", GL_RGBA8, 2, 2, 3);
    EXPECT_EQ(array.layers(), 3);
    const std::array<std::uint8_t, 16> magenta = {255, 0, 255, 255, 255, 0, 255, 255,
                                                  255, 0, 255, 255, 255, 0, 255, 255};
    array.upload_layer<std::uint8_t>(2, GL_RGBA, GL_UNSIGNED_BYTE, magenta);
    EXPECT_THROW(array.upload_layer<std::uint8_t>(3, GL_RGBA, GL_UNSIGNED_BYTE, magenta),
                 std::out_of_range);
    Framebuffer fbo = Framebuffer::create("layer reader");
    fbo.attach_colour_layer(0, array, 2);
    EXPECT_EQ(rgba_at(game::read_framebuffer_rgba8(fbo.id(), 2, 2), 1, 1),
              (std::array<int, 4>{255, 0, 255, 255}));

    Texture cube = Texture::create_cube("sky", GL_RGBA8, 2);
    EXPECT_EQ(cube.layers(), 6);
    EXPECT_EQ(cube.width(), 2);
    EXPECT_EQ(cube.height(), 2);
    const std::array<std::uint8_t, 16> teal = {0, 128, 128, 255, 0, 128, 128, 255,
                                               0, 128, 128, 255, 0, 128, 128, 255};
    cube.upload_layer<std::uint8_t>(4, GL_RGBA, GL_UNSIGNED_BYTE, teal);  // +Z
    Framebuffer face = Framebuffer::create("face reader");
    face.attach_colour_layer(0, cube, 4);
    EXPECT_EQ(rgba_at(game::read_framebuffer_rgba8(face.id(), 2, 2), 0, 0),
              (std::array<int, 4>{0, 128, 128, 255}));
    EXPECT_THROW(cube.upload<std::uint8_t>(GL_RGBA, GL_UNSIGNED_BYTE, teal), std::logic_error);
}

TEST_F(GlTest, SamplerHelpersSetTheTextureState) {
    Texture shadow = Texture::create_2d("shadow", GL_DEPTH_COMPONENT32F, 8, 8);
    EXPECT_TRUE(shadow.is_depth());
    shadow.set_depth_compare(true, GL_GEQUAL);
    shadow.set_filter(GL_NEAREST, GL_NEAREST);
    shadow.set_wrap(GL_CLAMP_TO_BORDER);
    shadow.set_border_colour({1, 1, 1, 1});
    auto param = [&](GLenum name) {
        GLint value = 0;
        glGetTextureParameteriv(shadow.id(), name, &value);
        return value;
    };
    EXPECT_EQ(param(GL_TEXTURE_COMPARE_MODE), GL_COMPARE_REF_TO_TEXTURE);
    EXPECT_EQ(param(GL_TEXTURE_COMPARE_FUNC), GL_GEQUAL);
    EXPECT_EQ(param(GL_TEXTURE_MIN_FILTER), GL_NEAREST);
    EXPECT_EQ(param(GL_TEXTURE_MAG_FILTER), GL_NEAREST);
    EXPECT_EQ(param(GL_TEXTURE_WRAP_S), GL_CLAMP_TO_BORDER);
    EXPECT_EQ(param(GL_TEXTURE_WRAP_R), GL_CLAMP_TO_BORDER);
    shadow.set_depth_compare(false);
    EXPECT_EQ(param(GL_TEXTURE_COMPARE_MODE), GL_NONE);

    char label[64] = {};
    glGetObjectLabel(GL_TEXTURE, shadow.id(), sizeof label, nullptr, label);
    EXPECT_STREQ(label, "shadow");
}

TEST_F(GlTest, BufferUpdatesAndRefusesBadRanges) {
    const std::array<std::uint32_t, 4> initial = {1, 2, 3, 4};
    Buffer buffer = Buffer::create<std::uint32_t>("numbers", initial);
    EXPECT_EQ(buffer.size(), 16);
    const std::array<std::uint32_t, 2> change = {7, 8};
    buffer.update<std::uint32_t>(8, change);
    std::array<std::uint32_t, 4> back = {};
    glGetNamedBufferSubData(buffer.id(), 0, 16, back.data());
    EXPECT_EQ(back, (std::array<std::uint32_t, 4>{1, 2, 7, 8}));

    EXPECT_THROW(buffer.update<std::uint32_t>(12, change), std::out_of_range);
    EXPECT_THROW(buffer.update<std::uint32_t>(-4, change), std::out_of_range);
    Buffer fixed = Buffer::create<std::uint32_t>("fixed", initial, 0);
    EXPECT_THROW(fixed.update<std::uint32_t>(0, change), std::logic_error);
    EXPECT_THROW(Buffer::create("empty", 0), std::invalid_argument);

    // Handles move ownership and delete on destruction.
    const GLuint name = buffer.id();
    Buffer moved = std::move(buffer);
    EXPECT_EQ(buffer.id(), 0u);  // NOLINT(bugprone-use-after-move): checking the moved-from state
    EXPECT_EQ(moved.id(), name);
    EXPECT_TRUE(glIsBuffer(name));
    moved = Buffer();
    EXPECT_FALSE(glIsBuffer(name));
}

TEST_F(GlTest, DebugGroupsPushAndPop) {
    GLint depth = 0;
    glGetIntegerv(GL_DEBUG_GROUP_STACK_DEPTH, &depth);
    const GLint base = depth;
    {
        DebugGroup outer("outer pass");
        {
            DebugGroup inner(std::string(1000, 'x'));  // long names are cut, not an error
            glGetIntegerv(GL_DEBUG_GROUP_STACK_DEPTH, &depth);
            EXPECT_EQ(depth, base + 2);
        }
        glGetIntegerv(GL_DEBUG_GROUP_STACK_DEPTH, &depth);
        EXPECT_EQ(depth, base + 1);
    }
    glGetIntegerv(GL_DEBUG_GROUP_STACK_DEPTH, &depth);
    EXPECT_EQ(depth, base);
}

TEST_F(GlTest, DebugOutputPrintsEachDistinctMessageOnce) {
    std::ostringstream sink;
    {
        DebugOutput output(sink);
        for (int i = 0; i < 3; ++i) glEnable(0xFFFF);  // the same invalid enum, three times
        glBindBuffer(0x1234, 0);                       // a different error
        EXPECT_EQ(output.printed(), 2u) << sink.str();
        EXPECT_EQ(output.suppressed(), 2u) << sink.str();
        DebugGroup group("notifications are not printed");
    }
    while (glGetError() != GL_NO_ERROR) {
    }
    const std::string text = sink.str();
    EXPECT_NE(text.find("GL HIGH error"), std::string::npos) << text;
    EXPECT_NE(text.find("glEnable"), std::string::npos) << text;
    EXPECT_EQ(text.find("notifications"), std::string::npos) << text;
    // Uninstalled: nothing more arrives.
    glEnable(0xFFFE);
    while (glGetError() != GL_NO_ERROR) {
    }
    EXPECT_EQ(sink.str(), text);
}

TEST_F(GlTest, PassTimerProfileModeTimesNamedPasses) {
    Target target(32, 32);
    const Program program = Program::from_sources(
        "timed", {{GL_VERTEX_SHADER, kFullScreenVert}, {GL_FRAGMENT_SHADER, kSolidFrag}});
    program.use();
    PassTimer timer(TimingMode::Profile);
    for (int frame = 0; frame < 3; ++frame) {
        timer.frame_begin();
        {
            auto pass = timer.scope("triangle");
            draw_full_screen();
        }
        timer.begin("clear");
        glClear(GL_COLOR_BUFFER_BIT);
        timer.end();
        timer.frame_end();
        ASSERT_EQ(timer.results().size(), 2u);
        EXPECT_EQ(timer.results()[0].name, "triangle");
        EXPECT_EQ(timer.results()[1].name, "clear");
        for (const PassTime& pass : timer.results()) {
            EXPECT_GE(pass.ms, 0.0);
            EXPECT_GE(pass.average_ms, 0.0);
        }
    }
    EXPECT_EQ(timer.completed_frames(), 3u);
    ASSERT_TRUE(timer.average_ms("triangle").has_value());
    EXPECT_FALSE(timer.average_ms("never ran").has_value());

    EXPECT_THROW(timer.begin("outside a frame"), std::logic_error);
    timer.frame_begin();
    EXPECT_THROW(timer.end(), std::logic_error);
    timer.begin("a");
    EXPECT_THROW(timer.begin("nested"), std::logic_error);
    EXPECT_THROW(timer.frame_end(), std::logic_error);
    timer.end();
    timer.frame_end();
}

TEST_F(GlTest, PassTimerGpuQueriesArriveWithinTheLatency) {
    Target target(32, 32);
    const Program program = Program::from_sources(
        "timed", {{GL_VERTEX_SHADER, kFullScreenVert}, {GL_FRAGMENT_SHADER, kSolidFrag}});
    program.use();
    PassTimer timer(TimingMode::GpuQueries);
    const int frames = 2 * PassTimer::kLatencyFrames;
    for (int frame = 0; frame < frames; ++frame) {
        timer.frame_begin();
        { auto pass = timer.scope("first"); draw_full_screen(); }
        { auto pass = timer.scope("second"); draw_full_screen(); }
        timer.frame_end();
    }
    // frame_begin waits for the frame kLatencyFrames back, so at least these are in.
    EXPECT_GE(timer.completed_frames(), std::uint64_t(frames - PassTimer::kLatencyFrames));
    ASSERT_EQ(timer.results().size(), 2u);
    EXPECT_EQ(timer.results()[0].name, "first");
    EXPECT_EQ(timer.results()[1].name, "second");
    EXPECT_GE(timer.results()[0].ms, 0.0);
    EXPECT_TRUE(timer.average_ms("second").has_value());
}

TEST_F(GlTest, PassTimerSampledMeasuresOnePassAFrameInTurn) {
    Target target(32, 32);
    const Program program = Program::from_sources(
        "timed", {{GL_VERTEX_SHADER, kFullScreenVert}, {GL_FRAGMENT_SHADER, kSolidFrag}});
    program.use();
    PassTimer timer(TimingMode::Sampled);
    const auto frame = [&] {
        timer.frame_begin();
        { auto pass = timer.scope("draw"); draw_full_screen(); }
        {
            // Wall time a pass takes counts, whatever the GPU timer would say.
            auto pass = timer.scope("wait");
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        { auto pass = timer.scope("clear"); glClear(GL_COLOR_BUFFER_BIT); }
        timer.frame_end();
    };
    // The first frame (shader compiles) is not measured, then one more pass each frame.
    frame();
    EXPECT_TRUE(timer.results().empty());
    EXPECT_FALSE(timer.average_ms("draw").has_value());
    frame();
    ASSERT_EQ(timer.results().size(), 1u);
    EXPECT_EQ(timer.results()[0].name, "draw");
    frame();
    ASSERT_EQ(timer.results().size(), 2u);
    EXPECT_EQ(timer.results()[1].name, "wait");
    EXPECT_GE(timer.results()[1].ms, 5.0);
    frame();
    ASSERT_EQ(timer.results().size(), 3u);
    EXPECT_EQ(timer.results()[2].name, "clear");
    for (int i = 0; i < 6; ++i) frame();
    // In frame order, each with its latest time and average.
    ASSERT_EQ(timer.results().size(), 3u);
    EXPECT_EQ(timer.results()[0].name, "draw");
    EXPECT_EQ(timer.results()[2].name, "clear");
    EXPECT_GE(*timer.average_ms("wait"), 5.0);
    EXPECT_EQ(timer.completed_frames(), 10u);
    EXPECT_THROW(timer.end(), std::logic_error);
}
