// The props merged into few draws at level load (effects/scene/StaticBatches): every
// prop triangle drawn once when the view holds the level, none when it holds none of it,
// and a batch kept or left whole by the view and the caller's selection.
#include <set>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

#include "HeadlessTest.h"
#include "effects/gl/DrawCount.h"
#include "effects/gl/Framebuffer.h"
#include "effects/gl/Program.h"
#include "effects/gl/Texture.h"
#include "effects/scene/StaticBatches.h"
#include "game/session/GameSession.h"

namespace {

class StaticBatchesTest : public HeadlessTest {
protected:
    void SetUp() override {
        HeadlessTest::SetUp();
        depth_ = effects::gl::Texture::create_2d("test.depth", GL_DEPTH_COMPONENT32F, 64, 64);
        fbo_ = effects::gl::Framebuffer::create("test.depth");
        fbo_.attach_depth(depth_);
        fbo_.set_draw_buffers({});
        fbo_.check_complete();
        fbo_.bind();
        glViewport(0, 0, 64, 64);
    }
    // What `draw` sends through GL.
    template <class Draw>
    effects::gl::DrawCount counted(Draw&& draw) {
        const effects::gl::DrawCount before = effects::gl::draw_count();
        draw();
        const effects::gl::DrawCount after = effects::gl::draw_count();
        return {after.draws - before.draws, after.triangles - before.triangles};
    }

    effects::gl::Texture depth_;
    effects::gl::Framebuffer fbo_;
    const effects::gl::Program program_ =
        effects::gl::Program::from_files("test.depth", {"scene/mesh.vert.glsl", "scene/depth_only.frag.glsl"});
};

// Looking straight down on the whole level (the harbour is 320 m across).
effects::Frustum whole_level() {
    return effects::Frustum(glm::ortho(-400.0f, 400.0f, -400.0f, 400.0f, 1.0f, 800.0f) *
                            glm::lookAt(glm::vec3(0.0f, 400.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f)));
}

TEST_F(StaticBatchesTest, EveryPropTriangleOnceInFarFewerDraws) {
    const game::GameSession s = game::GameSession::open("harbour", 1);
    const effects::SceneDesc& scene = s.level.scene;
    uint64_t triangles = 0, meshes = 0;
    std::set<std::tuple<float, float, float, float, float>> materials;
    for (const effects::PropInstance& prop : scene.props)
        for (const effects::MeshData& mesh : scene.models[size_t(prop.model)].meshes) {
            triangles += mesh.indices.size() / 3;
            meshes += !mesh.indices.empty();
            materials.insert({mesh.roughness, mesh.metallic, mesh.emissive.x, mesh.emissive.y, mesh.emissive.z});
        }
    const effects::StaticBatches batches(scene);
    const effects::gl::DrawCount all = counted([&] { batches.draw(program_, true, whole_level()); });
    EXPECT_EQ(all.triangles, triangles);
    EXPECT_EQ(all.draws, batches.size());
    // A draw a mesh before (196 in the harbour); now a draw per material and square (67).
    EXPECT_GE(batches.size(), materials.size());
    EXPECT_LT(batches.size() * 2, meshes);
    // Squares larger than the level: a draw per material in each quarter around the origin.
    const effects::StaticBatches coarse(scene, 1000.0f);
    EXPECT_GE(coarse.size(), materials.size());
    EXPECT_LE(coarse.size(), 4 * materials.size());
    EXPECT_EQ(counted([&] { coarse.draw(program_, true, whole_level()); }).triangles, triangles);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(StaticBatchesTest, TheViewAndTheSelectionKeepOrLeaveWholeBatches) {
    const game::GameSession s = game::GameSession::open("harbour", 1);
    const effects::StaticBatches batches(s.level.scene);
    // Straight up from far above the level: nothing of it.
    const effects::Frustum sky(glm::perspective(0.8f, 1.0f, 0.1f, 500.0f) *
                               glm::lookAt(glm::vec3(0.0f, 1000.0f, 0.0f), glm::vec3(0.0f, 2000.0f, 0.0f),
                                           glm::vec3(0.0f, 0.0f, -1.0f)));
    EXPECT_EQ(counted([&] { batches.draw(program_, true, sky); }).draws, 0u);
    EXPECT_EQ(counted([&] { batches.draw(program_, true, whole_level(), [](glm::vec3, glm::vec3) { return false; }); }).draws,
              0u);
    // West and east of x = 0 by each batch's box centre: every batch in exactly one.
    const auto west = [](glm::vec3 lo, glm::vec3 hi) { return lo.x + hi.x < 0.0f; };
    const auto east = [](glm::vec3 lo, glm::vec3 hi) { return lo.x + hi.x >= 0.0f; };
    const effects::gl::DrawCount w = counted([&] { batches.draw(program_, true, whole_level(), west); });
    const effects::gl::DrawCount e = counted([&] { batches.draw(program_, true, whole_level(), east); });
    const effects::gl::DrawCount all = counted([&] { batches.draw(program_, true, whole_level()); });
    EXPECT_GT(w.draws, 0u);
    EXPECT_GT(e.draws, 0u);
    EXPECT_EQ(w.draws + e.draws, all.draws);
    EXPECT_EQ(w.triangles + e.triangles, all.triangles);
}

}  // namespace
