#include "mesh/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "mesh/gltf_accessor_read.h"

namespace grass::core::gltf {
namespace {

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

}  // namespace grass::core::gltf
