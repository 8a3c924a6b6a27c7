#include "mesh/gltf_meshopt.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <string>
#include <vector>

namespace grass::core::gltf {

namespace {

const char* const EXTENSION_NAMES[] = {"EXT_meshopt_compression", "KHR_meshopt_compression"};

const tinygltf::Value* meshoptExtension(const tinygltf::ExtensionMap& extensions) {
    for (const char* name : EXTENSION_NAMES)
        if (const auto it = extensions.find(name); it != extensions.end() && it->second.IsObject())
            return &it->second;
    return nullptr;
}

// A non-negative integer member, or `absent` when missing; -1 when present but not one.
std::int64_t integer(const tinygltf::Value& object, const char* key, std::int64_t absent) {
    if (!object.Has(key))
        return absent;
    const tinygltf::Value& value = object.Get(key);
    if (!value.IsNumber())
        return -1;
    const double number = value.GetNumberAsDouble();
    return number >= 0.0 && number <= 9.0e15 && number == double(std::int64_t(number))
               ? std::int64_t(number)
               : -1;
}

std::string text(const tinygltf::Value& object, const char* key, const char* absent) {
    return object.Has(key) && object.Get(key).IsString() ? object.Get(key).Get<std::string>()
                                                         : std::string(absent);
}

Result<void> decodeView(tinygltf::Model& model, std::size_t index, const tinygltf::Value& ext) {
    const std::string what = "bufferView " + std::to_string(index) + " (EXT_meshopt_compression)";
    tinygltf::BufferView& view = model.bufferViews[index];
    const std::int64_t sourceBuffer = integer(ext, "buffer", -1);
    const std::int64_t offset = integer(ext, "byteOffset", 0);
    const std::int64_t length = integer(ext, "byteLength", -1);
    const std::int64_t stride = integer(ext, "byteStride", -1);
    const std::int64_t count = integer(ext, "count", -1);
    const std::string mode = text(ext, "mode", "");
    const std::string filter = text(ext, "filter", "NONE");
    if (sourceBuffer < 0 || offset < 0 || length < 0 || stride < 0 || count < 0)
        return makeError("", what + " lacks buffer, byteLength, byteStride or count, or one is "
                                    "not a non-negative integer");
    if (std::size_t(sourceBuffer) >= model.buffers.size())
        return makeError("", what + " reads buffer " + std::to_string(sourceBuffer) +
                                 ", but the file has " + std::to_string(model.buffers.size()));
    const std::vector<unsigned char>& source = model.buffers[std::size_t(sourceBuffer)].data;
    if (std::uint64_t(offset) > source.size() || std::uint64_t(length) > source.size() - std::uint64_t(offset))
        return makeError("", what + " reads past the end of buffer " + std::to_string(sourceBuffer) +
                                 ": the file is truncated or corrupt");
    const bool attributes = mode == "ATTRIBUTES";
    const bool triangles = mode == "TRIANGLES", indices = mode == "INDICES";
    if (!attributes && !triangles && !indices)
        return makeError("", what + " has mode \"" + mode + "\"; it must be ATTRIBUTES, TRIANGLES or INDICES");
    if (attributes ? (stride == 0 || stride % 4 != 0 || stride > 256) : (stride != 2 && stride != 4))
        return makeError("", what + " has byteStride " + std::to_string(stride) +
                                 (attributes ? "; ATTRIBUTES needs a multiple of 4 up to 256"
                                             : "; indices are 2 or 4 bytes"));
    if (triangles && count % 3 != 0)
        return makeError("", what + " holds " + std::to_string(count) + " triangle indices, not a multiple of 3");
    const std::uint64_t decodedSize = std::uint64_t(count) * std::uint64_t(stride);
    if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size())
        return makeError("", what + " refers to a buffer that does not exist");
    std::vector<unsigned char>& target = model.buffers[std::size_t(view.buffer)].data;
    if (decodedSize > view.byteLength || view.byteOffset > target.size() ||
        view.byteLength > target.size() - view.byteOffset)
        return makeError("", what + " decodes to " + std::to_string(decodedSize) +
                                 " bytes, more than the bufferView's place in its buffer");
    // Decoded apart from the buffer: the source and the target may be the same buffer.
    std::vector<unsigned char> decoded(decodedSize);
    const unsigned char* data = source.data() + offset;
    const auto n = std::size_t(count), size = std::size_t(stride), bytes = std::size_t(length);
    const int status = attributes ? meshopt_decodeVertexBuffer(decoded.data(), n, size, data, bytes)
                       : triangles ? meshopt_decodeIndexBuffer(decoded.data(), n, size, data, bytes)
                                   : meshopt_decodeIndexSequence(decoded.data(), n, size, data, bytes);
    if (status != 0)
        return makeError("", what + " holds data meshoptimizer cannot decode (error " +
                                 std::to_string(status) + "): the file is corrupt");
    if (filter != "NONE") {
        if (!attributes)
            return makeError("", what + " has filter " + filter + " on indices");
        if (filter == "OCTAHEDRAL" && (size == 4 || size == 8))
            meshopt_decodeFilterOct(decoded.data(), n, size);
        else if (filter == "QUATERNION" && size == 8)
            meshopt_decodeFilterQuat(decoded.data(), n, size);
        else if (filter == "EXPONENTIAL")
            meshopt_decodeFilterExp(decoded.data(), n, size);
        else
            return makeError("", what + " has filter \"" + filter + "\" with byteStride " +
                                     std::to_string(stride) + ", which the extension does not define");
    }
    std::copy(decoded.begin(), decoded.end(), target.begin() + std::ptrdiff_t(view.byteOffset));
    // The decoded elements are tightly packed at the extension's stride.
    view.byteStride = attributes ? size : 0;
    return {};
}

}  // namespace

Result<void> decodeMeshoptBufferViews(tinygltf::Model& model) {
    for (std::size_t i = 0; i < model.bufferViews.size(); ++i)
        if (const tinygltf::Value* ext = meshoptExtension(model.bufferViews[i].extensions))
            if (auto decoded = decodeView(model, i, *ext); !decoded)
                return decoded.error();
    return {};
}

}  // namespace grass::core::gltf
