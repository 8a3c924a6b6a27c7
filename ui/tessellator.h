// The tessellator: turns the shapes a frame painted (shape.h, points) into indexed triangle
// meshes for the backend (mesh.h), anti-aliased by feathering: every filled outline and stroke
// gets an extra band one physical pixel wide in which alpha falls to zero, so edges look smooth
// without MSAA (the approach of egui's epaint).
//
// Guarantees (tests/ui/tessellator_test.cpp):
// - Consecutive shapes with the same clip rectangle and texture share one Mesh; a mesh's clip
//   is exactly the clip its shapes were painted with. Geometry is NOT cut at the clip: the
//   backend must scissor to Mesh::clip (editor/gl/ui_renderer does). Shapes entirely outside
//   their clip, with an empty clip, or with nothing visible (transparent, zero size) emit
//   nothing, and no empty mesh is returned.
// - Each shape's vertices stay within its own bounds grown by half its stroke width plus one
//   feather width (and a miter allowance for sharp polyline joins).
// - Colours are premultiplied in sRGB space (the backend blends with ONE, ONE_MINUS_SRC_ALPHA
//   into an sRGB-encoded target without conversion, as egui's gamma-space blending does).
// - Untextured shapes use the font atlas (texture 0) at FontAtlas::whiteUv(); text quads sample
//   glyph coverage and are snapped to whole physical pixels so glyphs stay crisp.
#pragma once

#include <vector>

#include "font.h"
#include "mesh.h"
#include "shape.h"

namespace grass::ui {

// Width of the anti-aliasing band, points: one physical pixel.
inline float featherWidth(float pixelsPerPoint) {
    return 1.0f / pixelsPerPoint;
}

// Straight-alpha sRGB colour to premultiplied (rounded to nearest).
Color32 premultiply(Color32 color);

// Builds the frame's meshes. May rasterise new glyphs into `font` (its version() changes) before
// any vertex is written, so every uv in the result refers to the atlas as it is on return.
std::vector<Mesh> tessellate(const std::vector<ClippedShape>& shapes, const FontAtlas& font,
                             float pixelsPerPoint);
// The same into `meshes`, reusing the vertex and index storage it already holds: an editor
// keeping one vector across frames allocates nothing once the UI stops growing.
void tessellate(const std::vector<ClippedShape>& shapes, const FontAtlas& font,
                float pixelsPerPoint, std::vector<Mesh>& meshes);

}  // namespace grass::ui
