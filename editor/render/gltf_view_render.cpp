#include "render/gltf_view_render.h"

#include <cstddef>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/uniform_block.h"
#include "gl/vertex_array.h"
#include "render/lighting_block.h"

namespace grass::render {

namespace {
struct ViewVertex {
    float position[3];
    float normal[3];
    float color[4];
};
}  // namespace

Result<gl::Rgba8Image> renderGltfView(const core::GltfView& view, const core::OrbitCamera& camera,
                                      const GltfViewRequest& request, const RenderOptions& options) {
    auto program = gl::Program::load(
        {{GL_VERTEX_SHADER, "gltf_view.vert"}, {GL_FRAGMENT_SHADER, "gltf_view.frag"}}, "gltf view");
    if (!program)
        return program.error();
    std::vector<ViewVertex> vertices(view.positions.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const glm::vec3 p = view.positions[i], n = view.normals[i];
        const glm::vec4 c = view.colors[i];
        vertices[i] = {{p.x, p.y, p.z}, {n.x, n.y, n.z}, {c.r, c.g, c.b, c.a}};
    }
    gl::Framebuffer framebuffer(request.width, request.height, request.msaaSamples);
    framebuffer.bind();
    glViewport(0, 0, request.width, request.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glClearColor(options.skyColor.r, options.skyColor.g, options.skyColor.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl::UniformBlock<LightingBlock> lighting("gltf view lighting");
    lighting.upload(lightingBlock(options.lighting, options.sun, options.skyColor, options.groundColor));
    if (!view.indices.empty()) {
        const gl::Buffer vertexBuffer = gl::Buffer::fromVector(vertices, "gltf view vertices");
        const gl::Buffer indexBuffer = gl::Buffer::fromVector(view.indices, "gltf view indices");
        gl::VertexArray vertexArray("gltf view");
        vertexArray.setVertexBuffer(vertexBuffer, sizeof(ViewVertex));
        vertexArray.setElementBuffer(indexBuffer);
        const gl::VertexAttribute attributes[] = {{3, offsetof(ViewVertex, position)},
                                                  {3, offsetof(ViewVertex, normal)},
                                                  {4, offsetof(ViewVertex, color)}};
        vertexArray.setAttributes(attributes);
        program->use();
        const float aspect = static_cast<float>(request.width) / static_cast<float>(request.height);
        program->set("uViewProj", camera.projection(aspect) * camera.view());
        program->set("uUnlit", options.albedoView ? 1 : 0);
        vertexArray.bind();
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(view.indices.size()), GL_UNSIGNED_INT,
                       nullptr);
        glBindVertexArray(0);
    }
    return framebuffer.readPixels();
}

}  // namespace grass::render
