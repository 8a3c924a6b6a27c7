#include "mesh/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <limits>
#include <type_traits>

namespace grass::core::gltf {
namespace {

// What a primitive reads, and so which accessor types it accepts.
enum class Semantic {
    Position,
    Normal,
    TexCoord,
    Indices,
    Translation,
    Rotation,
    Scale,
    Color,
    Joints,
    Weights,
    InverseBindMatrices
};

// An accessor without a bufferView is all zeros; its count is not bounded by any data, so a
// corrupt count must not turn into a multi-gigabyte allocation.
constexpr std::uint64_t MAX_VIEWLESS_COUNT = 1u << 26;
// OpenMesh indexes vertices with int.
constexpr std::uint64_t MAX_VERTICES = static_cast<std::uint64_t>(std::numeric_limits<int>::max());

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

std::string accessorLabel(int index, Semantic semantic, const std::string& where) {
    return "accessor " + std::to_string(index) + " (" + semanticName(semantic) + " of " + where +
           ")";
}

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

// An RGB or RGBA colour accessor as RGBA (alpha 1 for RGB).
Result<std::vector<glm::vec4>> readColors(const tinygltf::Model& model, int index,
                                          const std::string& where) {
    auto values = readAccessor<float>(model, index, Semantic::Color, where);
    if (!values)
        return values.error();
    const bool rgba = typeComponents(model.accessors[static_cast<std::size_t>(index)].type) == 4;
    const std::size_t n = rgba ? 4 : 3;
    std::vector<glm::vec4> colors(values->size() / n);
    for (std::size_t i = 0; i < colors.size(); ++i) {
        const float* c = values->data() + n * i;
        colors[i] = {c[0], c[1], c[2], rgba ? c[3] : 1.0f};
    }
    return colors;
}

// Refuses, before any read, an accessor whose count is not `expected` (what `expectedWhat`
// names): a corrupt count then cannot allocate more than the data it must match. An index out
// of range is left to readAccessor's message.
Result<void> expectCount(const tinygltf::Model& model, int index, Semantic semantic,
                         std::uint64_t expected, const std::string& expectedWhat,
                         const std::string& where) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        return {};
    const std::uint64_t count = model.accessors[static_cast<std::size_t>(index)].count;
    if (count == expected)
        return {};
    return makeError("", accessorLabel(index, semantic, where) + " has " + std::to_string(count) +
                             " elements, but " + expectedWhat + " has " + std::to_string(expected));
}

// Reads a VEC3 or VEC4 accessor of exactly `vertexCount` elements.
template <class Vec, class T = typename Vec::value_type>
Result<std::vector<Vec>> readPerVertex(const tinygltf::Model& model, int index, Semantic semantic,
                                       std::size_t vertexCount, const std::string& where) {
    if (auto counted = expectCount(model, index, semantic, vertexCount, "POSITION", where);
        !counted)
        return counted.error();
    const auto flat = readAccessor<T>(model, index, semantic, where);
    if (!flat)
        return flat.error();
    constexpr auto n = static_cast<std::size_t>(Vec::length());
    std::vector<Vec> out(flat->size() / n);
    for (std::size_t i = 0; i < out.size(); ++i)
        for (std::size_t c = 0; c < n; ++c)
            out[i][static_cast<glm::length_t>(c)] = (*flat)[n * i + c];
    return out;
}

int attributeAccessor(const tinygltf::Primitive& primitive, const char* name) {
    const auto it = primitive.attributes.find(name);
    return it == primitive.attributes.end() ? -1 : it->second;
}

}  // namespace

glm::dmat4 composeTrs(glm::dvec3 translation, glm::dvec4 rotationXyzw, glm::dvec3 scale) {
    // glTF stores x, y, z, w; glm::dquat's constructor takes w first.
    const glm::dquat q(rotationXyzw.w, rotationXyzw.x, rotationXyzw.y, rotationXyzw.z);
    const double length = glm::length(q);
    // A zero quaternion is no rotation at all; a non-finite one stays so, for callers to refuse.
    const glm::dmat4 rotation = length == 0.0 ? glm::dmat4(1.0) : glm::mat4_cast(q / length);
    return glm::translate(glm::dmat4(1.0), translation) * rotation *
           glm::scale(glm::dmat4(1.0), scale);
}

std::string describeMesh(const tinygltf::Model& model, std::size_t meshIndex) {
    const std::string& name = model.meshes[meshIndex].name;
    return name.empty() ? "mesh " + std::to_string(meshIndex) : "mesh \"" + name + "\"";
}

Result<PrimitiveData> readTrianglePrimitive(const tinygltf::Model& model,
                                            const tinygltf::Primitive& primitive,
                                            const std::string& where, bool withColors) {
    PrimitiveData data;
    const int positionIndex = attributeAccessor(primitive, "POSITION");
    auto positions = readAccessor<float>(model, positionIndex, Semantic::Position, where);
    if (!positions)
        return positions.error();
    const std::size_t vertexCount = positions->size() / 3;
    const std::string positionLabel = accessorLabel(positionIndex, Semantic::Position, where);
    if (vertexCount > MAX_VERTICES)
        return makeError("", positionLabel + " has more vertices than grass can hold");
    data.positions.resize(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i) {
        const glm::vec3 p((*positions)[3 * i], (*positions)[3 * i + 1], (*positions)[3 * i + 2]);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return makeError(
                "", positionLabel + " holds a non-finite position at element " + std::to_string(i));
        data.positions[i] = p;
    }

    const auto sameCount = [&](std::size_t count, int index, Semantic semantic) -> Result<void> {
        if (count == vertexCount)
            return {};
        return makeError("", accessorLabel(index, semantic, where) + " has " +
                                 std::to_string(count) + " elements, but POSITION has " +
                                 std::to_string(vertexCount));
    };
    if (const int index = attributeAccessor(primitive, "NORMAL"); index >= 0) {
        const auto normals = readAccessor<float>(model, index, Semantic::Normal, where);
        if (!normals)
            return normals.error();
        if (auto same = sameCount(normals->size() / 3, index, Semantic::Normal); !same)
            return same.error();
        data.normals.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i)
            data.normals[i] = {(*normals)[3 * i], (*normals)[3 * i + 1], (*normals)[3 * i + 2]};
    }
    if (const int index = attributeAccessor(primitive, "TEXCOORD_0"); index >= 0) {
        const auto uvs = readAccessor<float>(model, index, Semantic::TexCoord, where);
        if (!uvs)
            return uvs.error();
        if (auto same = sameCount(uvs->size() / 2, index, Semantic::TexCoord); !same)
            return same.error();
        data.uvs.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i)
            data.uvs[i] = {(*uvs)[2 * i], (*uvs)[2 * i + 1]};
    }

    if (const int index = attributeAccessor(primitive, "COLOR_0"); withColors && index >= 0) {
        auto colors = readColors(model, index, where);
        if (!colors)
            return colors.error();
        if (auto same = sameCount(colors->size(), index, Semantic::Color); !same)
            return same.error();
        data.colors = std::move(*colors);
    }
    data.material = primitive.material;

    const bool indexed = primitive.indices >= 0;
    std::vector<std::uint32_t> indices;
    if (indexed) {
        auto read = readAccessor<std::uint32_t>(model, primitive.indices, Semantic::Indices, where);
        if (!read)
            return read.error();
        indices = std::move(*read);
        for (std::size_t i = 0; i < indices.size(); ++i) {
            if (indices[i] < vertexCount)
                continue;
            return makeError("", "index out of range: " +
                                     accessorLabel(primitive.indices, Semantic::Indices, where) +
                                     " holds " + std::to_string(indices[i]) + " at element " +
                                     std::to_string(i) + ", but the primitive has " +
                                     std::to_string(vertexCount) + " vertices");
        }
    }
    const std::size_t n = indexed ? indices.size() : vertexCount;
    const auto v = [&](std::size_t i) {
        return indexed ? indices[i] : static_cast<std::uint32_t>(i);
    };
    // Spec §3.7.2.1: strips alternate winding, fans pivot on the first vertex.
    if (primitive.mode == TINYGLTF_MODE_TRIANGLES) {
        data.triangles.reserve(n / 3);
        for (std::size_t i = 0; i + 2 < n; i += 3)
            data.triangles.push_back({v(i), v(i + 1), v(i + 2)});
    } else if (primitive.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 0; i + 2 < n; ++i)
            data.triangles.push_back(i % 2 == 0 ? std::array{v(i), v(i + 1), v(i + 2)}
                                                : std::array{v(i), v(i + 2), v(i + 1)});
    } else if (primitive.mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (std::size_t i = 0; i + 2 < n; ++i)
            data.triangles.push_back({v(i + 1), v(i + 2), v(0)});
    }
    return data;
}

Result<std::vector<glm::dmat4>> readInstanceTransforms(const tinygltf::Model& model,
                                                       const tinygltf::Value& extension,
                                                       const std::string& where) {
    const tinygltf::Value& attributes = extension.Get("attributes");
    const auto read = [&](const char* name, Semantic semantic) -> Result<std::vector<float>> {
        if (!attributes.Has(name))
            return std::vector<float>{};
        const tinygltf::Value& index = attributes.Get(name);
        if (!index.IsNumber())
            return makeError(
                "", where + ": EXT_mesh_gpu_instancing " + name + " is not an accessor index");
        return readAccessor<float>(model, index.GetNumberAsInt(), semantic, where);
    };
    const auto translations = read("TRANSLATION", Semantic::Translation);
    if (!translations)
        return translations.error();
    const auto rotations = read("ROTATION", Semantic::Rotation);
    if (!rotations)
        return rotations.error();
    const auto scales = read("SCALE", Semantic::Scale);
    if (!scales)
        return scales.error();
    const std::size_t count =
        std::max({translations->size() / 3, rotations->size() / 4, scales->size() / 3});
    if ((!translations->empty() && translations->size() / 3 != count) ||
        (!rotations->empty() && rotations->size() / 4 != count) ||
        (!scales->empty() && scales->size() / 3 != count))
        return makeError("", where + ": EXT_mesh_gpu_instancing attributes differ in count");
    std::vector<glm::dmat4> transforms(count);
    for (std::size_t i = 0; i < count; ++i) {
        const auto vec3 = [&](const std::vector<float>& values, glm::dvec3 absent) {
            return values.empty() ? absent
                                  : glm::dvec3(values[3 * i], values[3 * i + 1], values[3 * i + 2]);
        };
        const glm::dvec4 rotation =
            rotations->empty() ? glm::dvec4(0, 0, 0, 1)
                               : glm::dvec4((*rotations)[4 * i], (*rotations)[4 * i + 1],
                                            (*rotations)[4 * i + 2], (*rotations)[4 * i + 3]);
        transforms[i] = composeTrs(vec3(*translations, glm::dvec3(0.0)), rotation,
                                   vec3(*scales, glm::dvec3(1.0)));
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                if (!std::isfinite(transforms[i][c][r]))
                    return makeError("", where + ": EXT_mesh_gpu_instancing instance " +
                                             std::to_string(i) + " has a non-finite transform");
    }
    return transforms;
}

Result<std::vector<glm::vec4>> readInstanceColors(const tinygltf::Model& model,
                                                  const tinygltf::Value& extension,
                                                  const std::string& where) {
    const tinygltf::Value& attributes = extension.Get("attributes");
    if (!attributes.Has("_COLOR_0"))
        return std::vector<glm::vec4>{};
    const tinygltf::Value& index = attributes.Get("_COLOR_0");
    if (!index.IsNumber())
        return makeError("", where + ": EXT_mesh_gpu_instancing _COLOR_0 is not an accessor index");
    return readColors(model, index.GetNumberAsInt(), where + " _COLOR_0");
}

Result<std::vector<glm::vec3>> readMorphDeltas(const tinygltf::Model& model, int index,
                                               bool normals, std::size_t vertexCount,
                                               const std::string& where) {
    return readPerVertex<glm::vec3>(model, index, normals ? Semantic::Normal : Semantic::Position,
                                    vertexCount, where);
}

Result<std::vector<glm::uvec4>> readJoints(const tinygltf::Model& model, int index,
                                           std::size_t vertexCount, const std::string& where) {
    return readPerVertex<glm::uvec4>(model, index, Semantic::Joints, vertexCount, where);
}

Result<std::vector<glm::vec4>> readJointWeights(const tinygltf::Model& model, int index,
                                                std::size_t vertexCount,
                                                const std::string& where) {
    return readPerVertex<glm::vec4>(model, index, Semantic::Weights, vertexCount, where);
}

Result<std::vector<glm::dmat4>> readInverseBindMatrices(const tinygltf::Model& model, int index,
                                                        std::size_t jointCount,
                                                        const std::string& where) {
    if (index >= 0 && static_cast<std::size_t>(index) < model.accessors.size()) {
        const auto& accessor = model.accessors[static_cast<std::size_t>(index)];
        const std::string label = accessorLabel(index, Semantic::InverseBindMatrices, where);
        // Spec §3.7.3.1: at least one matrix per joint; the rest are unused.
        if (accessor.count < jointCount)
            return makeError("", label + " holds " + std::to_string(accessor.count) +
                                     " matrices for " + std::to_string(jointCount) + " joints");
        // Zeros with sparse overrides could claim any count; only the joints' are needed.
        if (accessor.bufferView < 0 && accessor.count > jointCount)
            return makeError("", label + " has no bufferView and " +
                                     std::to_string(accessor.count) + " matrices for " +
                                     std::to_string(jointCount) + " joints");
    }
    const auto flat = readAccessor<float>(model, index, Semantic::InverseBindMatrices, where);
    if (!flat)
        return flat.error();
    std::vector<glm::dmat4> matrices(jointCount);
    for (std::size_t j = 0; j < jointCount; ++j)
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                matrices[j][c][r] = (*flat)[16 * j + static_cast<std::size_t>(4 * c + r)];
    return matrices;
}

}  // namespace grass::core::gltf
