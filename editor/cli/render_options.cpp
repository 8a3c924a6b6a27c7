#include "cli/render_options.h"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "cli/output_files.h"
#include "cli/parse_arguments.h"
#include "cli/preset_option.h"
#include "gl/headless_context.h"
#include "mesh/gltf_loader.h"
#include "scene/turntable.h"
#include "util/arg_parser.h"
#include "util/image_file.h"

namespace grass::cli {

namespace {

// The options of the image itself: what draws it and how it looks.
void describeImageOptions(ArgParser& parser, RenderArgs& args) {
    parser.text("--out", "FILE",
                "image to write (default: <project name>.png in the working folder, the name kept "
                "to letters, digits, - and _)",
                &args.out);
    parser.integer("--width", "image width in pixels (default: the project's)", &args.width, 1,
                   16384);
    parser.integer("--height", "image height in pixels (default: the project's)", &args.height, 1,
                   16384);
    parser.unsignedInteger("--seed", "scatter seed, overrides the project's", &args.seed);
    parser.text("--camera", "NAME", "which of the project's cameras (default: the first)",
                &args.camera);
    parser.choice("--geometry", {"project", "auto", "tess", "strips"},
                  "blade geometry path: tessellation shaders or instanced strips; auto = strips on "
                  "software GL, tessellation on a GPU",
                  &args.geometry);
    parser.choice(
        "--shape", {"project", "quad", "triangle", "quadratic", "triangle-tip", "dandelion"},
        "blade outline for every layer (SPEC §7); project = each layer's own", &args.shape);
    parser.choice("--technique", {"project", "blades", "billboards", "hybrid", "growth"},
                  "what draws the grass: geometric blades, star billboards (SPEC §8), blades "
                  "near the camera cross-faded into billboards far away, or Kim & Cho's "
                  "instanced stem sets grown from the soil and light maps (SPEC §9)",
                  &args.technique);
    parser.choice("--animation", {"project", "per-cluster", "per-vertex", "per-object"},
                  "billboard wind animation: a CPU offset per cluster (one draw each), or in the "
                  "shader by vertex position or by object centre",
                  &args.animation);
    parser.choice("--lighting", {"project", "grass", "simple", "article"},
                  "blade lighting: the grass model of SPEC §10, a wrapped Lambert, or article "
                  "003's model exactly as written (docs/rendering.md compares them)",
                  &args.lighting);
    parser.flag("--light-per-vertex",
                "light blades per vertex (as the article does) instead of per pixel",
                &args.lightPerVertex);
    parser.flag("--light-per-pixel",
                "light every blade per pixel; by default the blades beyond the LOD distance "
                "(half or quarter segments, a few pixels wide) are lit per vertex",
                &args.lightPerPixel);
    parser.choice("--snow-exposure", {"auto", "pixel", "vertex"},
                  "where the snow surface measures its exposure to the sky (the shelter edge): "
                  "per pixel (exact), or per vertex of the tessellated surface, interpolated "
                  "(cheaper, softer edges; docs/snow.md); auto: per vertex on software GL",
                  &args.snowExposure);
    parser.flag("--snow",
                "snow on (SPEC §11) with the project's snow settings (their defaults when the "
                "project has none); --stats adds the snow pass time",
                &args.snow);
    parser.number("--lod-distance", "M",
                  "blades nearer than M metres get every strip segment / tessellation level, "
                  "half up to 3·M, a quarter beyond",
                  &args.lodDistanceM, 0.0, 1e5,
                  "the project's lod_distance; 0: full detail everywhere");
    parser.number("--lod-blend", "SHARE",
                  "blades morph into the next level of detail over the last SHARE of each "
                  "level's distance range, so nothing pops where the level changes",
                  &args.lodBlend, 0.0, 1.0, "0.25; 0: levels switch hard");
    addPresetOption(parser, &args.preset);
    parser.choice("--msaa", {"project", "0", "1", "2", "4", "8"},
                  "multisample anti-aliasing samples per pixel", &args.msaa);
}

// The options of the run around the image: frames, views, the field's time, what is counted.
void describeRunOptions(ArgParser& parser, RenderArgs& args) {
    parser.integer("--frames", "frames to draw and time", &args.frames, 1, 1000);
    parser.integer("--turntable",
                   "render N views (0: one image) orbiting 360° about the vertical axis through "
                   "the camera's target, each drawn once, to <out stem>_0000.png ... and a contact "
                   "sheet <out stem>_sheet.png; with --time every view shows the same moment; "
                   "Ctrl+C ends the turn after the view under way, with the sheet of the views "
                   "done (exit 130)",
                   &args.turntable, core::TURNTABLE_MIN_FRAMES, core::TURNTABLE_MAX_FRAMES);
    parser.integer("--blades", "with --mesh: about how many blades to grow", &args.blades, 1,
                   20000000);
    parser.number("--time", "T",
                  "simulate the project's physics (wind, colliders, gravity) for T seconds first, "
                  "so the picture shows the wind and the trails",
                  &args.timeS, 0.0, 86400.0, "0: blades at rest");
    parser.choice("--backend", {"auto", "gpu", "cpu"},
                  "with --time: run the physics as the compute shader or on the CPU (SIMD); "
                  "auto: the CPU on software GL, where it is ~10x faster, the GPU elsewhere",
                  &args.backend);
    parser.text("--cull", "LIST",
                "per-blade culling tests, comma-separated: orientation,frustum,distance,occlusion; "
                "all or none (none draws every blade); distance thins only where the project "
                "has a render.thinning_distance (0 turns it off)",
                &args.cull);
    parser.text("--stats", "FILE.json",
                "write the last frame's blade counts per cull test and pass timings as JSON",
                &args.stats);
    parser.flag("--gl-debug", "print GL debug output (errors and warnings from the driver)",
                &args.glDebug);
}

// `--cull LIST`: which of the per-blade tests run (SPEC §6); collectStats is set by the caller.
Result<render::CullSettings> parseCullList(const std::string& list) {
    render::CullSettings settings;
    if (list == "all")
        return settings;
    settings.orientation = settings.frustum = settings.distance = settings.occlusion = false;
    if (list == "none")
        return settings;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string name = list.substr(start, comma - start);
        if (name == "orientation")
            settings.orientation = true;
        else if (name == "frustum")
            settings.frustum = true;
        else if (name == "distance")
            settings.distance = true;
        else if (name == "occlusion")
            settings.occlusion = true;
        else
            return makeError("--cull", "unknown test \"" + name +
                                           "\" (valid: orientation, frustum, distance, "
                                           "occlusion, or all, none)");
        start = comma + 1;
    }
    return settings;
}

// Exactly one input: a project or --mesh (a glTF file given as the project is taken as --mesh).
Result<void> checkInput(const RenderArgs& args) {
    if (args.project.empty() == args.mesh.empty())
        return makeError("", args.mesh.empty() ? "give a project folder or --mesh FILE (see --help)"
                                               : "give either a project or --mesh, not both");
    if ((args.unit != "m" || args.up != "+Y") && args.mesh.empty())
        return makeError(args.unit != "m" ? "--unit" : "--up",
                         "applies to --mesh only (a project says its mesh's unit and up axis in "
                         "project.json: /mesh/unit, /mesh/up)");
    if (args.lightPerVertex && args.lightPerPixel)
        return makeError("--light-per-pixel", "cannot be given with --light-per-vertex: choose one");
    if (const auto unit = core::parseMeshUnit(args.unit); !unit)
        return makeError("--unit", unit.error().message);
    if (const auto up = core::parseUpAxis(args.up); !up)
        return makeError("--up", up.error().message);
    return {};
}

// Fail before the (possibly long) scene build and render when an output can't be written.
Result<void> checkOutputsWritable(const RenderArgs& args) {
    if (auto writable = checkOutputWritable(args.stats, "--stats", "stats.json"); !writable)
        return writable;
    if (!args.out.empty())
        if (auto writable = checkImageWritable(args.out); !writable)
            return writable;
    return {};
}

// The render options' overrides of the project's that the command line names.
void applyRenderOverrides(const RenderArgs& args, render::RenderOptions& options) {
    if (args.geometry != "project") {
        if (auto path = core::parseGeometryPath(args.geometry))
            options.geometry = render::resolveGeometryPath(*path, gl::isSoftwareRenderer());
    }
    options.timeS = static_cast<float>(args.timeS);
    options.lightPerVertex = args.lightPerVertex;
    options.lodBlend = static_cast<float>(args.lodBlend);
    if (args.lightPerPixel)
        options.pixelLitLods = core::LOD_COUNT;
    if (args.snow)
        options.snow.enabled = 1u;
    if (args.snowExposure != "auto")
        options.snowExposurePerVertex = args.snowExposure == "vertex";
    if (args.technique != "project")
        if (auto technique = core::parseGrassTechnique(args.technique))
            options.technique = *technique;
    if (args.animation != "project")
        if (auto animation = core::parseBillboardAnimation(args.animation))
            options.billboards.animation = *animation;
    if (args.lighting != "project")
        options.lighting.model = args.lighting == "grass"     ? core::LightingModel::Grass
                                 : args.lighting == "article" ? core::LightingModel::Article
                                                              : core::LightingModel::Simple;
    if (args.shape != "project") {
        if (auto shape = core::parseBladeShape(args.shape))
            options.shape = *shape;
    }
}

}  // namespace

std::optional<int> parseRenderArgs(const std::vector<std::string>& argv, RenderArgs& args) {
    ArgParser parser(
        "grass render <project-dir|project.json> [--out F.png] [options]\n"
        "       grass render [--mesh] M.gltf|M.glb [--out F.png] [options]",
        "Grows the project's grass and renders it headless (EGL, no display needed) to an image "
        "through OpenImageIO; the format follows the extension (.png, .tif, .jpg, .exr). Prints "
        "where it wrote the image and the frame timings. With --mesh (or a .gltf/.glb given as "
        "the project), grows a default field on any glTF file with a camera framing its bounds.");
    addProjectArgument(parser, &args.project, false);
    parser.text("--mesh", "FILE", "render a default field on this glTF file instead of a project",
                &args.mesh);
    parser.text("--unit", "UNIT",
                "with --mesh: what one unit of the file measures: mm, cm, m, in, ft, or metres per "
                "unit (0.001 = mm)",
                &args.unit);
    parser.text("--up", "AXIS", "with --mesh: the file's up axis, +Y or +Z (turned to +Y)", &args.up);
    describeImageOptions(parser, args);
    describeRunOptions(parser, args);
    // Parsed before the defaults that depend on it are shown, so 0 reads as "the project's".
    if (const auto exitCode = parseArguments(parser, argv, "render"))
        return exitCode;
    args.seedGiven = parser.given("--seed");
    args.lodDistanceGiven = parser.given("--lod-distance");
    // `grass render rock.glb` means --mesh rock.glb, as `grass-editor rock.glb` opens a project
    // around it.
    if (args.mesh.empty() && core::isGltfPath(args.project))
        args.mesh = std::exchange(args.project, {});
    return std::nullopt;
}

Result<render::CullSettings> checkRenderArgs(const RenderArgs& args) {
    if (auto input = checkInput(args); !input)
        return input.error();
    auto cullTests = parseCullList(args.cull);
    if (!cullTests)
        return cullTests;
    if (auto writable = checkOutputsWritable(args); !writable)
        return writable.error();
    return cullTests;
}

FrameSize frameSize(const RenderArgs& args, const core::RenderSettings& settings) {
    return {args.width > 0 ? args.width : settings.width,
            args.height > 0 ? args.height : settings.height,
            args.msaa == "project" ? settings.msaaSamples : std::stoi(args.msaa)};
}

render::OffscreenRequest offscreenRequest(const RenderArgs& args, const core::Project& project,
                                          const render::CullSettings& cullTests) {
    const FrameSize size = frameSize(args, project.render);
    render::OffscreenRequest request;
    request.width = size.width;
    request.height = size.height;
    request.msaaSamples = size.samples;
    request.frames = args.frames;
    request.options = render::renderOptionsFor(project, gl::isSoftwareRenderer());
    applyRenderOverrides(args, request.options);
    // Counters are read once after the last frame: cheap for a one-shot render. The list picks
    // the tests; distances come from the project (thinning only where it has a distance).
    render::CullSettings& culling = request.options.cull;
    culling.frustum = cullTests.frustum;
    culling.orientation = cullTests.orientation;
    culling.occlusion = cullTests.occlusion;
    culling.distance = culling.distance && cullTests.distance;
    culling.collectStats = true;
    if (args.lodDistanceGiven)
        culling.lodDistanceM = static_cast<float>(args.lodDistanceM);
    return request;
}

}  // namespace grass::cli
