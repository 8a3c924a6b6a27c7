// The tessellator's output and the backend's only input: indexed triangles with a clip
// rectangle and a texture, in points (the backend scales by pixels per point). Colours are
// premultiplied-alpha sRGB; the font atlas texel at uv (0, 0)..(1, 1) of texture 0 is opaque
// white at WHITE_UV, so untextured shapes sample it and everything is one shader.
#pragma once

#include <cstdint>
#include <vector>

#include "shape.h"

namespace grass::ui {

struct Vertex {
    Vec2 pos{0.0f};             // points
    Vec2 uv{0.0f};              // texture coordinates
    Color32 color;              // premultiplied alpha
};
static_assert(sizeof(Vertex) == 20, "ui::Vertex is 2 + 2 floats and 4 bytes");

struct Mesh {
    Rect clip;  // points; the backend sets the scissor from it
    TextureId texture;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;  // triangles
};

}  // namespace grass::ui
