// UiRenderer: the GL backend of the UI library. It only draws what ui::tessellate produced
// (ui/mesh.h): indexed triangles in points with a clip rectangle and a texture each, into the
// framebuffer bound at draw() time. Texture 0 is the font atlas (uploaded as R8, swizzled to
// premultiplied white: coverage in all four channels, re-uploaded whenever FontAtlas::version()
// changes); other ui::TextureIds name user images registered here.
//
// Colour: vertex colours and textures are premultiplied-alpha sRGB and are blended as stored
// (ONE, ONE_MINUS_SRC_ALPHA) with GL_FRAMEBUFFER_SRGB off, i.e. in gamma space, as egui does:
// UI colours then match the numbers in the style exactly, and anti-aliased edges look as
// designed in sRGB tools. The target is expected to hold sRGB-encoded values (RGBA8 or the
// window's back buffer).
//
// draw() sets its own state (blend, scissor, no depth test, no face culling, viewport) and
// restores the capabilities and blend function it changed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

#include <glm/glm.hpp>

#include "gl/buffer.h"
#include "gl/framebuffer.h"
#include "gl/gl_handle.h"
#include "gl/program.h"
#include "gl/vertex_array.h"
#include "ui/font.h"
#include "ui/mesh.h"

namespace grass::gl {

class UiRenderer {
public:
    // Loads shaders/ui.{vert,frag}; the error names the shader file and line.
    static Result<UiRenderer> create();

    // A texture owned elsewhere (a map the editor renders), drawn for meshes with `id`. Its
    // colours must be premultiplied (opaque textures need nothing). Id 0 is the font atlas.
    void registerTexture(ui::TextureId id, GLuint texture);
    // Uploads an RGBA8 image with straight alpha (as image files hold it), premultiplied here,
    // owned by the renderer. Replaces an earlier texture of the same id.
    void registerTexture(ui::TextureId id, const Rgba8Image& image);
    void unregisterTexture(ui::TextureId id);

    // Draws the meshes in order into the bound framebuffer of framebufferSizePx pixels.
    // Meshes whose texture is unknown are skipped (counted in skippedMeshes()).
    void draw(const std::vector<ui::Mesh>& meshes, const ui::FontAtlas& font,
              glm::ivec2 framebufferSizePx, float pixelsPerPoint);

    // Of the last draw().
    std::size_t drawCalls() const { return mDrawCalls; }
    std::size_t skippedMeshes() const { return mSkippedMeshes; }

private:
    UiRenderer() = default;
    void uploadFont(const ui::FontAtlas& font);
    void reserve(std::size_t vertexBytes, std::size_t indexBytes);

    Program mProgram;
    VertexArray mVertexArray;
    Buffer mVertices;
    Buffer mIndices;
    TextureHandle mFontTexture;
    int mFontHeight = 0;
    std::uint64_t mFontVersion = 0;
    // By ui::TextureId value: every known texture, and those the renderer owns.
    std::map<std::uint64_t, GLuint> mTextures;
    std::map<std::uint64_t, TextureHandle> mOwnedTextures;
    std::size_t mDrawCalls = 0;
    std::size_t mSkippedMeshes = 0;
};

}  // namespace grass::gl
