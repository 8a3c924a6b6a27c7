#include "cli/paint_options.h"

#include "cli/commands.h"
#include "cli/parse_arguments.h"
#include "cli/stroke_text.h"
#include "util/arg_parser.h"

namespace grass::cli {

namespace {

// The options of the brush itself: how one dab weighs and where dabs fall.
void describeBrushOptions(ArgParser& parser, PaintArgs& args) {
    parser.choice("--mode", {"add", "subtract", "smooth", "set"},
                  "add or subtract the brush weight, smooth toward the neighbours, or set toward "
                  "--value",
                  &args.mode);
    // A micrometre at least: a brush of radius 0 paints nothing.
    parser.number("--radius", "M", "brush radius in world units", &args.radiusM, 1e-6, 1e9,
                  "5 % of the mesh bounds diagonal");
    parser.number("--strength", "S", "weight of one dab at its centre", &args.strength, 0.0, 1.0,
                  "0.5");
    parser.choice("--falloff", {"smooth", "linear", "constant"},
                  "weight across a dab: 1 − smoothstep, a cone, or a hard disc", &args.falloff);
    parser.number("--value", "V", "the value --mode set paints toward", &args.value, 0.0, 1.0, "1");
    parser.number("--spacing", "F", "distance between dabs as a fraction of the radius",
                  &args.spacing, 0.05, 2.0, "0.25");
}

Result<core::LayerMap> parseMapName(const std::string& map) {
    for (const core::LayerMap which : core::ALL_LAYER_MAPS)
        if (map == core::layerMapName(which))
            return which;
    return makeError("--map", map.empty() ? "missing: give --map density, soil, light or cut"
                                          : "expected density, soil, light or cut, got '" + map + "'");
}

}  // namespace

std::optional<int> parsePaintArgs(const std::vector<std::string>& argv, PaintArgs& args) {
    // --stroke repeats, so takeStrokes reads it; the parser lists it for --help only.
    std::string strokeForHelp;
    ArgParser parser(
        "grass paint <project-dir|project.json> --map density|soil|light|cut --stroke \"x,y,z; ...\" "
        "[--stroke ...] [options]",
        "Paints one map of a layer (density, or soil / light of the growth model, SPEC §9) with "
        "brush strokes across the mesh surface, as the editor's brush does, and saves it "
        "atomically. A layer without that map gets a new one (map_resolution, 1 everywhere, "
        "16-bit PNG) and project.json is updated to name it; nothing else in the project "
        "changes. Prints per stroke the dabs, the texels changed, the touched bounds and the "
        "grass patches re-grown (and how long that took); for density also the live blades.");
    addProjectArgument(parser, &args.project, true);
    parser.text("--map", "density|soil|light|cut", "which of the layer's maps to paint (required); cut: the height blades are cut to, a share of their own",
                &args.map);
    parser.text("--stroke", "\"x,y,z; x,y,z; ...\"",
                "one stroke: surface hits in world units, separated by ';'; repeat for more "
                "strokes (at least one)",
                &strokeForHelp);
    parser.text("--layer", "NAME", "which layer (default: the first)", &args.layer);
    parser.flag("--uv",
                "stroke points are \"u,v\" in the map's UV space, placed on the surface at the "
                "texel they fall in (error if that is off the mesh)",
                &args.uv);
    describeBrushOptions(parser, args);
    parser.text("--file", "RELPATH",
                "where to save the map, relative to the project folder, and name it in "
                "project.json (default: the layer's file, else maps/<layer>-<map>.png)",
                &args.file);
    parser.flag("--dry-run", "paint and report, but write nothing", &args.dryRun);

    std::vector<std::string> rest = argv;
    auto strokes = takeStrokes(rest);
    if (!strokes) {
        printError("paint", strokes.error().str());
        return EXIT_USAGE;
    }
    if (const auto exitCode = parseArguments(parser, rest, "paint"))
        return exitCode;
    args.strokes = std::move(*strokes);
    args.radiusGiven = parser.given("--radius");
    return std::nullopt;
}

Result<PaintStrokes> readPaintStrokes(const PaintArgs& args) {
    PaintStrokes strokes;
    auto which = parseMapName(args.map);
    if (!which)
        return which.error();
    strokes.which = *which;
    if (args.strokes.empty())
        return makeError("--stroke", "missing: give at least one --stroke \"x,y,z; x,y,z\"");
    for (std::size_t s = 0; s < args.strokes.size(); ++s) {
        auto stroke = parseStroke(args.strokes[s], s + 1, args.uv ? 2 : 3);
        if (!stroke)
            return stroke.error();
        strokes.points.push_back(std::move(*stroke));
    }
    return strokes;
}

core::BrushSettings brushSettings(const PaintArgs& args) {
    core::BrushSettings brush;
    brush.mode = args.mode == "add"        ? core::BrushMode::Add
                 : args.mode == "subtract" ? core::BrushMode::Subtract
                 : args.mode == "smooth"   ? core::BrushMode::Smooth
                                           : core::BrushMode::Set;
    brush.falloff = args.falloff == "smooth"   ? core::BrushFalloff::Smooth
                    : args.falloff == "linear" ? core::BrushFalloff::Linear
                                               : core::BrushFalloff::Constant;
    brush.strength = static_cast<float>(args.strength);
    brush.setValue = static_cast<float>(args.value);
    brush.dabSpacing = static_cast<float>(args.spacing);
    brush.radiusM = static_cast<float>(args.radiusM);
    return brush;
}

}  // namespace grass::cli
