// ScenePainter: the editor's brush on a live Scene (issue 8). A stroke is fed the surface hits of
// the viewport's ray casts as the mouse moves; after each hit the grass patches the new dabs can
// reach re-grow (regrowLayerRegion), so the field follows the brush within the frame and the
// renderer re-uploads only those patches. A finished stroke becomes a PaintEdit for the history;
// applying one backwards or forwards writes its texels back bit-exactly and re-grows the region
// it touched.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <utility>

#include "edit/history.h"
#include "maps/brush.h"
#include "maps/texel_surface.h"
#include "scene/scene.h"
#include "util/result.h"

namespace grass::core {

class ScenePainter {
public:
    // `scene` must outlive the painter; its mesh must not change meanwhile.
    ScenePainter(Scene& scene, GrassLightingDesc lighting);

    // Starts a stroke on `map` of layer `layer` (an index into scene.layers). A layer without
    // that map gets one of `resolution`, 1 everywhere: what its grass grew from so far.
    // Preconditions (GRASS_ASSERT): layer in range, resolution >= 1, no stroke active.
    void begin(std::size_t layer, LayerMap map, glm::ivec2 resolution, const BrushSettings& brush);
    bool active() const { return mStroke != nullptr; }
    std::size_t layer() const { return mLayer; }  // the stroke's (or the last stroke's) layer
    // Paints from the last hit (or dabs, on the first) to `hitWorld` with the pen's pressure and
    // re-grows what changed. A dab that adds or removes blades re-bakes only their own shading
    // (ShadingUpdate::RegrownOnly): the neighbours' AO and blurred normals wait for
    // settleShading(), so a density dab costs what its patches cost (issue 24).
    // Preconditions: active().
    Result<RegrowReport> paintTo(glm::vec3 hitWorld, float pressure = 1.0f);
    // The exact re-bake of every neighbourhood the stroke's dabs left pending (nothing when none
    // did); the report names the patches to re-upload. Call it when the stroke ends, before
    // end() (which settles what is still pending itself, without a report).
    Result<RegrowReport> settleShading();
    // A scripted stroke (`grass paint`): paints along many hits without re-growing; then
    // regrowChanged() re-grows once what they changed (an empty report when nothing did).
    // Preconditions: active().
    void addHits(std::span<const glm::vec3> hits);
    Result<RegrowReport> regrowChanged();
    std::size_t dabCount() const { return mStroke ? mStroke->dabCount() : 0; }
    // Ends the stroke: the edit to record, or nullopt when no texel changed.
    std::optional<PaintEdit> end();

    // Replaces a whole map with `image` (an imported picture, already at the map's size, or at
    // the layer's resolution when the layer has no map yet) as one edit, like a stroke over
    // every texel that differs, and re-grows the layer. nullopt in the edit: nothing differed.
    // Preconditions: no stroke active, layer in range.
    Result<std::pair<std::optional<PaintEdit>, RegrowReport>> replaceMap(std::size_t layer,
                                                                         LayerMap map,
                                                                         const MapImage& image);

    // Writes an edit's `before` (undo) or `after` (redo) values back and re-grows what they touch.
    // An error (nothing changed) when the layer or the map no longer matches the edit.
    Result<RegrowReport> apply(const PaintEdit& edit, bool undo);

    // The texel positions of a map of this size on the scene's mesh, built on first use.
    const TexelSurface& surface(glm::ivec2 resolution);
    // Hands over a surface already built on the scene's mesh (the caller needed it first).
    void adoptSurface(std::unique_ptr<TexelSurface> surface);

private:
    Result<RegrowReport> regrow(std::size_t layer, const Bounds& region, float texelMarginM);

    Scene* mScene;
    GrassLightingDesc mLighting;
    std::map<std::pair<int, int>, std::unique_ptr<TexelSurface>> mSurfaces;
    std::unique_ptr<PaintStroke> mStroke;
    std::optional<Bounds> mPendingShade;  // union of the dabs' pendingShadeRegion
    std::size_t mLayer = 0;
    LayerMap mMap = LayerMap::Density;
};

}  // namespace grass::core
