#include "ui/tessellator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

namespace grass::ui {

namespace {

// Curves are flattened until a chord strays at most this far from the true arc (physical
// pixels): below what the feather band can show.
constexpr float ARC_TOLERANCE_PX = 0.1f;
constexpr int MAX_SEGMENTS_PER_QUARTER = 64;
// Points closer than this (points) are merged: a zero-length edge has no normal.
constexpr float MERGE_DISTANCE = 1e-4f;
// Miter normals are the average edge normal divided by its squared length; at joins sharper
// than about 150° that explodes, so the squared length is floored (a 4× miter at most).
constexpr float MIN_MITER_LENGTH_SQ = 0.0625f;

Color32 scaleColor(Color32 c, float factor) {
    const auto scale = [factor](std::uint8_t v) {
        return static_cast<std::uint8_t>(std::lround(float(v) * std::clamp(factor, 0.0f, 1.0f)));
    };
    return {scale(c.r), scale(c.g), scale(c.b), scale(c.a)};
}

float cross(Vec2 a, Vec2 b) {
    return a.x * b.y - a.y * b.x;
}

// Segments for one quarter circle of radius r so the sagitta r·(1 − cos(θ/2)) stays under the
// tolerance: large radii get more segments, tiny ones a single chord.
int quarterSegments(float radiusPt, float pixelsPerPoint) {
    const float radiusPx = radiusPt * pixelsPerPoint;
    if (radiusPx <= ARC_TOLERANCE_PX)
        return 1;
    const float step = 2.0f * std::acos(1.0f - ARC_TOLERANCE_PX / radiusPx);
    const int segments = int(std::ceil(0.5f * std::numbers::pi_v<float> / step));
    return std::clamp(segments, 1, MAX_SEGMENTS_PER_QUARTER);
}

// Points on the arc from angle a0 to a1 (inclusive); with y down, growing angles run clockwise
// on screen.
void appendArc(std::vector<Vec2>& out, Vec2 centre, float radius, float a0, float a1,
               int segments) {
    for (int i = 0; i <= segments; ++i) {
        const float a = a0 + (a1 - a0) * float(i) / float(segments);
        out.push_back(centre + radius * Vec2(std::cos(a), std::sin(a)));
    }
}

// Both path builders overwrite `path` (scratch storage reused across shapes: no allocation per
// shape once it has grown).
void roundedRectPath(std::vector<Vec2>& path, const Rect& rect, float rounding,
                     float pixelsPerPoint) {
    const float r = std::clamp(rounding, 0.0f, 0.5f * std::min(rect.width(), rect.height()));
    path.clear();
    if (r <= 0.0f) {
        path.insert(path.end(),
                    {rect.min, {rect.max.x, rect.min.y}, rect.max, {rect.min.x, rect.max.y}});
        return;
    }
    const int n = quarterSegments(r, pixelsPerPoint);
    constexpr float PI = std::numbers::pi_v<float>;
    appendArc(path, {rect.min.x + r, rect.min.y + r}, r, PI, 1.5f * PI, n);
    appendArc(path, {rect.max.x - r, rect.min.y + r}, r, 1.5f * PI, 2.0f * PI, n);
    appendArc(path, {rect.max.x - r, rect.max.y - r}, r, 0.0f, 0.5f * PI, n);
    appendArc(path, {rect.min.x + r, rect.max.y - r}, r, 0.5f * PI, PI, n);
}

void circlePath(std::vector<Vec2>& path, Vec2 centre, float radius, float pixelsPerPoint) {
    // At least 8 points: a tiny circle (a radio dot) still reads as round.
    const int n = std::max(2, quarterSegments(radius, pixelsPerPoint));
    path.clear();
    appendArc(path, centre, radius, 0.0f, 2.0f * std::numbers::pi_v<float>, 4 * n);
    // The arc repeats its first point at 2π.
    path.pop_back();
}

// Drops non-finite and repeated points in place (and, for closed paths, a last point equal to
// the first).
void removeDuplicates(std::vector<Vec2>& points, bool closed) {
    std::size_t kept = 0;
    for (const Vec2 p : points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            continue;
        if (kept == 0 || glm::distance(points[kept - 1], p) > MERGE_DISTANCE)
            points[kept++] = p;
    }
    points.resize(kept);
    if (closed && kept > 1 && glm::distance(points.front(), points.back()) <= MERGE_DISTANCE)
        points.pop_back();
}

// The normal of edge a→b, to the left of its direction in y-down coordinates ((d.y, −d.x)):
// outward for a clockwise-on-screen outline.
Vec2 edgeNormal(Vec2 a, Vec2 b) {
    const Vec2 d = glm::normalize(b - a);
    return {d.y, -d.x};
}

// The join normal at a vertex between edges with normals n0 and n1, long enough that offsets
// along it keep both edges parallel (a miter), floored at sharp joins.
Vec2 miterNormal(Vec2 n0, Vec2 n1) {
    const Vec2 average = 0.5f * (n0 + n1);
    const float lengthSq = glm::dot(average, average);
    if (lengthSq < 1e-12f)
        return n1;
    return average / std::max(lengthSq, MIN_MITER_LENGTH_SQ);
}

// Per-vertex miter normals of a path into `normals` (`edges` is scratch); open ends take their
// one edge's normal. `sign` −1 flips them (a counter-clockwise outline's outward side).
void pathNormals(const std::vector<Vec2>& p, bool closed, float sign, std::vector<Vec2>& edges,
                 std::vector<Vec2>& normals) {
    const std::size_t n = p.size();
    edges.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        edges[i] = sign * edgeNormal(p[i], p[(i + 1) % n]);
    normals.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (!closed && i == 0)
            normals[i] = edges[0];
        else if (!closed && i == n - 1)
            normals[i] = edges[n - 2];
        else
            normals[i] = miterNormal(edges[(i + n - 1) % n], edges[i]);
    }
}

// Storage reused for every shape of one tessellate() call.
struct Scratch {
    std::vector<Vec2> path, edges, normals;
};

class MeshBuilder {
public:
    MeshBuilder(Mesh& mesh, Scratch& scratch, Vec2 whiteUv, float pixelsPerPoint)
        : mMesh(mesh),
          mScratch(scratch),
          mWhiteUv(whiteUv),
          mPixelsPerPoint(pixelsPerPoint),
          mFeather(featherWidth(pixelsPerPoint)) {}

    // Room for `vertices` and `indices` more, growing geometrically: a reserve of the exact
    // size per shape would reallocate on every shape.
    void reserve(std::size_t vertices, std::size_t indices) {
        const auto grow = [](auto& v, std::size_t more) {
            if (v.size() + more > v.capacity())
                v.reserve(std::max(2 * v.capacity(), v.size() + more));
        };
        grow(mMesh.vertices, vertices);
        grow(mMesh.indices, indices);
    }

    std::uint32_t vertex(Vec2 pos, Color32 color) { return vertex(pos, mWhiteUv, color); }
    std::uint32_t vertex(Vec2 pos, Vec2 uv, Color32 color) {
        mMesh.vertices.push_back({pos, uv, color});
        return static_cast<std::uint32_t>(mMesh.vertices.size() - 1);
    }
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        mMesh.indices.push_back(a);
        mMesh.indices.push_back(b);
        mMesh.indices.push_back(c);
    }
    void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }

    // A convex polygon: a fan over an inner outline half a feather inside the edge, plus a
    // band out to half a feather outside where alpha falls to zero. The band's average
    // coverage is 1/2 at the true edge, so the area covered equals the polygon's.
    void fillConvex(const std::vector<Vec2>& points, Color32 color) {
        if (points.size() < 3 || color.a == 0)
            return;
        float area2 = 0.0f;
        for (std::size_t i = 0; i < points.size(); ++i)
            area2 += cross(points[i], points[(i + 1) % points.size()]);
        if (std::abs(area2) < 1e-8f)
            return;
        // Edge normals point outward for positive (clockwise-on-screen) winding; flipped
        // otherwise. The fan's own winding does not matter (no face culling).
        std::vector<Vec2>& normals = mScratch.normals;
        pathNormals(points, true, area2 < 0.0f ? -1.0f : 1.0f, mScratch.edges, normals);
        reserve(2 * points.size(), 9 * points.size());
        const auto first = static_cast<std::uint32_t>(mMesh.vertices.size());
        const Color32 clear = Color32::transparent();
        const float half = 0.5f * mFeather;
        for (std::size_t i = 0; i < points.size(); ++i) {
            vertex(points[i] - half * normals[i], color);
            vertex(points[i] + half * normals[i], clear);
        }
        const auto n = static_cast<std::uint32_t>(points.size());
        for (std::uint32_t i = 1; i + 1 < n; ++i)
            triangle(first, first + 2 * i, first + 2 * (i + 1));
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::uint32_t j = (i + 1) % n;
            quad(first + 2 * i, first + 2 * j, first + 2 * j + 1, first + 2 * i + 1);
        }
    }

    // A polyline of `width` points centred on the path. Lines thinner than a pixel keep a
    // one-pixel profile (a tent two feathers wide) and fade instead, so their total coverage
    // stays proportional to the width rather than vanishing or aliasing.
    void stroke(const std::vector<Vec2>& points, bool closed, const Stroke& stroke) {
        if (points.size() < 2 || stroke.width <= 0.0f || stroke.color.a == 0)
            return;
        const bool isClosed = closed && points.size() > 2;
        std::vector<Vec2>& normals = mScratch.normals;
        pathNormals(points, isClosed, 1.0f, mScratch.edges, normals);
        reserve(4 * points.size(), 18 * points.size());
        const Color32 color = premultiply(stroke.color);
        const Color32 clear = Color32::transparent();
        const auto first = static_cast<std::uint32_t>(mMesh.vertices.size());
        const auto n = static_cast<std::uint32_t>(points.size());
        const std::uint32_t segments = isClosed ? n : n - 1;
        const float widthPx = stroke.width * mPixelsPerPoint;
        if (widthPx <= 1.0f) {
            const Color32 faded = scaleColor(color, widthPx);
            for (std::size_t i = 0; i < points.size(); ++i) {
                vertex(points[i] + mFeather * normals[i], clear);
                vertex(points[i], faded);
                vertex(points[i] - mFeather * normals[i], clear);
            }
            for (std::uint32_t s = 0; s < segments; ++s) {
                const std::uint32_t a = first + 3 * s;
                const std::uint32_t b = first + 3 * ((s + 1) % n);
                quad(a, b, b + 1, a + 1);
                quad(a + 1, b + 1, b + 2, a + 2);
            }
            return;
        }
        const float inner = 0.5f * (stroke.width - mFeather);
        const float outer = 0.5f * (stroke.width + mFeather);
        for (std::size_t i = 0; i < points.size(); ++i) {
            vertex(points[i] + outer * normals[i], clear);
            vertex(points[i] + inner * normals[i], color);
            vertex(points[i] - inner * normals[i], color);
            vertex(points[i] - outer * normals[i], clear);
        }
        for (std::uint32_t s = 0; s < segments; ++s) {
            const std::uint32_t a = first + 4 * s;
            const std::uint32_t b = first + 4 * ((s + 1) % n);
            quad(a, b, b + 1, a + 1);
            quad(a + 1, b + 1, b + 2, a + 2);
            quad(a + 2, b + 2, b + 3, a + 3);
        }
    }

    void texturedRect(const Rect& rect, const Rect& uv, Color32 color) {
        const std::uint32_t a = vertex(rect.min, uv.min, color);
        const std::uint32_t b = vertex({rect.max.x, rect.min.y}, {uv.max.x, uv.min.y}, color);
        const std::uint32_t c = vertex(rect.max, uv.max, color);
        const std::uint32_t d = vertex({rect.min.x, rect.max.y}, {uv.min.x, uv.max.y}, color);
        quad(a, b, c, d);
    }

    // Nearest physical pixel boundary, in points.
    float snap(float v) const { return std::round(v * mPixelsPerPoint) / mPixelsPerPoint; }

private:
    Mesh& mMesh;
    Scratch& mScratch;
    Vec2 mWhiteUv;
    float mPixelsPerPoint;
    float mFeather;
};

// The area a shape may touch, for culling against its clip.
Rect shapeBounds(const Shape& shape, float feather) {
    return std::visit(
        [feather](const auto& s) -> Rect {
            using T = std::decay_t<decltype(s)>;
            if constexpr (std::is_same_v<T, RectShape>) {
                return s.rect.expand(0.5f * s.stroke.width + feather);
            } else if constexpr (std::is_same_v<T, CircleShape>) {
                return Rect{s.centre, s.centre}.expand(s.radius + 0.5f * s.stroke.width + feather);
            } else if constexpr (std::is_same_v<T, PathShape>) {
                if (s.points.empty())
                    return {};
                Rect r{s.points.front(), s.points.front()};
                for (const Vec2 p : s.points)
                    r = {glm::min(r.min, p), glm::max(r.max, p)};
                // Miter joins reach up to 4 half-widths out (MIN_MITER_LENGTH_SQ).
                return r.expand(2.0f * s.stroke.width + 4.0f * feather);
            } else if constexpr (std::is_same_v<T, ImageShape>) {
                return s.rect;
            } else {
                // Text is culled glyph by glyph; an unbounded rect keeps it here.
                return Rect{Vec2(-1e30f), Vec2(1e30f)};
            }
        },
        shape);
}

bool overlaps(const Rect& a, const Rect& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

void tessellateText(MeshBuilder& out, const TextShape& text, const Rect& clip,
                    const FontAtlas& font) {
    if (text.color.a == 0)
        return;
    const Color32 color = premultiply(text.color);
    out.reserve(4 * text.text.size(), 6 * text.text.size());
    const float line = font.lineHeight(text.sizePt);
    const float ascent = font.ascent(text.sizePt);
    float penX = text.pos.x;
    float baseline = text.pos.y + ascent;
    for (std::size_t pos = 0; pos < text.text.size();) {
        const char32_t cp = decodeUtf8(text.text, pos);
        if (cp == U'\n') {
            penX = text.pos.x;
            baseline += line;
            continue;
        }
        const Glyph& glyph = font.glyph(cp, text.sizePt);
        // Glyph offsets are whole pixels, so snapping the pen puts every texel on a pixel.
        const Vec2 origin(out.snap(penX), out.snap(baseline));
        penX += glyph.advance;
        const Rect quad{origin + glyph.offset.min, origin + glyph.offset.max};
        if (quad.empty() || !overlaps(quad, clip))
            continue;
        out.texturedRect(quad, glyph.uv, color);
    }
}

}  // namespace

Color32 premultiply(Color32 c) {
    const auto mul = [a = unsigned(c.a)](std::uint8_t v) {
        return static_cast<std::uint8_t>((unsigned(v) * a + 127u) / 255u);
    };
    return {mul(c.r), mul(c.g), mul(c.b), c.a};
}

void tessellate(const std::vector<ClippedShape>& shapes, const FontAtlas& font,
                float pixelsPerPoint, std::vector<Mesh>& meshes) {
    // Rasterise every glyph first: a glyph added later could grow the atlas and move the uv of
    // quads (and of the white texel) already written.
    for (const ClippedShape& clipped : shapes) {
        if (const auto* text = std::get_if<TextShape>(&clipped.shape)) {
            for (std::size_t pos = 0; pos < text->text.size();)
                font.glyph(decodeUtf8(text->text, pos), text->sizePt);
        }
    }
    const Vec2 whiteUv = font.whiteUv();
    const float feather = featherWidth(pixelsPerPoint);

    // Meshes [0, used) are this frame's; those beyond keep last frame's capacity for reuse.
    std::size_t used = 0;
    Scratch scratch;
    for (const ClippedShape& clipped : shapes) {
        if (clipped.clip.empty() || !overlaps(shapeBounds(clipped.shape, feather), clipped.clip))
            continue;
        const auto* image = std::get_if<ImageShape>(&clipped.shape);
        const TextureId texture = image != nullptr ? image->texture : TextureId{0};
        // A mesh whose shapes all drew nothing is dropped; the one before it may match again.
        if (used > 0 && meshes[used - 1].vertices.empty())
            --used;
        if (used == 0 || meshes[used - 1].clip != clipped.clip ||
            meshes[used - 1].texture != texture) {
            if (used == meshes.size())
                meshes.emplace_back();
            Mesh& fresh = meshes[used++];
            fresh.clip = clipped.clip;
            fresh.texture = texture;
            fresh.vertices.clear();
            fresh.indices.clear();
        }
        MeshBuilder out(meshes[used - 1], scratch, whiteUv, pixelsPerPoint);
        std::visit(
            [&](const auto& s) {
                using T = std::decay_t<decltype(s)>;
                if constexpr (std::is_same_v<T, RectShape>) {
                    if (s.rect.empty())
                        return;
                    std::vector<Vec2>& path = scratch.path;
                    roundedRectPath(path, s.rect, s.rounding, pixelsPerPoint);
                    removeDuplicates(path, true);
                    out.fillConvex(path, premultiply(s.fill));
                    out.stroke(path, true, s.stroke);
                } else if constexpr (std::is_same_v<T, CircleShape>) {
                    if (!(s.radius > 0.0f))
                        return;
                    std::vector<Vec2>& path = scratch.path;
                    circlePath(path, s.centre, s.radius, pixelsPerPoint);
                    out.fillConvex(path, premultiply(s.fill));
                    out.stroke(path, true, s.stroke);
                } else if constexpr (std::is_same_v<T, PathShape>) {
                    std::vector<Vec2>& path = scratch.path;
                    path.assign(s.points.begin(), s.points.end());
                    removeDuplicates(path, s.closed);
                    // A fill closes the outline even when the stroke is left open.
                    out.fillConvex(path, premultiply(s.fill));
                    out.stroke(path, s.closed, s.stroke);
                } else if constexpr (std::is_same_v<T, TextShape>) {
                    tessellateText(out, s, clipped.clip, font);
                } else if constexpr (std::is_same_v<T, ImageShape>) {
                    if (!s.rect.empty() && s.tint.a != 0)
                        out.texturedRect(s.rect, s.uv, premultiply(s.tint));
                }
            },
            clipped.shape);
    }
    if (used > 0 && meshes[used - 1].vertices.empty())
        --used;
    meshes.resize(used);
}

std::vector<Mesh> tessellate(const std::vector<ClippedShape>& shapes, const FontAtlas& font,
                             float pixelsPerPoint) {
    std::vector<Mesh> meshes;
    tessellate(shapes, font, pixelsPerPoint, meshes);
    return meshes;
}

}  // namespace grass::ui
