#include "export/raw_export.h"

#include <bit>
#include <cstring>

#include "util/atomic_file.h"

namespace grass::core {

namespace {

// The files are little-endian by definition; the blades are copied as the CPU holds them, which
// is what the renderer uploads.
static_assert(std::endian::native == std::endian::little, "raw export assumes little-endian");

template <class T>
void append(std::string& out, const T& value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
T load(const char* bytes) {
    T value;
    std::memcpy(&value, bytes, sizeof value);
    return value;
}

Result<std::string> readRecords(const std::filesystem::path& file, std::size_t stride) {
    auto bytes = readFile(file);
    if (!bytes)
        return bytes.error();
    if (bytes->size() % stride != 0)
        return makeError(file.string(), std::to_string(bytes->size()) +
                                            " bytes is not a whole number of " +
                                            std::to_string(stride) + "-byte records (truncated?)");
    return bytes;
}

nlohmann::json field(const char* name, std::size_t offset, const char* type, const char* units) {
    return {{"name", name}, {"offset", offset}, {"type", type}, {"units", units}};
}

}  // namespace

std::string rawBladeBytes(const std::vector<Blade>& blades) {
    std::string out(blades.size() * RAW_BLADE_STRIDE, '\0');
    if (!blades.empty())
        std::memcpy(out.data(), blades.data(), out.size());
    return out;
}

std::string rawPatchBytes(const std::vector<Patch>& patches) {
    std::string out;
    out.reserve(patches.size() * RAW_PATCH_STRIDE);
    for (const Patch& patch : patches) {
        append(out, patch.firstBlade);
        append(out, patch.bladeCount);
        for (int axis = 0; axis < 3; ++axis)
            append(out, patch.bounds.min[axis]);
        for (int axis = 0; axis < 3; ++axis)
            append(out, patch.bounds.max[axis]);
    }
    return out;
}

std::string rawFloatBytes(const std::vector<float>& values) {
    std::string out(values.size() * sizeof(float), '\0');
    if (!values.empty())
        std::memcpy(out.data(), values.data(), out.size());
    return out;
}

nlohmann::json rawLayoutManifest() {
    return {
        {"byte_order", "little-endian"},
        {"units", "metres"},
        {"axes", "+Y up, right-handed (as glTF)"},
        {"angles", "radians"},
        {"blade_record",
         {{"stride", RAW_BLADE_STRIDE},
          {"fields",
           {field("v0", 0, "float32[3]", "metres, root, world space"),
            field("theta", 12, "float32", "radians, width direction about up"),
            field("v1", 16, "float32[3]", "metres, middle Bezier control point"),
            field("h", 28, "float32", "metres, height"),
            field("v2", 32, "float32[3]", "metres, tip control point"),
            field("w", 44, "float32", "metres, half width (edges at c +- w*t1)"),
            field("up", 48, "float32[3]", "unit surface normal at the root"),
            field("s", 60, "float32", "stiffness")}}}},
        {"patch_record",
         {{"stride", RAW_PATCH_STRIDE},
          {"fields",
           {field("firstBlade", 0, "uint32", "blade index"),
            field("bladeCount", 4, "uint32", "live blades; the patch holds patch_size slots"),
            field("boundsMin", 8, "float32[3]", "metres"),
            field("boundsMax", 20, "float32[3]", "metres")}}}},
        {"shading_record",
         {{"stride", 32},
          {"fields",
           {field("blurredNormal", 0, "float32[3]", "unit, the terrain normal blurred (SPEC 10)"),
            field("ao", 12, "float32", "grass ambient occlusion 0..1 at the root"),
            field("water", 16, "float32", "0..1, the lighting's water term"),
            field("age", 20, "float32", "0..1"),
            field("wilt", 24, "float32", "0..1, colour = mix(healthy, poor, wilt)"),
            field("unused", 28, "float32", "0")}}}},
        {"maps", "float32 width x height, row-major, row 0 = top of the image = v 0, values 0..1"},
    };
}

Result<std::vector<Blade>> readRawBlades(const std::filesystem::path& file) {
    auto bytes = readRecords(file, RAW_BLADE_STRIDE);
    if (!bytes)
        return bytes.error();
    std::vector<Blade> blades(bytes->size() / RAW_BLADE_STRIDE);
    if (!blades.empty())
        std::memcpy(blades.data(), bytes->data(), bytes->size());
    return blades;
}

Result<std::vector<Patch>> readRawPatches(const std::filesystem::path& file) {
    auto bytes = readRecords(file, RAW_PATCH_STRIDE);
    if (!bytes)
        return bytes.error();
    std::vector<Patch> patches(bytes->size() / RAW_PATCH_STRIDE);
    for (std::size_t i = 0; i < patches.size(); ++i) {
        const char* record = bytes->data() + i * RAW_PATCH_STRIDE;
        patches[i].firstBlade = load<std::uint32_t>(record);
        patches[i].bladeCount = load<std::uint32_t>(record + 4);
        for (int axis = 0; axis < 3; ++axis) {
            patches[i].bounds.min[axis] = load<float>(record + 8 + 4 * axis);
            patches[i].bounds.max[axis] = load<float>(record + 20 + 4 * axis);
        }
    }
    return patches;
}

}  // namespace grass::core
