#include "gl/ui_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

#include "gl/scoped_capability.h"
#include "gl/texture.h"

namespace grass::gl {

namespace {

// Vertex and index buffers start at this many bytes and double: a typical editor frame fits
// after the first few frames and then never reallocates.
constexpr std::size_t INITIAL_BUFFER_BYTES = 64 * 1024;

std::size_t grownCapacity(std::size_t current, std::size_t needed) {
    std::size_t capacity = std::max(current, INITIAL_BUFFER_BYTES);
    while (capacity < needed)
        capacity *= 2;
    return capacity;
}

TextureHandle makeTexture(GLenum format, int width, int height, std::string_view label) {
    TextureHandle texture = makeTexture2D(format, width, height, 1, label);
    // Linear: glyph quads map texels to pixels 1:1 (so this equals nearest), and images scale.
    setClampedFiltering(texture, GL_LINEAR, GL_LINEAR);
    return texture;
}

}  // namespace

Result<UiRenderer> UiRenderer::create() {
    auto program =
        Program::load({{GL_VERTEX_SHADER, "ui.vert"}, {GL_FRAGMENT_SHADER, "ui.frag"}}, "ui");
    if (!program)
        return program.error();
    UiRenderer renderer;
    renderer.mProgram = std::move(*program);

    renderer.mVertexArray = VertexArray("ui");
    const VertexAttribute attributes[] = {
        {2, offsetof(ui::Vertex, pos)},
        {2, offsetof(ui::Vertex, uv)},
        // Colour bytes 0..255 arrive as 0..1.
        {4, offsetof(ui::Vertex, color), GL_UNSIGNED_BYTE, true},
    };
    renderer.mVertexArray.setAttributes(attributes);
    renderer.reserve(INITIAL_BUFFER_BYTES, INITIAL_BUFFER_BYTES);
    return renderer;
}

void UiRenderer::reserve(std::size_t vertexBytes, std::size_t indexBytes) {
    // Immutable storage cannot grow: a larger buffer replaces the old one, and the vertex
    // array is pointed at it.
    if (vertexBytes > mVertices.size() || mVertices.id() == 0) {
        const std::vector<std::byte> zeros(grownCapacity(mVertices.size(), vertexBytes));
        mVertices = Buffer(zeros, "ui vertices");
        mVertexArray.setVertexBuffer(mVertices, sizeof(ui::Vertex));
    }
    if (indexBytes > mIndices.size() || mIndices.id() == 0) {
        const std::vector<std::byte> zeros(grownCapacity(mIndices.size(), indexBytes));
        mIndices = Buffer(zeros, "ui indices");
        mVertexArray.setElementBuffer(mIndices);
    }
}

void UiRenderer::registerTexture(ui::TextureId id, GLuint texture) {
    mOwnedTextures.erase(id.value);
    mTextures[id.value] = texture;
}

void UiRenderer::registerTexture(ui::TextureId id, const Rgba8Image& image) {
    std::vector<std::uint8_t> premultiplied = image.pixels;
    for (std::size_t i = 0; i + 3 < premultiplied.size(); i += 4) {
        const unsigned alpha = premultiplied[i + 3];
        for (std::size_t c = 0; c < 3; ++c)
            premultiplied[i + c] =
                static_cast<std::uint8_t>((unsigned(premultiplied[i + c]) * alpha + 127u) / 255u);
    }
    TextureHandle texture =
        makeTexture(GL_RGBA8, image.width, image.height, "ui texture " + std::to_string(id.value));
    // Row 0 = top of the image = t 0, matching ui uv (0, 0) at the top-left.
    uploadTexture2D(texture, image.width, image.height, GL_RGBA, premultiplied.data());
    mTextures[id.value] = texture.id();
    mOwnedTextures[id.value] = std::move(texture);
}

void UiRenderer::unregisterTexture(ui::TextureId id) {
    mTextures.erase(id.value);
    mOwnedTextures.erase(id.value);
}

void UiRenderer::uploadFont(const ui::FontAtlas& font) {
    if (mFontTexture && font.version() == mFontVersion && font.height() == mFontHeight)
        return;
    // The atlas grows in height only; a new size needs new storage.
    if (!mFontTexture || font.height() != mFontHeight) {
        mFontTexture = makeTexture(GL_R8, font.width(), font.height(), "ui font atlas");
        // Coverage c in red is read as (c, c, c, c): premultiplied white at opacity c, so the
        // shader treats glyphs like any premultiplied texture.
        const GLint swizzle[] = {GL_RED, GL_RED, GL_RED, GL_RED};
        glTextureParameteriv(mFontTexture.id(), GL_TEXTURE_SWIZZLE_RGBA, swizzle);
        mFontHeight = font.height();
    }
    uploadTexture2D(mFontTexture, font.width(), font.height(), GL_RED, font.pixels().data());
    mFontVersion = font.version();
}

void UiRenderer::draw(const std::vector<ui::Mesh>& meshes, const ui::FontAtlas& font,
                      glm::ivec2 framebufferSizePx, float pixelsPerPoint) {
    mDrawCalls = 0;
    mSkippedMeshes = 0;
    uploadFont(font);
    if (meshes.empty() || framebufferSizePx.x <= 0 || framebufferSizePx.y <= 0)
        return;

    // All meshes go into one vertex and one index buffer; each draw picks its range and adds
    // its base vertex, so the indices stay as the tessellator wrote them.
    std::size_t vertexCount = 0, indexCount = 0;
    for (const ui::Mesh& mesh : meshes) {
        vertexCount += mesh.vertices.size();
        indexCount += mesh.indices.size();
    }
    reserve(vertexCount * sizeof(ui::Vertex), indexCount * sizeof(std::uint32_t));
    std::size_t vertexOffset = 0, indexOffset = 0;
    for (const ui::Mesh& mesh : meshes) {
        mVertices.update(std::as_bytes(std::span(mesh.vertices)),
                         vertexOffset * sizeof(ui::Vertex));
        mIndices.update(std::as_bytes(std::span(mesh.indices)),
                        indexOffset * sizeof(std::uint32_t));
        vertexOffset += mesh.vertices.size();
        indexOffset += mesh.indices.size();
    }

    const ScopedCapability blend(GL_BLEND, true);
    const ScopedCapability scissor(GL_SCISSOR_TEST, true);
    const ScopedCapability depth(GL_DEPTH_TEST, false);
    const ScopedCapability cull(GL_CULL_FACE, false);
    // Gamma-space blending (see the header): no linear-to-sRGB conversion on write.
    const ScopedCapability srgb(GL_FRAMEBUFFER_SRGB, false);
    GLint blendState[4] = {};
    glGetIntegerv(GL_BLEND_SRC_RGB, &blendState[0]);
    glGetIntegerv(GL_BLEND_DST_RGB, &blendState[1]);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &blendState[2]);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &blendState[3]);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glViewport(0, 0, framebufferSizePx.x, framebufferSizePx.y);

    mProgram.use();
    mProgram.set("uScreenSizePt", glm::vec2(framebufferSizePx) / pixelsPerPoint);
    mVertexArray.bind();

    vertexOffset = indexOffset = 0;
    for (const ui::Mesh& mesh : meshes) {
        const std::size_t firstVertex = vertexOffset;
        const std::size_t firstIndex = indexOffset;
        vertexOffset += mesh.vertices.size();
        indexOffset += mesh.indices.size();
        GLuint texture = mFontTexture.id();
        if (mesh.texture.value != 0) {
            const auto found = mTextures.find(mesh.texture.value);
            if (found == mTextures.end()) {
                ++mSkippedMeshes;
                continue;
            }
            texture = found->second;
        }
        // Clip rect in points to whole pixels; GL's scissor origin is the bottom-left.
        const glm::ivec2 size = framebufferSizePx;
        const int x0 = std::clamp(int(std::round(mesh.clip.min.x * pixelsPerPoint)), 0, size.x);
        const int y0 = std::clamp(int(std::round(mesh.clip.min.y * pixelsPerPoint)), 0, size.y);
        const int x1 = std::clamp(int(std::round(mesh.clip.max.x * pixelsPerPoint)), 0, size.x);
        const int y1 = std::clamp(int(std::round(mesh.clip.max.y * pixelsPerPoint)), 0, size.y);
        if (x1 <= x0 || y1 <= y0 || mesh.indices.empty())
            continue;
        glScissor(x0, size.y - y1, x1 - x0, y1 - y0);
        glBindTextureUnit(0, texture);
        glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(mesh.indices.size()),
                                 GL_UNSIGNED_INT,
                                 reinterpret_cast<const void*>(firstIndex * sizeof(std::uint32_t)),
                                 static_cast<GLint>(firstVertex));
        ++mDrawCalls;
    }
    glBindVertexArray(0);
    glBlendFuncSeparate(GLenum(blendState[0]), GLenum(blendState[1]), GLenum(blendState[2]),
                        GLenum(blendState[3]));
}

}  // namespace grass::gl
