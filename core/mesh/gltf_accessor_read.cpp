#include "mesh/gltf_accessor_read.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

namespace grass::core::gltf {
namespace {

// An accessor without a bufferView is all zeros; its count is not bounded by any data, so a
// corrupt count must not turn into a multi-gigabyte allocation.
constexpr std::uint64_t MAX_VIEWLESS_COUNT = 1u << 26;

const char* semanticName(Semantic semantic) {
    switch (semantic) {
        case Semantic::Position:
            return "POSITION";
        case Semantic::Normal:
            return "NORMAL";
        case Semantic::TexCoord:
            return "TEXCOORD_0";
        case Semantic::Indices:
            return "indices";
        case Semantic::Translation:
            return "TRANSLATION";
        case Semantic::Rotation:
            return "ROTATION";
        case Semantic::Scale:
            return "SCALE";
        case Semantic::Color:
            return "COLOR_0";
        case Semantic::Joints:
            return "JOINTS";
        case Semantic::Weights:
            return "WEIGHTS";
        case Semantic::InverseBindMatrices:
            return "inverseBindMatrices";
    }
    return "?";
}

int semanticComponents(Semantic semantic) {
    switch (semantic) {
        case Semantic::Position:
        case Semantic::Normal:
        case Semantic::Translation:
        case Semantic::Scale:
        case Semantic::Color:  // or 4 (readAccessor)
            return 3;
        case Semantic::TexCoord:
            return 2;
        case Semantic::Rotation:
        case Semantic::Joints:
        case Semantic::Weights:
            return 4;
        case Semantic::Indices:
            return 1;
        case Semantic::InverseBindMatrices:
            return 16;
    }
    return 0;
}

// glTF 2.0 §3.7.2.1 (core), KHR_mesh_quantization's integer POSITION, NORMAL, TEXCOORD_0, and
// EXT_mesh_gpu_instancing's TRANSLATION, ROTATION, SCALE; COLOR_0 (and the per-instance _COLOR_0
// of the same convention); JOINTS_n, WEIGHTS_n and inverseBindMatrices (§3.7.3). Morph target
// deltas are read as POSITION and NORMAL.
bool acceptsComponent(Semantic semantic, int componentType) {
    const bool isFloat = componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool isSigned = componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                          componentType == TINYGLTF_COMPONENT_TYPE_SHORT;
    const bool isUnsigned = componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                            componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    switch (semantic) {
        case Semantic::Position:
        case Semantic::TexCoord:
            return isFloat || isSigned || isUnsigned;
        case Semantic::Normal:
        case Semantic::Rotation:
            return isFloat || isSigned;
        case Semantic::Translation:
        case Semantic::Scale:
            return isFloat;
        case Semantic::Indices:
            return isUnsigned || componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        case Semantic::Color:
        case Semantic::Weights:
            return isFloat || isUnsigned;
        case Semantic::Joints:
            return isUnsigned;
        case Semantic::InverseBindMatrices:
            return isFloat;
    }
    return false;
}

const char* expectedTypes(Semantic semantic) {
    switch (semantic) {
        case Semantic::Position:
            return "VEC3 of FLOAT, or of BYTE/UNSIGNED_BYTE/SHORT/UNSIGNED_SHORT "
                   "(KHR_mesh_quantization)";
        case Semantic::Normal:
            return "VEC3 of FLOAT, or of BYTE/SHORT (KHR_mesh_quantization)";
        case Semantic::TexCoord:
            return "VEC2 of FLOAT, UNSIGNED_BYTE or UNSIGNED_SHORT, or of BYTE/SHORT "
                   "(KHR_mesh_quantization)";
        case Semantic::Indices:
            return "SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT";
        case Semantic::Translation:
        case Semantic::Scale:
            return "VEC3 of FLOAT";
        case Semantic::Rotation:
            return "VEC4 of FLOAT, or of normalized BYTE/SHORT";
        case Semantic::Color:
            return "VEC3 or VEC4 of FLOAT, or of normalized UNSIGNED_BYTE/UNSIGNED_SHORT";
        case Semantic::Joints:
            return "VEC4 of UNSIGNED_BYTE or UNSIGNED_SHORT";
        case Semantic::Weights:
            return "VEC4 of FLOAT, or of normalized UNSIGNED_BYTE/UNSIGNED_SHORT";
        case Semantic::InverseBindMatrices:
            return "MAT4 of FLOAT";
    }
    return "?";
}

std::size_t componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

std::string componentName(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return "FLOAT";
        default:
            return "component type " + std::to_string(componentType);
    }
}

}  // namespace

int typeComponents(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        // Only a skin's inverse bind matrices; MAT4 of FLOAT has no column padding (§3.6.2.4).
        case TINYGLTF_TYPE_MAT4:
            return 16;
        default:
            return 0;  // MAT2, MAT3: never read
    }
}
namespace {

std::string typeName(int type) {
    if (type == TINYGLTF_TYPE_MAT4)
        return "MAT4";
    const int n = typeComponents(type);
    if (n == 1)
        return "SCALAR";
    if (n > 1)
        return "VEC" + std::to_string(n);
    return "a matrix";
}

// Byte arithmetic on sizes read from the file saturates instead of wrapping.
std::uint64_t addSat(std::uint64_t a, std::uint64_t b) {
    return a > std::numeric_limits<std::uint64_t>::max() - b
               ? std::numeric_limits<std::uint64_t>::max()
               : a + b;
}
std::uint64_t mulSat(std::uint64_t a, std::uint64_t b) {
    return a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a
               ? std::numeric_limits<std::uint64_t>::max()
               : a * b;
}

// Where `count` elements of `elementSize` bytes, `stride` apart, start `offset` bytes into
// bufferView `viewIndex`. Checks the elements lie inside the view and the view inside its
// buffer, so the caller may read them. `label` names the reader in messages.
Result<const unsigned char*> locate(const tinygltf::Model& model, int viewIndex,
                                    std::uint64_t offset, std::uint64_t stride, std::uint64_t count,
                                    std::uint64_t elementSize, const std::string& label) {
    if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= model.bufferViews.size())
        return makeError("", label + " refers to bufferView " + std::to_string(viewIndex) +
                                 ", but the file has " + std::to_string(model.bufferViews.size()) +
                                 " bufferViews");
    const auto& view = model.bufferViews[static_cast<std::size_t>(viewIndex)];
    const std::string viewName = "bufferView " + std::to_string(viewIndex);
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
        return makeError("", viewName + " (read by " + label + ") refers to buffer " +
                                 std::to_string(view.buffer) + ", but the file has " +
                                 std::to_string(model.buffers.size()) + " buffers");
    const auto& data = model.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::string bufferName =
        "buffer " + std::to_string(view.buffer) + " (" + std::to_string(data.size()) + " bytes)";
    const std::uint64_t bufferSize = data.size();
    const std::uint64_t viewEnd = addSat(view.byteOffset, view.byteLength);
    const std::uint64_t readEnd =
        addSat(addSat(view.byteOffset, offset), addSat(mulSat(stride, count - 1), elementSize));
    const auto past = [](std::uint64_t end, std::uint64_t size) {
        return end == std::numeric_limits<std::uint64_t>::max() ? std::string("far")
                                                                : std::to_string(end - size);
    };
    if (readEnd > bufferSize)
        return makeError("", label + " reads " + past(readEnd, bufferSize) +
                                 " bytes past the end of " + bufferName +
                                 ": the file is truncated or corrupt");
    if (viewEnd > bufferSize)
        return makeError("", viewName + " (read by " + label + ") ends " +
                                 past(viewEnd, bufferSize) + " bytes past the end of " +
                                 bufferName + ": the file is truncated or corrupt");
    if (readEnd > viewEnd)
        return makeError("", label + " reads " + past(readEnd, viewEnd) +
                                 " bytes past the end of " + viewName + " (" +
                                 std::to_string(view.byteLength) + " bytes): the file is corrupt");
    return data.data() + view.byteOffset + offset;
}

// Converts one component to T: float outputs apply the spec's normalization (§3.11,
// max(c / MAX, -1) for signed types), integer outputs take the value as is.
template <class C, class T>
void decodeComponents(const unsigned char* src, std::uint64_t stride, std::uint64_t count,
                      int components, bool normalized, T* dst) {
    for (std::uint64_t i = 0; i < count; ++i) {
        const unsigned char* element = src + i * stride;
        for (int c = 0; c < components; ++c) {
            C value;
            std::memcpy(&value, element + static_cast<std::size_t>(c) * sizeof(C), sizeof(C));
            if constexpr (std::is_floating_point_v<T> && std::is_integral_v<C>) {
                constexpr float MAX = static_cast<float>(std::numeric_limits<C>::max());
                const float f = static_cast<float>(value);
                *dst++ = normalized ? std::max(f / MAX, -1.0f) : f;
            } else {
                *dst++ = static_cast<T>(value);
            }
        }
    }
}

template <class T>
void decode(int componentType, const unsigned char* src, std::uint64_t stride, std::uint64_t count,
            int components, bool normalized, T* dst) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return decodeComponents<std::int8_t>(src, stride, count, components, normalized, dst);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return decodeComponents<std::uint8_t>(src, stride, count, components, normalized, dst);
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return decodeComponents<std::int16_t>(src, stride, count, components, normalized, dst);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return decodeComponents<std::uint16_t>(src, stride, count, components, normalized, dst);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return decodeComponents<std::uint32_t>(src, stride, count, components, normalized, dst);
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return decodeComponents<float>(src, stride, count, components, normalized, dst);
        default:
            return;  // refused by acceptsComponent before any read
    }
}

}  // namespace

std::string accessorLabel(int index, Semantic semantic, const std::string& where) {
    return "accessor " + std::to_string(index) + " (" + semanticName(semantic) + " of " + where +
           ")";
}
namespace {

// Overwrites the elements a sparse accessor names (spec §3.6.2.3).
template <class T>
Result<void> applySparse(const tinygltf::Model& model, const tinygltf::Accessor& accessor,
                         const std::string& label, int components, bool normalized,
                         std::vector<T>& out) {
    const auto& sparse = accessor.sparse;
    if (sparse.count < 1 || static_cast<std::uint64_t>(sparse.count) > accessor.count)
        return makeError("", label + " has a sparse count of " + std::to_string(sparse.count) +
                                 ", outside 1.." + std::to_string(accessor.count));
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
        return makeError("", label + " has a negative sparse byteOffset");
    const int indexType = sparse.indices.componentType;
    if (!acceptsComponent(Semantic::Indices, indexType))
        return makeError("", label + " has sparse indices of " + componentName(indexType) +
                                 "; they must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    const auto count = static_cast<std::uint64_t>(sparse.count);
    const std::uint64_t indexSize = componentSize(indexType);
    const auto indexData = locate(model, sparse.indices.bufferView,
                                  static_cast<std::uint64_t>(sparse.indices.byteOffset), indexSize,
                                  count, indexSize, "the sparse indices of " + label);
    if (!indexData)
        return indexData.error();
    const std::uint64_t elementSize =
        componentSize(accessor.componentType) * static_cast<std::uint64_t>(components);
    const auto valueData = locate(model, sparse.values.bufferView,
                                  static_cast<std::uint64_t>(sparse.values.byteOffset), elementSize,
                                  count, elementSize, "the sparse values of " + label);
    if (!valueData)
        return valueData.error();

    std::vector<std::uint32_t> indices(count);
    decode(indexType, *indexData, indexSize, count, 1, false, indices.data());
    std::vector<T> values(count * static_cast<std::uint64_t>(components));
    decode(accessor.componentType, *valueData, elementSize, count, components, normalized,
           values.data());
    const auto n = static_cast<std::size_t>(components);
    for (std::size_t k = 0; k < indices.size(); ++k) {
        if (indices[k] >= accessor.count)
            return makeError("", label + " has sparse index " + std::to_string(indices[k]) +
                                     " at position " + std::to_string(k) +
                                     ", out of range for its " + std::to_string(accessor.count) +
                                     " elements");
        std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(k * n), n,
                    out.begin() + static_cast<std::ptrdiff_t>(indices[k] * n));
    }
    return {};
}

}  // namespace

// Reads accessor `index` as flat components of T, for the given attribute.
template <class T>
Result<std::vector<T>> readAccessor(const tinygltf::Model& model, int index, Semantic semantic,
                                    const std::string& where) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        return makeError("", where + ": " + semanticName(semantic) + " refers to accessor " +
                                 std::to_string(index) + ", but the file has " +
                                 std::to_string(model.accessors.size()) + " accessors");
    const auto& accessor = model.accessors[static_cast<std::size_t>(index)];
    const std::string label = accessorLabel(index, semantic, where);
    // Colours come as RGB or RGBA (spec §3.7.2.1).
    const int components = semantic == Semantic::Color && typeComponents(accessor.type) == 4
                               ? 4
                               : semanticComponents(semantic);
    if (typeComponents(accessor.type) != components ||
        !acceptsComponent(semantic, accessor.componentType))
        return makeError("", label + " is " + typeName(accessor.type) + " of " +
                                 componentName(accessor.componentType) + "; " +
                                 semanticName(semantic) + " must be " + expectedTypes(semantic));
    const std::uint64_t count = accessor.count;
    const std::uint64_t elementSize =
        componentSize(accessor.componentType) * static_cast<std::uint64_t>(components);
    if (count == 0)
        return std::vector<T>{};
    if (accessor.bufferView < 0 && count > MAX_VIEWLESS_COUNT)
        return makeError("", label + " has no bufferView and a count of " + std::to_string(count) +
                                 ", more than grass reads (" + std::to_string(MAX_VIEWLESS_COUNT) +
                                 ")");

    const tinygltf::BufferView* view = nullptr;
    if (accessor.bufferView >= 0 &&
        static_cast<std::size_t>(accessor.bufferView) < model.bufferViews.size())
        view = &model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    const std::uint64_t stride = view && view->byteStride != 0 ? view->byteStride : elementSize;
    if (stride < elementSize)
        return makeError("", "bufferView " + std::to_string(accessor.bufferView) +
                                 " has byteStride " + std::to_string(stride) +
                                 ", smaller than the " + std::to_string(elementSize) +
                                 "-byte elements of " + label);
    // Resolve the range first: the allocation below is then bounded by the file's size.
    const unsigned char* base = nullptr;
    if (accessor.bufferView >= 0) {
        const auto located = locate(model, accessor.bufferView, accessor.byteOffset, stride, count,
                                    elementSize, label);
        if (!located)
            return located.error();
        base = *located;
    }
    std::vector<T> out(count * static_cast<std::uint64_t>(components), T{});
    // Without a bufferView the accessor starts as zeros (spec §3.6.2.3).
    // Integer colours and joint weights are normalized by the spec; a file that forgot the flag
    // still means it.
    const bool normalized =
        accessor.normalized || semantic == Semantic::Color || semantic == Semantic::Weights;
    if (base)
        decode(accessor.componentType, base, stride, count, components, normalized, out.data());
    if (accessor.sparse.isSparse) {
        const auto sparse = applySparse(model, accessor, label, components, normalized, out);
        if (!sparse)
            return sparse.error();
    }
    return out;
}

int attributeAccessor(const tinygltf::Primitive& primitive, const std::string& name) {
    const auto it = primitive.attributes.find(name);
    return it == primitive.attributes.end() ? -1 : it->second;
}

template Result<std::vector<float>> readAccessor<float>(const tinygltf::Model&, int, Semantic,
                                                        const std::string&);
template Result<std::vector<std::uint32_t>> readAccessor<std::uint32_t>(const tinygltf::Model&, int,
                                                                        Semantic,
                                                                        const std::string&);

}  // namespace grass::core::gltf
