#include "export/gltf_builder.h"

#include <algorithm>
#include <bit>
#include <limits>

#include "util/assert.h"

namespace grass::core {

namespace {

// glTF buffers are little-endian (spec §3.6.1); the floats are copied as the CPU holds them.
static_assert(std::endian::native == std::endian::little,
              "glTF export assumes a little-endian CPU");

constexpr int COMPONENT_FLOAT = 5126;
constexpr int COMPONENT_UNSIGNED_INT = 5125;

const char* accessorType(int components) {
    switch (components) {
        case 1:
            return "SCALAR";
        case 2:
            return "VEC2";
        case 3:
            return "VEC3";
        default:
            return "VEC4";
    }
}

}  // namespace

GltfBuilder::GltfBuilder() {
    mDocument = nlohmann::json::object();
    mDocument["accessors"] = nlohmann::json::array();
    mDocument["bufferViews"] = nlohmann::json::array();
}

int GltfBuilder::addView(const void* data, std::size_t bytes, GltfTarget target) {
    // Every view starts 4-byte aligned: accessors must be aligned to their component size.
    mBinary.resize((mBinary.size() + 3) / 4 * 4, '\0');
    nlohmann::json view = {{"buffer", 0}, {"byteOffset", mBinary.size()}, {"byteLength", bytes}};
    if (target != GltfTarget::None)
        view["target"] = static_cast<int>(target);
    mBinary.append(static_cast<const char*>(data), bytes);
    mDocument["bufferViews"].push_back(view);
    return static_cast<int>(mDocument["bufferViews"].size()) - 1;
}

int GltfBuilder::addFloats(std::span<const float> values, int components, GltfTarget target) {
    GRASS_ASSERT(components >= 1 && components <= 4);
    GRASS_ASSERT(!values.empty() && values.size() % static_cast<std::size_t>(components) == 0);
    const auto width = static_cast<std::size_t>(components);
    std::vector<float> lo(width, std::numeric_limits<float>::max());
    std::vector<float> hi(width, std::numeric_limits<float>::lowest());
    for (std::size_t i = 0; i < values.size(); ++i) {
        lo[i % width] = std::min(lo[i % width], values[i]);
        hi[i % width] = std::max(hi[i % width], values[i]);
    }
    const int view = addView(values.data(), values.size_bytes(), target);
    nlohmann::json accessor = {{"bufferView", view},
                               {"componentType", COMPONENT_FLOAT},
                               {"count", values.size() / width},
                               {"type", accessorType(components)}};
    // float → double is exact, so the JSON numbers read back as the very float32 values.
    accessor["min"] = nlohmann::json::array();
    accessor["max"] = nlohmann::json::array();
    for (std::size_t c = 0; c < width; ++c) {
        accessor["min"].push_back(static_cast<double>(lo[c]));
        accessor["max"].push_back(static_cast<double>(hi[c]));
    }
    mDocument["accessors"].push_back(accessor);
    return static_cast<int>(mDocument["accessors"].size()) - 1;
}

int GltfBuilder::addIndices(std::span<const std::uint32_t> indices) {
    GRASS_ASSERT(!indices.empty());
    const int view = addView(indices.data(), indices.size_bytes(), GltfTarget::ElementArrayBuffer);
    const auto [lo, hi] = std::minmax_element(indices.begin(), indices.end());
    mDocument["accessors"].push_back({{"bufferView", view},
                                      {"componentType", COMPONENT_UNSIGNED_INT},
                                      {"count", indices.size()},
                                      {"type", "SCALAR"},
                                      {"min", {*lo}},
                                      {"max", {*hi}}});
    return static_cast<int>(mDocument["accessors"].size()) - 1;
}

const std::string& GltfBuilder::finishBinary() {
    mBinary.resize((mBinary.size() + 3) / 4 * 4, '\0');
    return mBinary;
}

std::string GltfBuilder::finishJson(const std::string& binUri) {
    finishBinary();
    if (!mBinary.empty())
        mDocument["buffers"] = {{{"uri", binUri}, {"byteLength", mBinary.size()}}};
    // The spec forbids empty top-level arrays (a layer with no blades on an empty mesh).
    for (auto it = mDocument.begin(); it != mDocument.end();)
        it = it->is_array() && it->empty() ? mDocument.erase(it) : std::next(it);
    return mDocument.dump(1) + "\n";
}

}  // namespace grass::core
