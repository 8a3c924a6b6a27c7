// The tessellator (ui/tessellator.h) without GL: meshes are well formed for any input, the
// anti-aliased geometry covers the right area, text makes one quad per visible glyph, and
// batching/culling follow the clip rectangles.
//
// "Coverage" below integrates the (linearly interpolated) vertex alpha over the triangles: the
// area a rasteriser would paint, feather bands counted at their average opacity.
#include "ui/tessellator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace grass::ui {
namespace {

constexpr float PI = std::numbers::pi_v<float>;
const Rect EVERYWHERE{Vec2(-1e4f), Vec2(1e4f)};

const FontAtlas& font() {
    static const FontAtlas atlas = [] {
        std::string error;
        auto loaded = FontAtlas::load(FontAtlas::defaultFontPath(), &error);
        if (!loaded) {
            ADD_FAILURE() << error;
            std::abort();
        }
        return std::move(*loaded);
    }();
    return atlas;
}

std::vector<Mesh> tessellateOne(Shape shape, float ppp = 1.0f, Rect clip = EVERYWHERE) {
    return tessellate({ClippedShape{clip, std::move(shape)}}, font(), ppp);
}

double coverage(const std::vector<Mesh>& meshes) {
    double sum = 0.0;
    for (const Mesh& mesh : meshes) {
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const Vertex& a = mesh.vertices[mesh.indices[t]];
            const Vertex& b = mesh.vertices[mesh.indices[t + 1]];
            const Vertex& c = mesh.vertices[mesh.indices[t + 2]];
            const double area = 0.5 * std::abs(double(b.pos.x - a.pos.x) * (c.pos.y - a.pos.y) -
                                               double(c.pos.x - a.pos.x) * (b.pos.y - a.pos.y));
            sum += area * (a.color.a + b.color.a + c.color.a) / (3.0 * 255.0);
        }
    }
    return sum;
}

// What every mesh must satisfy whatever the input; returns a description of the first fault.
std::string wellFormed(const std::vector<Mesh>& meshes) {
    for (const Mesh& mesh : meshes) {
        if (mesh.vertices.empty() || mesh.indices.empty())
            return "empty mesh";
        if (mesh.indices.size() % 3 != 0)
            return "index count not a multiple of 3";
        for (const std::uint32_t index : mesh.indices)
            if (index >= mesh.vertices.size())
                return "index out of range";
        for (const Vertex& v : mesh.vertices) {
            if (!std::isfinite(v.pos.x) || !std::isfinite(v.pos.y) || !std::isfinite(v.uv.x) ||
                !std::isfinite(v.uv.y))
                return "non-finite vertex";
            if (v.uv.x < 0.0f || v.uv.x > 1.0f || v.uv.y < 0.0f || v.uv.y > 1.0f)
                return "uv outside 0..1";
            // Premultiplied: no channel above alpha.
            if (v.color.r > v.color.a || v.color.g > v.color.a || v.color.b > v.color.a)
                return "colour not premultiplied";
        }
    }
    return "";
}

Color32 randomColor(std::mt19937& rng) {
    std::uniform_int_distribution<int> byte(0, 255);
    return {std::uint8_t(byte(rng)), std::uint8_t(byte(rng)), std::uint8_t(byte(rng)),
            std::uint8_t(byte(rng))};
}

// Any shape, including degenerate ones: zero sizes, repeated points, huge roundings.
Shape randomShape(std::mt19937& rng) {
    std::uniform_real_distribution<float> coord(-50.0f, 250.0f);
    std::uniform_real_distribution<float> size(0.0f, 120.0f);
    std::uniform_real_distribution<float> width(0.0f, 6.0f);
    const auto stroke = [&] { return Stroke{width(rng), randomColor(rng)}; };
    switch (std::uniform_int_distribution<int>(0, 4)(rng)) {
        case 0: {
            const Vec2 min(coord(rng), coord(rng));
            return RectShape{Rect::fromMinSize(min, {size(rng), size(rng)}), size(rng),
                             randomColor(rng), stroke()};
        }
        case 1:
            return CircleShape{{coord(rng), coord(rng)}, size(rng), randomColor(rng), stroke()};
        case 2: {
            PathShape path;
            const int n = std::uniform_int_distribution<int>(0, 8)(rng);
            for (int i = 0; i < n; ++i) {
                // One point in three repeats the previous one.
                if (!path.points.empty() && rng() % 3 == 0)
                    path.points.push_back(path.points.back());
                else
                    path.points.push_back({coord(rng), coord(rng)});
            }
            path.closed = rng() % 2 == 0;
            path.fill = rng() % 2 == 0 ? randomColor(rng) : Color32::transparent();
            path.stroke = stroke();
            return path;
        }
        case 3:
            return TextShape{{coord(rng), coord(rng)},
                             "Grass \xC3\xB6\n\xFF x",
                             6.0f + size(rng) / 4.0f,
                             randomColor(rng)};
        default:
            return ImageShape{Rect::fromMinSize({coord(rng), coord(rng)}, {size(rng), size(rng)}),
                              TextureId{rng() % 3}};
    }
}

TEST(Tessellator, RandomShapesGiveWellFormedMeshes) {
    for (std::uint32_t seed = 0; seed < 200; ++seed) {
        std::mt19937 rng(seed);
        std::vector<ClippedShape> shapes;
        for (int i = 0; i < 20; ++i) {
            const Rect clip = rng() % 4 == 0 ? EVERYWHERE
                                             : Rect::fromMinSize({float(rng() % 100), 0.0f},
                                                                 {float(rng() % 150), 120.0f});
            shapes.push_back({clip, randomShape(rng)});
        }
        const float ppp = seed % 2 == 0 ? 1.0f : 1.5f;
        const std::vector<Mesh> meshes = tessellate(shapes, font(), ppp);
        EXPECT_EQ(wellFormed(meshes), "") << "seed " << seed;
    }
}

// The documented bound: a shape's vertices stay within its outline grown by half the stroke
// and one feather (paths: a 4× miter allowance).
TEST(Tessellator, VerticesStayWithinShapeBoundsPlusFeather) {
    for (std::uint32_t seed = 0; seed < 300; ++seed) {
        std::mt19937 rng(seed);
        const Shape shape = randomShape(rng);
        const float ppp = 1.0f + float(seed % 3) * 0.5f;
        const float feather = featherWidth(ppp);
        Rect bound;
        if (const auto* r = std::get_if<RectShape>(&shape))
            bound = r->rect.expand(0.5f * r->stroke.width + feather);
        else if (const auto* c = std::get_if<CircleShape>(&shape))
            bound = Rect{c->centre, c->centre}.expand(c->radius + 0.5f * c->stroke.width + feather);
        else if (const auto* i = std::get_if<ImageShape>(&shape))
            bound = i->rect;
        else
            continue;
        for (const Mesh& mesh : tessellateOne(shape, ppp))
            for (const Vertex& v : mesh.vertices) {
                ASSERT_GE(v.pos.x, bound.min.x - 1e-3f) << "seed " << seed;
                ASSERT_GE(v.pos.y, bound.min.y - 1e-3f) << "seed " << seed;
                ASSERT_LE(v.pos.x, bound.max.x + 1e-3f) << "seed " << seed;
                ASSERT_LE(v.pos.y, bound.max.y + 1e-3f) << "seed " << seed;
            }
    }
}

TEST(Tessellator, FilledRectCoversItsArea) {
    for (const float ppp : {1.0f, 2.0f}) {
        const Rect rect = Rect::fromMinSize({10.0f, 20.0f}, {100.0f, 50.0f});
        const auto meshes =
            tessellateOne(RectShape{rect, 0.0f, Color32::rgb(200, 10, 10), {}}, ppp);
        ASSERT_EQ(meshes.size(), 1u);
        // Exact but for the four feathered corners (each off by under a feather squared).
        EXPECT_NEAR(coverage(meshes), 5000.0, 4.0 / (ppp * ppp));
        // The opaque part is the rect shrunk by half a feather on every side.
        const float f = featherWidth(ppp);
        double opaque = 0.0;
        const Mesh& mesh = meshes.front();
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
            const Vertex& a = mesh.vertices[mesh.indices[t]];
            const Vertex& b = mesh.vertices[mesh.indices[t + 1]];
            const Vertex& c = mesh.vertices[mesh.indices[t + 2]];
            if (a.color.a == 255 && b.color.a == 255 && c.color.a == 255)
                opaque += 0.5 * std::abs(double(b.pos.x - a.pos.x) * (c.pos.y - a.pos.y) -
                                         double(c.pos.x - a.pos.x) * (b.pos.y - a.pos.y));
        }
        EXPECT_NEAR(opaque, (100.0 - f) * (50.0 - f), 1e-2);
    }
}

TEST(Tessellator, RoundedRectLosesTheCorners) {
    const float r = 12.0f;
    const auto meshes = tessellateOne(
        RectShape{Rect::fromMinSize({0.0f, 0.0f}, {100.0f, 60.0f}), r, Color32::rgb(1, 2, 3), {}});
    const double expected = 100.0 * 60.0 - (4.0 - PI) * r * r;
    // Chords lie inside the arcs by ≤ 0.1 px: at most 0.1 × arc length of area.
    EXPECT_NEAR(coverage(meshes), expected, 0.1 * 2.0 * PI * r + 1.0);
    // Rounding larger than half the short side is clamped to a stadium.
    const auto stadium = tessellateOne(RectShape{
        Rect::fromMinSize({0.0f, 0.0f}, {100.0f, 20.0f}), 50.0f, Color32::rgb(1, 2, 3), {}});
    EXPECT_NEAR(coverage(stadium), 80.0 * 20.0 + PI * 100.0, 0.1 * 2.0 * PI * 10.0 + 1.0);
}

TEST(Tessellator, CircleCoversPiRSquared) {
    for (const float r : {3.0f, 20.0f, 200.0f}) {
        const auto meshes =
            tessellateOne(CircleShape{{50.0f, 50.0f}, r, Color32::rgb(0, 255, 0), {}});
        EXPECT_NEAR(coverage(meshes), PI * r * r, 0.1 * 2.0 * PI * r + 1.0) << "r " << r;
    }
}

TEST(Tessellator, ClosedStrokeCoversPerimeterTimesWidth) {
    // A rect outline with miter joins: (w+s)(h+s) − (w−s)(h−s) = 2·s·(w+h) exactly.
    const float s = 3.0f;
    const auto outline =
        tessellateOne(RectShape{Rect::fromMinSize({10.0f, 10.0f}, {80.0f, 40.0f}), 0.0f,
                                Color32::transparent(), Stroke{s, Color32::rgb(255, 255, 255)}});
    EXPECT_NEAR(coverage(outline), 2.0 * s * (80.0 + 40.0), 4.0);
    const auto ring = tessellateOne(CircleShape{
        {50.0f, 50.0f}, 30.0f, Color32::transparent(), Stroke{2.0f, Color32::rgb(255, 255, 255)}});
    EXPECT_NEAR(coverage(ring), 2.0 * PI * 30.0 * 2.0, 2.0);
}

TEST(Tessellator, OpenPolylineCoversLengthTimesWidth) {
    PathShape path;
    path.points = {{0.0f, 0.0f}, {100.0f, 0.0f}, {100.0f, 50.0f}};
    path.stroke = {2.0f, Color32::rgb(255, 0, 0)};
    const auto meshes = tessellateOne(path);
    // The miter at the corner adds a (w/2)² square, the butt ends nothing.
    EXPECT_NEAR(coverage(meshes), 150.0 * 2.0, 2.0);
    EXPECT_EQ(wellFormed(meshes), "");
}

// Lines thinner than a pixel keep a one-pixel footprint and fade, so coverage stays w · length.
TEST(Tessellator, ThinLinesFadeInsteadOfVanishing) {
    for (const float width : {0.25f, 0.5f, 1.0f}) {
        PathShape line;
        line.points = {{0.0f, 10.0f}, {100.0f, 10.0f}};
        line.stroke = {width, Color32::rgb(255, 255, 255)};
        const auto meshes = tessellateOne(line);
        EXPECT_NEAR(coverage(meshes), 100.0 * width, 1.0) << "width " << width;
        std::uint8_t peak = 0;
        for (const Vertex& v : meshes.front().vertices)
            peak = std::max(peak, v.color.a);
        EXPECT_NEAR(peak, 255.0f * width, 1.0f);
    }
}

TEST(Tessellator, ConvexPolygonFillsEitherWinding) {
    PathShape triangle;
    triangle.points = {{0.0f, 0.0f}, {40.0f, 0.0f}, {0.0f, 30.0f}};
    triangle.closed = true;
    triangle.fill = Color32::rgb(9, 9, 9);
    const double clockwise = coverage(tessellateOne(triangle));
    std::reverse(triangle.points.begin(), triangle.points.end());
    const double counter = coverage(tessellateOne(triangle));
    EXPECT_NEAR(clockwise, 600.0, 2.0);
    EXPECT_NEAR(counter, 600.0, 2.0);
}

TEST(Tessellator, HelloIsFiveGlyphQuadsAndSpacesAddNone) {
    for (const std::string text : {"Hello", "He llo", " Hello "}) {
        const auto meshes = tessellateOne(TextShape{{10.3f, 20.6f}, text, 14.0f});
        ASSERT_EQ(meshes.size(), 1u) << text;
        EXPECT_EQ(meshes.front().texture, TextureId{0});
        EXPECT_EQ(meshes.front().vertices.size(), 5u * 4u) << text;
        EXPECT_EQ(meshes.front().indices.size(), 5u * 6u) << text;
    }
}

TEST(Tessellator, GlyphQuadsSnapToPhysicalPixels) {
    for (const float ppp : {1.0f, 2.0f, 1.5f}) {
        FontAtlas& atlas = const_cast<FontAtlas&>(font());
        atlas.setPixelsPerPoint(ppp);
        const auto meshes = tessellateOne(TextShape{{10.3f, 20.6f}, "Snap", 13.0f}, ppp);
        ASSERT_FALSE(meshes.empty());
        for (const Vertex& v : meshes.front().vertices) {
            EXPECT_NEAR(v.pos.x * ppp, std::round(v.pos.x * ppp), 1e-3f) << "ppp " << ppp;
            EXPECT_NEAR(v.pos.y * ppp, std::round(v.pos.y * ppp), 1e-3f) << "ppp " << ppp;
        }
        atlas.setPixelsPerPoint(1.0f);
    }
}

// Text starts at its top-left: glyphs lie between pos.y and pos.y + line height, and the
// second line one line height lower.
TEST(Tessellator, TextLinesStackByLineHeight) {
    const float size = 16.0f;
    const auto meshes = tessellateOne(TextShape{{0.0f, 100.0f}, "Hg\nHg", size});
    ASSERT_EQ(meshes.front().vertices.size(), 16u);
    const auto& v = meshes.front().vertices;
    const float line = font().lineHeight(size);
    for (std::size_t i = 0; i < 8; ++i) {
        EXPECT_GE(v[i].pos.y, 100.0f - 1.0f);
        EXPECT_LE(v[i].pos.y, 100.0f + line + 1.0f);
        EXPECT_NEAR(v[i + 8].pos.y - v[i].pos.y, line, 1.01f);
    }
}

TEST(Tessellator, ColoursArePremultiplied) {
    EXPECT_EQ(premultiply({255, 128, 0, 128}), (Color32{128, 64, 0, 128}));
    EXPECT_EQ(premultiply({255, 255, 255, 255}), (Color32{255, 255, 255, 255}));
    EXPECT_EQ(premultiply({255, 255, 255, 0}), (Color32{0, 0, 0, 0}));
    const auto meshes = tessellateOne(
        RectShape{Rect::fromMinSize({0.0f, 0.0f}, {10.0f, 10.0f}), 0.0f, {255, 0, 0, 128}, {}});
    EXPECT_EQ(meshes.front().vertices.front().color, (Color32{128, 0, 0, 128}));
    // Untextured shapes sample the atlas's white texel.
    EXPECT_EQ(meshes.front().vertices.front().uv, font().whiteUv());
}

TEST(Tessellator, ShapesBatchByClipAndTexture) {
    const Rect clipA = Rect::fromMinSize({0.0f, 0.0f}, {100.0f, 100.0f});
    const Rect clipB = Rect::fromMinSize({100.0f, 0.0f}, {100.0f, 100.0f});
    const RectShape inA{
        Rect::fromMinSize({10.0f, 10.0f}, {20.0f, 20.0f}), 0.0f, Color32::rgb(1, 1, 1), {}};
    const RectShape inB{
        Rect::fromMinSize({110.0f, 10.0f}, {20.0f, 20.0f}), 0.0f, Color32::rgb(1, 1, 1), {}};
    const ImageShape image{Rect::fromMinSize({10.0f, 40.0f}, {20.0f, 20.0f}), TextureId{7}};
    const TextShape text{{10.0f, 70.0f}, "ab", 12.0f};
    const auto meshes = tessellate(
        {{clipA, inA}, {clipA, text}, {clipA, image}, {clipA, inA}, {clipB, inB}, {clipB, inB}},
        font(), 1.0f);
    ASSERT_EQ(meshes.size(), 4u);
    EXPECT_EQ(meshes[0].clip, clipA);
    EXPECT_EQ(meshes[0].texture, TextureId{0});
    EXPECT_EQ(meshes[0].vertices.size(), 8u + 8u);
    EXPECT_EQ(meshes[1].texture, TextureId{7});
    EXPECT_EQ(meshes[1].vertices.size(), 4u);
    EXPECT_EQ(meshes[2].texture, TextureId{0});
    EXPECT_EQ(meshes[3].clip, clipB);
    EXPECT_EQ(meshes[3].vertices.size(), 16u);
}

TEST(Tessellator, InvisibleShapesEmitNothing) {
    const Rect clip = Rect::fromMinSize({0.0f, 0.0f}, {100.0f, 100.0f});
    const Color32 red = Color32::rgb(255, 0, 0);
    const std::vector<ClippedShape> shapes{
        // Entirely outside its clip.
        {clip, RectShape{Rect::fromMinSize({200.0f, 200.0f}, {10.0f, 10.0f}), 0.0f, red, {}}},
        {clip, CircleShape{{-50.0f, 50.0f}, 10.0f, red, {}}},
        {clip, TextShape{{0.0f, 300.0f}, "below", 14.0f}},
        // Empty clip, zero size, fully transparent, a single point, nothing but spaces.
        {Rect{}, RectShape{Rect::fromMinSize({10.0f, 10.0f}, {10.0f, 10.0f}), 0.0f, red, {}}},
        {clip, RectShape{Rect::fromMinSize({10.0f, 10.0f}, {0.0f, 10.0f}), 0.0f, red, {}}},
        {clip, CircleShape{{50.0f, 50.0f}, 10.0f, Color32::transparent(), {}}},
        {clip, PathShape{{{5.0f, 5.0f}}, false, red, Stroke{2.0f, red}}},
        {clip, TextShape{{0.0f, 0.0f}, "   ", 14.0f}},
    };
    EXPECT_TRUE(tessellate(shapes, font(), 1.0f).empty());
}

// The allocation-free overload: a vector reused across frames ends up exactly as a fresh result,
// even when the earlier frame had more meshes or more vertices.
TEST(Tessellator, ReusedOutputEqualsFreshOutput) {
    std::mt19937 rng(7);
    const auto frame = [&](int count) {
        std::vector<ClippedShape> shapes;
        for (int i = 0; i < count; ++i)
            shapes.push_back({Rect::fromMinSize({float(i % 3) * 50.0f, 0.0f}, {60.0f, 200.0f}),
                              randomShape(rng)});
        return shapes;
    };
    const std::vector<ClippedShape> big = frame(60);
    const std::vector<ClippedShape> small = frame(15);
    std::vector<Mesh> reused;
    tessellate(big, font(), 1.0f, reused);
    tessellate(small, font(), 1.0f, reused);
    const std::vector<Mesh> fresh = tessellate(small, font(), 1.0f);
    ASSERT_EQ(reused.size(), fresh.size());
    for (std::size_t m = 0; m < fresh.size(); ++m) {
        EXPECT_EQ(reused[m].clip, fresh[m].clip);
        EXPECT_EQ(reused[m].texture, fresh[m].texture);
        EXPECT_EQ(reused[m].indices, fresh[m].indices);
        ASSERT_EQ(reused[m].vertices.size(), fresh[m].vertices.size());
        for (std::size_t v = 0; v < fresh[m].vertices.size(); ++v) {
            EXPECT_EQ(reused[m].vertices[v].pos, fresh[m].vertices[v].pos);
            EXPECT_EQ(reused[m].vertices[v].color, fresh[m].vertices[v].color);
        }
    }
}

TEST(Tessellator, PartlyVisibleShapeKeepsItsClip) {
    const Rect clip = Rect::fromMinSize({0.0f, 0.0f}, {50.0f, 50.0f});
    const auto meshes = tessellateOne(
        RectShape{
            Rect::fromMinSize({40.0f, 40.0f}, {30.0f, 30.0f}), 0.0f, Color32::rgb(1, 2, 3), {}},
        1.0f, clip);
    ASSERT_EQ(meshes.size(), 1u);
    // Not cut on the CPU: the backend scissors to this rect.
    EXPECT_EQ(meshes.front().clip, clip);
}

}  // namespace
}  // namespace grass::ui
