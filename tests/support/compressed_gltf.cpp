#include "support/compressed_gltf.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <meshoptimizer.h>

#include <cstdlib>
#include <cstring>

namespace grass::test {

namespace {

using nlohmann::json;

void appendAligned(std::vector<std::uint8_t>& bin, const void* data, std::size_t size) {
    while (bin.size() % 4 != 0)
        bin.push_back(0);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    bin.insert(bin.end(), bytes, bytes + size);
}

std::vector<std::uint32_t> indicesOf(const GltfPrimitive& p) {
    if (!p.indices.empty())
        return p.indices;
    std::vector<std::uint32_t> all(p.positions.size());
    for (std::uint32_t i = 0; i < all.size(); ++i)
        all[i] = i;
    return all;
}

json emptyDocument() {
    return {{"asset", {{"version", "2.0"}, {"generator", "grass tests (compressed_gltf.cpp)"}}},
            {"scene", 0},
            {"scenes", {{{"nodes", {0}}}}},
            {"nodes", {{{"name", "Mesh"}, {"mesh", 0}}}},
            {"buffers", json::array()},
            {"bufferViews", json::array()},
            {"accessors", json::array()}};
}

}  // namespace

GltfDocument dracoDocument(const GltfPrimitive& primitive, int positionBits) {
    const std::vector<std::uint32_t> indices = indicesOf(primitive);
    const int faces = int(indices.size() / 3);
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(faces);
    const int position = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    const int normal = primitive.normals.empty()
                           ? -1
                           : builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
    const int uv = primitive.uvs.empty()
                       ? -1
                       : builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
    for (int f = 0; f < faces; ++f) {
        const std::uint32_t* t = &indices[std::size_t(3 * f)];
        const draco::FaceIndex face(static_cast<std::uint32_t>(f));
        builder.SetAttributeValuesForFace(position, face, &primitive.positions[t[0]],
                                          &primitive.positions[t[1]], &primitive.positions[t[2]]);
        if (normal >= 0)
            builder.SetAttributeValuesForFace(normal, face, &primitive.normals[t[0]],
                                              &primitive.normals[t[1]], &primitive.normals[t[2]]);
        if (uv >= 0)
            builder.SetAttributeValuesForFace(uv, face, &primitive.uvs[t[0]], &primitive.uvs[t[1]],
                                              &primitive.uvs[t[2]]);
    }
    std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, positionBits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 10);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
    draco::EncoderBuffer encoded;
    if (!mesh || !encoder.EncodeMeshToBuffer(*mesh, &encoded).ok())
        std::abort();  // a test bug
    // The accessors must count what a decoder yields (the encoder may merge or split points).
    draco::DecoderBuffer readBack;
    readBack.Init(encoded.data(), encoded.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&readBack);
    if (!decoded.ok())
        std::abort();
    const std::unique_ptr<draco::Mesh> points = std::move(decoded).value();

    GltfDocument doc;
    doc.json = emptyDocument();
    appendAligned(doc.bin, encoded.data(), encoded.size());
    doc.json["buffers"].push_back({{"byteLength", doc.bin.size()}});
    doc.json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 0}, {"byteLength", encoded.size()}});
    const auto accessor = [&](const char* type, int componentType, std::size_t count) {
        doc.json["accessors"].push_back({{"componentType", componentType}, {"count", count}, {"type", type}});
        return doc.json["accessors"].size() - 1;
    };
    const std::size_t vertexCount = points->num_points();
    json attributes = {{"POSITION", accessor("VEC3", 5126, vertexCount)}};
    json ids = {{"POSITION", mesh->attribute(position)->unique_id()}};
    doc.json["accessors"][0]["min"] = {-1e9, -1e9, -1e9};
    doc.json["accessors"][0]["max"] = {1e9, 1e9, 1e9};
    if (normal >= 0) {
        attributes["NORMAL"] = accessor("VEC3", 5126, vertexCount);
        ids["NORMAL"] = mesh->attribute(normal)->unique_id();
    }
    if (uv >= 0) {
        attributes["TEXCOORD_0"] = accessor("VEC2", 5126, vertexCount);
        ids["TEXCOORD_0"] = mesh->attribute(uv)->unique_id();
    }
    const std::size_t indexAccessor = accessor("SCALAR", 5125, std::size_t(points->num_faces()) * 3);
    doc.json["meshes"] = {{{"name", "Mesh"},
                           {"primitives",
                            {{{"attributes", attributes},
                              {"indices", indexAccessor},
                              {"extensions",
                               {{"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", ids}}}}}}}}}};
    doc.json["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    doc.json["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    return doc;
}

GltfDocument meshoptDocument(const GltfPrimitive& primitive, bool octahedralNormals) {
    GltfDocument doc;
    doc.json = emptyDocument();
    std::size_t fallbackBytes = 0;
    // One compressed stream in buffer 0 per bufferView; its place in the fallback buffer 1.
    const auto addView = [&](const void* raw, std::size_t count, std::size_t stride, const char* mode,
                             const char* filter, int target) {
        std::vector<unsigned char> encoded;
        if (std::strcmp(mode, "ATTRIBUTES") == 0) {
            encoded.resize(meshopt_encodeVertexBufferBound(count, stride));
            encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), raw, count, stride));
        } else {
            encoded.resize(meshopt_encodeIndexBufferBound(count, count));
            encoded.resize(meshopt_encodeIndexBuffer(encoded.data(), encoded.size(),
                                                     static_cast<const unsigned int*>(raw), count));
        }
        while (doc.bin.size() % 4 != 0)
            doc.bin.push_back(0);
        const std::size_t offset = doc.bin.size();
        doc.bin.insert(doc.bin.end(), encoded.begin(), encoded.end());
        json extension = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", encoded.size()},
                          {"byteStride", stride}, {"count", count}, {"mode", mode}};
        if (filter)
            extension["filter"] = filter;
        json view = {{"buffer", 1}, {"byteOffset", fallbackBytes}, {"byteLength", count * stride},
                     {"target", target}, {"extensions", {{"EXT_meshopt_compression", extension}}}};
        if (target == 34962)
            view["byteStride"] = stride;
        doc.json["bufferViews"].push_back(view);
        fallbackBytes += (count * stride + 3) / 4 * 4;
        return doc.json["bufferViews"].size() - 1;
    };
    const auto accessor = [&](std::size_t view, const char* type, int componentType, std::size_t count,
                              bool normalized) {
        json a = {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
        if (normalized)
            a["normalized"] = true;
        doc.json["accessors"].push_back(a);
        return doc.json["accessors"].size() - 1;
    };
    const std::size_t n = primitive.positions.size();
    // Positions padded to 16 bytes: a stride of 4's multiple, as the extension wants.
    std::vector<float> positions;
    for (const glm::vec3& p : primitive.positions)
        positions.insert(positions.end(), {p.x, p.y, p.z, 0.0f});
    json attributes = {{"POSITION", accessor(addView(positions.data(), n, 16, "ATTRIBUTES", nullptr, 34962),
                                             "VEC3", 5126, n, false)}};
    doc.json["accessors"][0]["min"] = {-1e9, -1e9, -1e9};
    doc.json["accessors"][0]["max"] = {1e9, 1e9, 1e9};
    if (!primitive.normals.empty()) {
        if (octahedralNormals) {
            std::vector<float> unit;
            for (const glm::vec3& v : primitive.normals)
                unit.insert(unit.end(), {v.x, v.y, v.z, 0.0f});
            std::vector<std::int16_t> packed(4 * n);
            meshopt_encodeFilterOct(packed.data(), n, 8, 16, unit.data());
            attributes["NORMAL"] = accessor(addView(packed.data(), n, 8, "ATTRIBUTES", "OCTAHEDRAL", 34962),
                                            "VEC3", 5122, n, true);
        } else {
            std::vector<float> normals;
            for (const glm::vec3& v : primitive.normals)
                normals.insert(normals.end(), {v.x, v.y, v.z, 0.0f});
            attributes["NORMAL"] = accessor(addView(normals.data(), n, 16, "ATTRIBUTES", nullptr, 34962),
                                            "VEC3", 5126, n, false);
        }
    }
    if (!primitive.uvs.empty())
        attributes["TEXCOORD_0"] = accessor(addView(primitive.uvs.data(), n, 8, "ATTRIBUTES", nullptr, 34962),
                                            "VEC2", 5126, n, false);
    const std::vector<std::uint32_t> indices = indicesOf(primitive);
    const std::size_t indexAccessor =
        accessor(addView(indices.data(), indices.size(), 4, "TRIANGLES", nullptr, 34963), "SCALAR", 5125,
                 indices.size(), false);
    doc.json["buffers"].push_back({{"byteLength", doc.bin.size()}});
    doc.json["buffers"].push_back(
        {{"byteLength", fallbackBytes}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
    doc.json["meshes"] = {{{"name", "Mesh"},
                           {"primitives", {{{"attributes", attributes}, {"indices", indexAccessor}}}}}};
    doc.json["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    doc.json["extensionsRequired"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    return doc;
}

}  // namespace grass::test
