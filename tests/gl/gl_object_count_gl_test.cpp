// Live GL object counts (gl_object_count.h): every wrapper counts its object while it lives, moves
// do not count twice, and a whole GPU physics run gives back all it made (what grass soak checks).
#include <gtest/gtest.h>

#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl_context_fixture.h"
#include "gl/gl_object_count.h"
#include "gl/program.h"
#include "scene/scene_physics.h"
#include "render/scene_physics_gpu.h"
#include "support/test_paths.h"
#include "gl/timer_query.h"

namespace grass::test {
namespace {

using gl::GlObjectKind;

using GlObjectCountTest = GlTest;

TEST_F(GlObjectCountTest, WrappersCountWhileTheyLive) {
    const gl::GlObjectCounts start = gl::liveGlObjects();
    {
        const std::vector<float> values(16, 1.0f);
        gl::Buffer buffer = gl::Buffer::fromVector(values, "count test");
        gl::Framebuffer framebuffer(8, 8, 0);
        gl::GpuTimer timer;
        GLuint vao = 0;
        glCreateVertexArrays(1, &vao);
        gl::VertexArrayHandle vertexArray(vao);
        GLuint texture = 0;
        glCreateTextures(GL_TEXTURE_2D, 1, &texture);
        gl::TextureHandle textureHandle(texture);
        auto program = gl::Program::load(
            {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "mesh.frag"}}, "count test");
        ASSERT_TRUE(program.ok()) << program.error().str();

        const gl::GlObjectCounts during = gl::liveGlObjects();
        EXPECT_EQ(during[GlObjectKind::Buffer], start[GlObjectKind::Buffer] + 1);
        // The framebuffer (colour and depth renderbuffers) and its resolve target (colour).
        EXPECT_EQ(during[GlObjectKind::Framebuffer], start[GlObjectKind::Framebuffer] + 2);
        EXPECT_EQ(during[GlObjectKind::Renderbuffer], start[GlObjectKind::Renderbuffer] + 3);
        EXPECT_EQ(during[GlObjectKind::Query], start[GlObjectKind::Query] + 1);
        EXPECT_EQ(during[GlObjectKind::VertexArray], start[GlObjectKind::VertexArray] + 1);
        EXPECT_EQ(during[GlObjectKind::Texture], start[GlObjectKind::Texture] + 1);
        EXPECT_EQ(during[GlObjectKind::Program], start[GlObjectKind::Program] + 1);
        // Shaders live only while the program links.
        EXPECT_EQ(during[GlObjectKind::Shader], start[GlObjectKind::Shader]);
        EXPECT_EQ(during.total(), start.total() + 10) << during.str();
        EXPECT_FALSE(during.noMoreThan(start));

        // Moves hand the name over: still one object each.
        gl::Buffer moved = std::move(buffer);
        gl::Buffer assigned;
        assigned = std::move(moved);
        gl::VertexArrayHandle otherVertexArray = std::move(vertexArray);
        EXPECT_EQ(gl::liveGlObjects(), during);
    }
    EXPECT_EQ(gl::liveGlObjects(), start) << gl::liveGlObjects().str() << " vs " << start.str();
    EXPECT_TRUE(gl::liveGlObjects().noMoreThan(start));
}

TEST_F(GlObjectCountTest, EmptyHandlesCountNothing) {
    const gl::GlObjectCounts start = gl::liveGlObjects();
    {
        gl::Buffer empty;
        gl::TextureHandle none(0);
        EXPECT_EQ(gl::liveGlObjects(), start);
    }
    EXPECT_EQ(gl::liveGlObjects(), start);
}

TEST_F(GlObjectCountTest, GpuPhysicsRunGivesBackEveryObject) {
    auto loaded = core::loadProject(sourceDir() / "tests/data/projects/windy");
    ASSERT_TRUE(loaded.ok()) << loaded.error().str();
    auto scene = core::buildScene(*loaded);
    ASSERT_TRUE(scene.ok()) << scene.error().str();
    auto physics = core::buildScenePhysics(*loaded);
    ASSERT_TRUE(physics.ok()) << physics.error().str();
    core::SceneSimulation simulation(*scene, *physics, 1);
    const gl::GlObjectCounts start = gl::liveGlObjects();
    {
        auto gpu = render::ScenePhysicsGpu::create(*scene);
        ASSERT_TRUE(gpu.ok()) << gpu.error().str();
        gpu->step(simulation.physics(), simulation.timeS());
        simulation.advanceClock();
        const gl::GlObjectCounts afterFirstStep = gl::liveGlObjects();
        EXPECT_GT(afterFirstStep.total(), start.total());
        for (int i = 0; i < 200; ++i) {
            gpu->step(simulation.physics(), simulation.timeS());
            simulation.advanceClock();
            if (i % 50 == 0)
                gpu->readBack(*scene, simulation);
        }
        glFinish();
        // Steady state: stepping and reading back make no objects.
        EXPECT_EQ(gl::liveGlObjects(), afterFirstStep) << gl::liveGlObjects().str();
    }
    EXPECT_EQ(gl::liveGlObjects(), start) << gl::liveGlObjects().str();
}

}  // namespace
}  // namespace grass::test
