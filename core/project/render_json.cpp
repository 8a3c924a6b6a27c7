// The "render" section of project.json: image size, blade geometry, LOD and the technique.
#include <array>
#include <bit>

#include "project/project_json_parts.h"
#include "util/byte_size.h"

namespace grass::core {

namespace {

using json::Json;
using settings::field;
using settings::Kind;

// project.h says why camera distances are bounded.
constexpr json::NumberRule DISTANCE_OR_OFF{0.0, MAX_CAMERA_DISTANCE_M};
constexpr int MAX_IMAGE_SIDE = 16384;
// The cull shader's work-group is 32 blades; a patch is whole groups.
constexpr std::uint32_t PATCH_GRANULE = 32;
constexpr std::uint32_t MAX_PATCH_SIZE = 65536;
constexpr std::array<std::string_view, 3> GEOMETRY_NAMES{"auto", "tess", "strips"};

void readMsaa(json::Reader& reader, json::Object& object, std::string_view key, RenderSettings& render) {
    const Json* msaa = object.find(key);
    if (!msaa)
        return;
    const std::uint64_t samples = msaa->is_number_unsigned() ? msaa->get<std::uint64_t>() : 3;
    if (samples <= 8 && (samples == 0 || std::has_single_bit(samples)))
        render.msaaSamples = msaa->get<int>();
    else
        reader.fail(object.pointerTo(key),
                    "must be 0, 1, 2, 4 or 8 samples (got " + json::describeValue(*msaa) + ")");
}

Json msaaJson(const RenderSettings& render) { return render.msaaSamples; }

void readPatchSize(json::Reader& reader, json::Object& object, std::string_view key, RenderSettings& render) {
    const Json* patch = object.find(key);
    if (!patch)
        return;
    const bool valid = patch->is_number_unsigned() && patch->get<std::uint64_t>() > 0 &&
                       patch->get<std::uint64_t>() <= MAX_PATCH_SIZE &&
                       patch->get<std::uint64_t>() % PATCH_GRANULE == 0;
    if (valid)
        render.patchSize = patch->get<std::uint32_t>();
    else
        reader.fail(object.pointerTo(key), "must be a positive multiple of 32 up to 65536 (got " +
                                              json::describeValue(*patch) + ")");
}

Json patchSizeJson(const RenderSettings& render) { return render.patchSize; }

constexpr std::array RENDER{
    field<&RenderSettings::width>(
        {.key = "width", .intMin = 1, .intMax = MAX_IMAGE_SIDE, .unit = "pixels"}),
    field<&RenderSettings::height>(
        {.key = "height", .intMin = 1, .intMax = MAX_IMAGE_SIDE, .unit = "pixels"}),
    field<&RenderSettings::geometry>(
        {.key = "geometry",
         .names = GEOMETRY_NAMES,
         .allowedText = "`\"auto\"` (strips on software GL, tessellation on GPUs), `\"tess\"`, "
                        "`\"strips\"`"}),
    field<&RenderSettings::tessLevel>({.key = "tess_level",
                                       .intMin = 1,
                                       .intMax = 64,
                                       .help = "tessellation level along a blade"}),
    field<&RenderSettings::stripSegments>({.key = "strip_segments",
                                           .intMin = 1,
                                           .intMax = 32,
                                           .help = "segments of an instanced strip"}),
    settings::custom<RenderSettings>(
        {.key = "msaa", .typeText = "integer", .allowedText = "0, 1, 2, 4 or 8 samples"}, readMsaa,
        msaaJson),
    settings::custom<RenderSettings>(
        {.key = "patch_size",
         .typeText = "integer",
         .allowedText = "blades per patch: a positive multiple of 32 (the cull work-group) up to "
                        "65536"},
        readPatchSize, patchSizeJson),
    field<&RenderSettings::skyColor>({.key = "sky_color",
                                      .kind = Kind::Colour,
                                      .rule = json::UNIT_INTERVAL,
                                      .label = "sky colour"}),
    field<&RenderSettings::groundColor>({.key = "ground_color",
                                         .kind = Kind::Colour,
                                         .rule = json::UNIT_INTERVAL,
                                         .label = "ground colour"}),
    field<&RenderSettings::technique>(
        {.key = "technique",
         .names = json::TECHNIQUE_NAMES,
         .allowedText = "`\"blades\"` (geometric blades), `\"billboards\"` (star billboards alone, "
                        "SPEC §8), `\"hybrid\"` (blades near the camera cross-faded into "
                        "billboards, see [billboards](#billboards)) or `\"growth\"` (Kim & Cho's "
                        "instanced stem sets, SPEC §9, see [growth](#growth))"}),
    field<&RenderSettings::lodDistanceM>(
        {.key = "lod_distance",
         .rule = DISTANCE_OR_OFF,
         .unit = "m",
         .help = "full blade segments up to this camera distance, half to 3×, a quarter beyond; 0 "
                 "keeps full detail everywhere (SPEC §7)"}),
    field<&RenderSettings::thinningDistanceM>(
        {.key = "thinning_distance",
         .rule = DISTANCE_OR_OFF,
         .unit = "m",
         .help = "the field thins in eighths out to this camera distance; 0 turns thinning off "
                 "(SPEC §6)"}),
};

}  // namespace

std::span<const settings::Setting<RenderSettings>> settings::render() { return RENDER; }

std::string_view geometryPathName(GeometryPath path) {
    const auto index = static_cast<std::size_t>(path);
    return index < GEOMETRY_NAMES.size() ? GEOMETRY_NAMES[index] : "auto";
}

Result<GeometryPath> parseGeometryPath(std::string_view name) {
    for (std::size_t i = 0; i < GEOMETRY_NAMES.size(); ++i)
        if (GEOMETRY_NAMES[i] == name)
            return static_cast<GeometryPath>(i);
    return makeError("", "unknown geometry path " + json::quote(name) +
                             " (valid: " + json::quotedList(GEOMETRY_NAMES) + ")");
}

void json::checkRender(Reader& reader, const Object& object, const RenderSettings& render) {
    const double bytes = framebufferBytes(render.width, render.height, render.msaaSamples);
    if (bytes > MAX_FRAMEBUFFER_BYTES)
        reader.fail(object.pointer(),
                    "width × height at msaa must fit the frame buffer limit, " +
                        byteSizeText(MAX_FRAMEBUFFER_BYTES) + " (got " +
                        std::to_string(render.width) + "×" + std::to_string(render.height) +
                        " at " + std::to_string(render.msaaSamples) +
                        " samples: " + byteSizeText(bytes) + "): lower width, height or msaa");
}

}  // namespace grass::core
