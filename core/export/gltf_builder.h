// GltfBuilder: the buffer, bufferViews and accessors of a glTF 2.0 document with one binary
// buffer, laid out the way the spec asks (§3.6): every bufferView starts at a multiple of 4
// (all our components are 4-byte floats or uint32), tightly packed so no byteStride is needed,
// and the buffer's byteLength is exactly the bytes written. Accessors get min/max (required for
// POSITION, useful everywhere), computed from the float32 values as stored so they match the
// data bit for bit.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace grass::core {

// bufferView.target values (spec §5.11.4); None leaves it out (instance attributes).
enum class GltfTarget { None = 0, ArrayBuffer = 34962, ElementArrayBuffer = 34963 };

class GltfBuilder {
public:
    GltfBuilder();

    // `values` holds count × components floats; `type` is "SCALAR", "VEC2", "VEC3" or "VEC4".
    // Returns the accessor index.
    int addFloats(std::span<const float> values, int components, GltfTarget target);
    int addIndices(std::span<const std::uint32_t> indices);
    // Raw bytes in a view of their own (an embedded image); returns the bufferView index.
    int addBytes(std::string_view bytes);

    nlohmann::json& document() { return mDocument; }
    // Pads the buffer to its final length (a multiple of 4) and returns it: what the .bin holds.
    const std::string& finishBinary();
    // Adds the buffer (uri = the .bin file next to the .gltf) and returns the finished JSON.
    std::string finishJson(const std::string& binUri);
    // The document and its buffer as one binary glTF (.glb, spec §4.4): a 12-byte header, the
    // JSON chunk padded with spaces and the BIN chunk padded with zeros to 4 bytes.
    std::string finishGlb();
    const std::string& binary() const { return mBinary; }

private:
    int addView(const void* data, std::size_t bytes, GltfTarget target);

    nlohmann::json mDocument;
    std::string mBinary;
};

}  // namespace grass::core
