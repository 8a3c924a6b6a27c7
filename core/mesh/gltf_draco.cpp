#include "mesh/gltf_draco.h"

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

#include <cmath>
#include <limits>
#include <memory>

namespace grass::core::gltf {

namespace {

// The bytes of bufferView `index`, checked to lie inside its buffer.
Result<std::pair<const char*, std::size_t>> viewBytes(const tinygltf::Model& model, int index,
                                                      const std::string& what) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.bufferViews.size())
        return makeError("", what + " refers to bufferView " + std::to_string(index) +
                                 ", but the file has " + std::to_string(model.bufferViews.size()));
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(index)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= model.buffers.size())
        return makeError("", what + ": bufferView " + std::to_string(index) + " has no buffer");
    const std::vector<unsigned char>& data = model.buffers[std::size_t(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        return makeError("", what + ": bufferView " + std::to_string(index) +
                                 " reads past the end of its buffer: the file is truncated or corrupt");
    return std::pair{reinterpret_cast<const char*>(data.data() + view.byteOffset), view.byteLength};
}

// The Draco attribute `name` maps to, or null when the extension does not list it.
Result<const draco::PointAttribute*> attribute(const draco::Mesh& mesh, const tinygltf::Value& ids,
                                               const char* name, int minComponents,
                                               int maxComponents, const std::string& where) {
    if (!ids.Has(name))
        return static_cast<const draco::PointAttribute*>(nullptr);
    const tinygltf::Value& id = ids.Get(name);
    const double number = id.IsNumber() ? id.GetNumberAsDouble() : -1.0;
    const std::string what = where + ": Draco attribute " + name;
    if (!(number >= 0.0 && number <= double(std::numeric_limits<std::uint32_t>::max())))
        return makeError("", what + " has no valid attribute id");
    const draco::PointAttribute* found = mesh.GetAttributeByUniqueId(std::uint32_t(number));
    if (!found)
        return makeError("", what + " (id " + std::to_string(std::uint32_t(number)) +
                                 ") is not in the compressed data");
    if (found->num_components() < minComponents || found->num_components() > maxComponents)
        return makeError("", what + " has " + std::to_string(found->num_components()) +
                                 " components; " + name + " needs " + std::to_string(minComponents) +
                                 (maxComponents > minComponents ? " or " + std::to_string(maxComponents) : ""));
    return found;
}

// Every point's value of `attr` as N floats (missing components stay 0; alpha defaults below).
template <int N>
Result<std::vector<float>> values(const draco::Mesh& mesh, const draco::PointAttribute& attr,
                                  const std::string& what) {
    std::vector<float> out(std::size_t(mesh.num_points()) * N, 0.0f);
    for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
        const draco::AttributeValueIndex index = attr.mapped_index(p);
        if (index.value() >= attr.size() ||
            !attr.ConvertValue<float>(index, std::int8_t(attr.num_components()),
                                      out.data() + std::size_t(p.value()) * N))
            return makeError("", what + " cannot be read at vertex " + std::to_string(p.value()));
    }
    return out;
}

}  // namespace

Result<PrimitiveData> readDracoPrimitive(const tinygltf::Model& model,
                                         const tinygltf::Primitive& primitive,
                                         const tinygltf::Value& extension, const std::string& where,
                                         bool withColors) {
    const std::string what = where + " (KHR_draco_mesh_compression)";
    const int viewIndex = extension.Has("bufferView") && extension.Get("bufferView").IsNumber()
                              ? extension.Get("bufferView").GetNumberAsInt()
                              : -1;
    const auto bytes = viewBytes(model, viewIndex, what);
    if (!bytes)
        return bytes.error();
    draco::DecoderBuffer buffer;
    buffer.Init(bytes->first, bytes->second);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok())
        return makeError("", what + " cannot be decoded: " + decoded.status().error_msg_string());
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    if (!mesh)
        return makeError("", what + " holds no mesh");
    const tinygltf::Value& ids = extension.Get("attributes");
    const std::size_t vertexCount = mesh->num_points();
    if (vertexCount > std::size_t(std::numeric_limits<int>::max()))
        return makeError("", what + " has more vertices than grass can hold");
    // The spec: the primitive's accessors keep the counts of the decoded data.
    const auto position = primitive.attributes.find("POSITION");
    if (position != primitive.attributes.end() && position->second >= 0 &&
        std::size_t(position->second) < model.accessors.size() &&
        model.accessors[std::size_t(position->second)].count != vertexCount)
        return makeError("", what + " decodes " + std::to_string(vertexCount) +
                                 " vertices, but its POSITION accessor says " +
                                 std::to_string(model.accessors[std::size_t(position->second)].count));
    const std::size_t faceCount = mesh->num_faces();
    const int indices = primitive.indices >= 0 ? primitive.indices
                        : extension.Has(DRACO_INDICES_KEY) && extension.Get(DRACO_INDICES_KEY).IsNumber()
                            ? extension.Get(DRACO_INDICES_KEY).GetNumberAsInt()
                            : -1;
    if (indices >= 0 && std::size_t(indices) < model.accessors.size() &&
        model.accessors[std::size_t(indices)].count != faceCount * 3)
        return makeError("", what + " decodes " + std::to_string(faceCount * 3) +
                                 " indices, but its indices accessor says " +
                                 std::to_string(model.accessors[std::size_t(indices)].count));

    PrimitiveData data;
    data.material = primitive.material;
    const auto positionAttribute = attribute(*mesh, ids, "POSITION", 3, 3, where);
    if (!positionAttribute)
        return positionAttribute.error();
    if (!*positionAttribute)
        return makeError("", what + " lists no POSITION attribute");
    auto positions = values<3>(*mesh, **positionAttribute, what + " POSITION");
    if (!positions)
        return positions.error();
    data.positions.resize(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i) {
        const glm::vec3 p((*positions)[3 * i], (*positions)[3 * i + 1], (*positions)[3 * i + 2]);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return makeError("", what + " holds a non-finite position at vertex " + std::to_string(i));
        data.positions[i] = p;
    }
    const auto normalAttribute = attribute(*mesh, ids, "NORMAL", 3, 3, where);
    if (!normalAttribute)
        return normalAttribute.error();
    if (*normalAttribute) {
        auto normals = values<3>(*mesh, **normalAttribute, what + " NORMAL");
        if (!normals)
            return normals.error();
        data.normals.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i)
            data.normals[i] = {(*normals)[3 * i], (*normals)[3 * i + 1], (*normals)[3 * i + 2]};
    }
    const auto uvAttribute = attribute(*mesh, ids, "TEXCOORD_0", 2, 2, where);
    if (!uvAttribute)
        return uvAttribute.error();
    if (*uvAttribute) {
        auto uvs = values<2>(*mesh, **uvAttribute, what + " TEXCOORD_0");
        if (!uvs)
            return uvs.error();
        data.uvs.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i)
            data.uvs[i] = {(*uvs)[2 * i], (*uvs)[2 * i + 1]};
    }
    if (withColors) {
        const auto colorAttribute = attribute(*mesh, ids, "COLOR_0", 3, 4, where);
        if (!colorAttribute)
            return colorAttribute.error();
        if (*colorAttribute) {
            auto colors = values<4>(*mesh, **colorAttribute, what + " COLOR_0");
            if (!colors)
                return colors.error();
            const bool rgb = (*colorAttribute)->num_components() == 3;
            data.colors.resize(vertexCount);
            for (std::size_t i = 0; i < vertexCount; ++i)
                data.colors[i] = {(*colors)[4 * i], (*colors)[4 * i + 1], (*colors)[4 * i + 2],
                                  rgb ? 1.0f : (*colors)[4 * i + 3]};
        }
    }
    data.triangles.reserve(faceCount);
    for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f) {
        const draco::Mesh::Face& face = mesh->face(f);
        std::array<std::uint32_t, 3> triangle{};
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = face[k].value();
            if (v >= vertexCount)
                return makeError("", what + " has an index out of range at triangle " +
                                         std::to_string(f.value()));
            triangle[std::size_t(k)] = v;
        }
        data.triangles.push_back(triangle);
    }
    return data;
}

}  // namespace grass::core::gltf
