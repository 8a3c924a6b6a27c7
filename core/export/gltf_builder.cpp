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

void appendU32(std::string& out, std::uint32_t value) {
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<char>((value >> (8 * i)) & 0xffu));
}

// Empty top-level arrays are forbidden (spec): a field with nothing in some of them.
void eraseEmptyArrays(nlohmann::json& document) {
    for (auto it = document.begin(); it != document.end();)
        it = it->is_array() && it->empty() ? document.erase(it) : std::next(it);
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

int GltfBuilder::addBytes(std::string_view bytes) {
    GRASS_ASSERT(!bytes.empty());
    return addView(bytes.data(), bytes.size(), GltfTarget::None);
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
    eraseEmptyArrays(mDocument);
    return mDocument.dump(1) + "\n";
}

std::string GltfBuilder::finishGlb() {
    finishBinary();
    if (!mBinary.empty())
        mDocument["buffers"] = {{{"byteLength", mBinary.size()}}};
    eraseEmptyArrays(mDocument);
    std::string json = mDocument.dump();
    json.resize((json.size() + 3) / 4 * 4, ' ');
    const std::size_t total =
        12 + 8 + json.size() + (mBinary.empty() ? 0 : 8 + mBinary.size());
    GRASS_ASSERT(total <= std::numeric_limits<std::uint32_t>::max());
    std::string glb;
    glb.reserve(total);
    appendU32(glb, 0x46546C67u);  // "glTF"
    appendU32(glb, 2u);
    appendU32(glb, static_cast<std::uint32_t>(total));
    appendU32(glb, static_cast<std::uint32_t>(json.size()));
    appendU32(glb, 0x4E4F534Au);  // "JSON"
    glb += json;
    if (!mBinary.empty()) {
        appendU32(glb, static_cast<std::uint32_t>(mBinary.size()));
        appendU32(glb, 0x004E4942u);  // "BIN\0"
        glb += mBinary;
    }
    return glb;
}

}  // namespace grass::core
