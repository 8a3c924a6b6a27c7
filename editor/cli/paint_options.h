// The command line of `grass paint`: its options, what the command line alone can refute (the
// map's name, the strokes' text) and the brush they describe.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "maps/brush.h"
#include "scene/layer_growth.h"
#include "util/result.h"

namespace grass::cli {

struct PaintArgs {
    std::string project, map, layer, mode = "add", falloff = "smooth", file;
    std::vector<std::string> strokes;
    double radiusM = 0.0, strength = 0.5, value = 1.0, spacing = 0.25;
    bool uv = false, dryRun = false;
    bool radiusGiven = false;  // else the radius follows the mesh (DEFAULT_RADIUS_SHARE)
};

// What the command line asks to paint, read before any file.
struct PaintStrokes {
    core::LayerMap which = core::LayerMap::Density;
    // Per stroke its points: world positions, or with --uv "u,v,0" until placed on the mesh.
    std::vector<std::vector<glm::vec3>> points;
};

// Reads the command line (the repeated --stroke options first) into `args`. Returns the exit
// code when the command ends here (--help, or a usage error printed); nothing when it goes on.
std::optional<int> parsePaintArgs(const std::vector<std::string>& argv, PaintArgs& args);

// Everything the command line alone can refute is refuted before any file is read: the map's
// name, no stroke, a stroke's text.
Result<PaintStrokes> readPaintStrokes(const PaintArgs& args);

// The brush of --mode, --falloff, --strength, --value, --spacing and --radius (0 when not given:
// the caller sizes it to the mesh).
core::BrushSettings brushSettings(const PaintArgs& args);

}  // namespace grass::cli
