// The strokes of `grass paint` painted one by one with the editor's brush (core::ScenePainter)
// into the map a layer grows from, the grass each stroke can reach re-grown right after it, as
// the editor does at the end of a stroke; a line per stroke and the total on stdout.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "edit/scene_paint.h"
#include "maps/texel_surface.h"
#include "util/result.h"

namespace grass::cli {

// Where the strokes go: the painter on the grown scene, the layer and its map being painted
// (the one its field grows from) and the texel surface the points lie on.
struct PaintCanvas {
    core::ScenePainter& painter;
    std::size_t layerIndex;
    core::LayerMap which;
    const core::LayerField& field;
    const core::MapImage& painted;
    const core::TexelSurface& surface;
};

// Paints the strokes (each a list of surface points) and returns how many texels the whole run
// changed: a texel painted by two strokes counts once, one painted back not at all.
Result<std::size_t> paintAndRegrow(const PaintCanvas& canvas, const core::BrushSettings& brush,
                                   const std::vector<std::vector<glm::vec3>>& points);

// "[x y z] .. [x y z]" with three significant digits.
std::string boundsText(const core::Bounds& bounds);

}  // namespace grass::cli
