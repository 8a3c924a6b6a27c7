// What widgets paint: resolution-independent shapes in points, each with the clip rectangle in
// force when it was painted. The tessellator (tessellator.h) turns them into meshes; nothing
// here knows about GL.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "types.h"

namespace grass::ui {

// A texture the backend knows by number: 0 is the font atlas, others are user images (maps).
struct TextureId {
    std::uint64_t value = 0;
    bool operator==(const TextureId&) const = default;
};

struct Stroke {
    float width = 0.0f;  // points; 0 = no stroke
    Color32 color = Color32::transparent();
    bool operator==(const Stroke&) const = default;
};

struct RectShape {
    Rect rect;
    float rounding = 0.0f;  // corner radius, points
    Color32 fill = Color32::transparent();
    Stroke stroke;
};

struct CircleShape {
    Vec2 centre{0.0f};
    float radius = 0.0f;
    Color32 fill = Color32::transparent();
    Stroke stroke;
};

// An open or closed polyline (a line is two points); `fill` fills a closed convex polygon.
struct PathShape {
    std::vector<Vec2> points;
    bool closed = false;
    Color32 fill = Color32::transparent();
    Stroke stroke;
};

// Text laid out from `pos` (top-left of the first line) in the font of `sizePt` points.
struct TextShape {
    Vec2 pos{0.0f};
    std::string text;  // UTF-8; '\n' starts a new line
    float sizePt = 14.0f;
    Color32 color = Color32::rgb(255, 255, 255);
};

// A textured rectangle (uv (0,0) top-left .. (1,1) bottom-right of the texture), tinted.
struct ImageShape {
    Rect rect;
    TextureId texture;
    Rect uv{{0.0f, 0.0f}, {1.0f, 1.0f}};
    Color32 tint = Color32::rgb(255, 255, 255);
};

using Shape = std::variant<RectShape, CircleShape, PathShape, TextShape, ImageShape>;

struct ClippedShape {
    Rect clip;
    Shape shape;
};

}  // namespace grass::ui
