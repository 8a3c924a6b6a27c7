#include "edit/scene_paint.h"

#include <algorithm>

#include "util/assert.h"

namespace grass::core {

ScenePainter::ScenePainter(Scene& scene, GrassLightingDesc lighting)
    : mScene(&scene), mLighting(std::move(lighting)) {}

const TexelSurface& ScenePainter::surface(glm::ivec2 resolution) {
    auto& slot = mSurfaces[{resolution.x, resolution.y}];
    if (!slot)
        slot = std::make_unique<TexelSurface>(mScene->mesh, resolution.x, resolution.y);
    return *slot;
}

void ScenePainter::begin(std::size_t layer, LayerMap map, glm::ivec2 resolution,
                         const BrushSettings& brush) {
    GRASS_ASSERT(layer < mScene->layers.size());
    GRASS_ASSERT(resolution.x >= 1 && resolution.y >= 1);
    GRASS_ASSERT(!active());
    MapImage& painted = layerMap(mScene->layers[layer].source.maps, map);
    // An absent map reads 1 everywhere, so a new one starts as what the grass already saw.
    if (painted.texels.empty())
        painted = makeConstantMap(resolution.x, resolution.y, 1.0f);
    const TexelSurface& texels = surface({painted.width, painted.height});
    mStroke = std::make_unique<PaintStroke>(painted, texels, brush);
    mLayer = layer;
    mMap = map;
}

void ScenePainter::adoptSurface(std::unique_ptr<TexelSurface> surface) {
    mSurfaces[{surface->width(), surface->height()}] = std::move(surface);
}

Result<RegrowReport> ScenePainter::paintTo(glm::vec3 hitWorld, float pressure) {
    GRASS_ASSERT(active());
    mStroke->setPressure(pressure);
    addHits(std::span<const glm::vec3>(&hitWorld, 1));
    const auto changed = mStroke->takeChangedRegion();
    if (!changed)
        return RegrowReport{};
    auto report = regrowLayerRegion(mScene->layers[mLayer], changed->bounds, changed->texelMarginM,
                                    mLighting, ShadingUpdate::RegrownOnly);
    if (report && report->shadingPending) {
        const Bounds& b = report->pendingShadeRegion;
        mPendingShade = mPendingShade ? Bounds{glm::min(mPendingShade->min, b.min),
                                               glm::max(mPendingShade->max, b.max)}
                                      : b;
    }
    return report;
}

Result<RegrowReport> ScenePainter::settleShading() {
    if (!mPendingShade)
        return RegrowReport{};
    const Bounds region = *mPendingShade;
    mPendingShade.reset();
    return rebakeLayerShading(mScene->layers[mLayer], region, mLighting);
}

void ScenePainter::addHits(std::span<const glm::vec3> hits) {
    GRASS_ASSERT(active());
    mStroke->addHits(hits);
}

Result<RegrowReport> ScenePainter::regrowChanged() {
    GRASS_ASSERT(active());
    const auto changed = mStroke->takeChangedRegion();
    if (!changed)
        return RegrowReport{};
    return regrow(mLayer, changed->bounds, changed->texelMarginM);
}

std::optional<PaintEdit> ScenePainter::end() {
    GRASS_ASSERT(active());
    // A caller that did not settle: the field is made exact all the same.
    if (mPendingShade)
        (void)settleShading();
    PaintEdit edit{mLayer, mMap, mStroke->record()};
    mStroke.reset();
    if (edit.record.empty())
        return std::nullopt;
    return edit;
}

Result<RegrowReport> ScenePainter::apply(const PaintEdit& edit, bool undo) {
    if (edit.layer >= mScene->layers.size())
        return Error{"undo", "the painted layer no longer exists"};
    MapImage& map = layerMap(mScene->layers[edit.layer].source.maps, edit.map);
    const std::size_t texels = map.texels.size();
    const bool fits = std::all_of(edit.record.texelIndex.begin(), edit.record.texelIndex.end(),
                                  [&](std::uint32_t texel) { return texel < texels; });
    if (!fits || edit.record.empty())
        return Error{"undo", "the painted map changed size since the stroke"};
    if (undo)
        undoPaint(map, edit.record);
    else
        redoPaint(map, edit.record);
    const TexelSurface& texelSurface = surface({map.width, map.height});
    float marginM = 0.0f;
    for (const std::uint32_t texel : edit.record.texelIndex)
        marginM = std::max(marginM, texelSurface.texelSizeM(texel));
    return regrow(edit.layer, edit.record.touchedBounds, marginM);
}

Result<std::pair<std::optional<PaintEdit>, RegrowReport>> ScenePainter::replaceMap(
    std::size_t layer, LayerMap which, const MapImage& image) {
    GRASS_ASSERT(layer < mScene->layers.size());
    GRASS_ASSERT(!active());
    MapImage& map = layerMap(mScene->layers[layer].source.maps, which);
    if (map.texels.empty())
        map = makeConstantMap(image.width, image.height, 1.0f);  // what the grass saw so far
    if (image.width != map.width || image.height != map.height)
        return Error{"import", "the picture is " + std::to_string(image.width) + "×" +
                                   std::to_string(image.height) + ", the map " +
                                   std::to_string(map.width) + "×" + std::to_string(map.height)};
    PaintEdit edit{layer, which, {}};
    PaintRecord& record = edit.record;
    for (std::size_t i = 0; i < map.texels.size(); ++i)
        if (map.texels[i] != image.texels[i]) {
            record.texelIndex.push_back(static_cast<std::uint32_t>(i));
            record.before.push_back(map.texels[i]);
            record.after.push_back(image.texels[i]);
        }
    if (record.empty())
        return std::pair<std::optional<PaintEdit>, RegrowReport>{};
    // The whole surface, padded as a stroke's bounds are (brush.h).
    const Bounds& bounds = mScene->bounds;
    const glm::vec3 pad(1e-3f * glm::length(bounds.size()));
    record.touchedBounds = {bounds.min - pad, bounds.max + pad};
    auto report = apply(edit, false);
    if (!report)
        return report.error();
    return std::pair<std::optional<PaintEdit>, RegrowReport>{std::move(edit), std::move(*report)};
}

Result<RegrowReport> ScenePainter::regrow(std::size_t layer, const Bounds& region,
                                          float texelMarginM) {
    return regrowLayerRegion(mScene->layers[layer], region, texelMarginM, mLighting);
}

}  // namespace grass::core
