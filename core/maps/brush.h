// Brush: painting environment maps (MapImage, SPEC §9/§12) with strokes across the mesh
// surface. A stroke is the sequence of surface hits of the editor's ray casts, in world units
// (metres for glTF). Dabs are spaced along the path between hits and pick texels by 3D distance
// through a TexelSurface, so a radius is in metres whatever the UV layout, and a stroke across a
// UV seam paints both sides. Each stroke yields a PaintRecord for exact undo/redo and for
// re-growing only the grass near the change.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "maps/map_image.h"
#include "maps/texel_surface.h"
#include "mesh/surface_mesh.h"

namespace grass::core {

// Weight across the dab, by distance / radius. Smooth: 1 − smoothstep (0.5 at half radius, flat
// at centre and rim); Linear: a cone; Constant: a hard disc.
enum class BrushFalloff { Smooth, Linear, Constant };

enum class BrushMode {
    Add,       // v += w
    Subtract,  // v -= w
    Smooth,    // v moves by w toward the mean of its 3 × 3 neighbours; at seams, found in 3D
    Set,       // v = mix(v, setValue, w)
};

// w = strength · brushFalloff(falloff, d / radiusM), applied once per dab, so overlapping dabs
// build up (strength is a per-dab flow, not a stroke opacity). Results are clamped to [0, 1].
//
// Out-of-range values are sanitised, never rejected (sanitizedBrush): a radius that is NaN,
// infinite or <= 0 paints nothing; strength and setValue are clamped to [0, 1] (NaN gives 0);
// a dabSpacing that is NaN or <= 0 gives the default, and it is clamped to [0.05, 2].
struct BrushSettings {
    float radiusM = 1.0f;
    float strength = 0.5f;
    BrushFalloff falloff = BrushFalloff::Smooth;
    BrushMode mode = BrushMode::Add;
    float setValue = 1.0f;
    // Distance between dabs as a fraction of the radius: at 1/4 a fast stroke shows no gaps and
    // no visible dab scallops.
    float dabSpacing = 0.25f;
    bool operator==(const BrushSettings&) const = default;
};

BrushSettings sanitizedBrush(const BrushSettings& settings);

// 1 at 0 (and below), 0 at >= 1 and for NaN, non-increasing in between.
float brushFalloff(BrushFalloff falloff, float distanceOverRadius);

// What one stroke changed: every texel whose value changed at least once, in ascending index
// order, with its value before the stroke's first change and after the stroke. A texel changed
// and changed back stays listed (before == after). Undo and redo write these values back, so
// they are bit-exact whatever happened in between on other texels.
struct PaintRecord {
    std::vector<std::uint32_t> texelIndex;
    std::vector<float> before;
    std::vector<float> after;
    // World bounds of the changed texels' positions, padded by 1.5 of their texel size:
    // MapImage::sample blends texels up to one texel away, so grass that far off can see the
    // change. Re-grow the grass patches that intersect it. Meaningless when empty().
    Bounds touchedBounds;

    bool empty() const { return texelIndex.empty(); }
    bool operator==(const PaintRecord&) const = default;
};

// A stroke in progress, for live painting: feed hits as the ray casts arrive, read the record
// when the stroke ends. Holds references: `map` and `surface` must outlive it and the map must
// not be resized meanwhile. Preconditions (GRASS_ASSERT): map and surface have the same size
// and map.texels matches it.
class PaintStroke {
public:
    PaintStroke(MapImage& map, const TexelSurface& surface, const BrushSettings& settings);

    // Dabs at the first hit ever, then every radius · dabSpacing along the straight segments
    // between hits (the remainder carries over to the next call). Non-finite hits are skipped.
    // A jump between far-apart hits is painted along the straight line between them: the
    // caller should end the stroke when the ray leaves the mesh.
    void addHits(std::span<const glm::vec3> hits);
    std::size_t dabCount() const { return mDabs; }
    PaintRecord record() const;

    // Pen pressure in [0, 1] (NaN gives 0) scales the strength of the dabs that follow, as a
    // tablet's pen does; 1 (the default) paints at the settings' strength.
    void setPressure(float pressure);

    // Where the map changed since the last call (padded like PaintRecord::touchedBounds) and the
    // largest changed texel's size on the surface, so a live editor can re-grow just that much
    // after every mouse move; nullopt when nothing changed since.
    struct ChangedRegion {
        Bounds bounds;
        float texelMarginM = 0.0f;
    };
    std::optional<ChangedRegion> takeChangedRegion();

private:
    void dab(glm::vec3 centre);
    float meanNeighbourDifference(std::uint32_t texel);

    MapImage* mMap;
    const TexelSurface* mSurface;
    BrushSettings mSettings;
    bool mStarted = false;
    glm::vec3 mLastHit{0.0f};
    float mToNextDabM = 0.0f;
    std::size_t mDabs = 0;
    float mPressure = 1.0f;
    std::optional<ChangedRegion> mChanged;
    // Per texel, its entry in mTouched / mBefore (NO_ENTRY if untouched); allocated on the
    // first change so strokes that change nothing cost nothing.
    std::vector<std::uint32_t> mEntry;
    std::vector<std::uint32_t> mTouched;
    std::vector<float> mBefore;
    // Scratch buffers reused by every dab.
    std::vector<std::uint32_t> mDabTexels;
    std::vector<std::uint32_t> mNeighbours;
    std::vector<float> mNewValues;
};

// A whole stroke at once: PaintStroke over all hits.
PaintRecord paintStroke(MapImage& map, const TexelSurface& surface, const BrushSettings& settings,
                        std::span<const glm::vec3> hits);

// Write the record's before / after values back. Preconditions (GRASS_ASSERT): the record's
// arrays have equal length and every index lies inside the map.
void undoPaint(MapImage& map, const PaintRecord& record);
void redoPaint(MapImage& map, const PaintRecord& record);

}  // namespace grass::core
