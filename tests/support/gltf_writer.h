// Writes glTF 2.0 files from C++ data so tests make their own inputs: .gltf with an external
// .bin file or a base64 data: URI, and .glb. Two steps: buildGltf() makes the JSON document and
// its one binary buffer (GltfDocument), which a test may damage or extend (plain nlohmann::json
// edits), then writeGltf() stores it. Units are whatever the test means (metres for grass).
#pragma once

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace grass::test {

// How an attribute's components are stored. Integer types are what KHR_mesh_quantization and
// normalized TEXCOORD_0 use: normalized values are scaled to the type's range, others rounded.
enum class ComponentEncoding { Float, Byte, UnsignedByte, Short, UnsignedShort };

struct AttributeEncoding {
    ComponentEncoding type = ComponentEncoding::Float;
    bool normalized = false;
};

enum class IndexType { UnsignedByte, UnsignedShort, UnsignedInt };

// glTF primitive modes (spec §3.7.2.1).
enum class PrimitiveMode {
    Points = 0,
    Lines = 1,
    LineLoop = 2,
    LineStrip = 3,
    Triangles = 4,
    TriangleStrip = 5,
    TriangleFan = 6
};

struct GltfPrimitive {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;      // empty: no NORMAL attribute
    std::vector<glm::vec2> uvs;          // empty: no TEXCOORD_0 attribute
    std::vector<std::uint32_t> indices;  // empty: not indexed
    PrimitiveMode mode = PrimitiveMode::Triangles;
    IndexType indexType = IndexType::UnsignedInt;
    AttributeEncoding positionEncoding;
    AttributeEncoding normalEncoding;
    AttributeEncoding uvEncoding;
    // All attributes in one bufferView with a byteStride (each attribute 4-byte aligned).
    bool interleaved = false;
    // POSITION as a sparse accessor: these elements are written as sparse overrides of
    // `positions`. With sparseWithoutBufferView the accessor has no bufferView, so its base is
    // zeros and `positions` only sets the count.
    std::vector<std::pair<std::uint32_t, glm::vec3>> sparsePositions;
    bool sparseWithoutBufferView = false;
    int material = -1;  // into GltfAsset::materials; -1: none
};

struct GltfMesh {
    std::string name;
    std::vector<GltfPrimitive> primitives;
};

// One EXT_mesh_gpu_instancing instance: a T * R * S applied before the node's transform.
struct GltfInstance {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
};

struct GltfNode {
    std::string name;
    int mesh = -1;
    std::vector<int> children;
    std::optional<glm::mat4> matrix;  // written as "matrix" instead of TRS when set
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // glm order: w, x, y, z
    glm::vec3 scale{1.0f};
    // Non-empty: the node's mesh is drawn once per instance (EXT_mesh_gpu_instancing, added to
    // extensionsUsed).
    std::vector<GltfInstance> instances;
};

// A plain material: a name and pbrMetallicRoughness.baseColorFactor.
struct GltfMaterial {
    std::string name;
    glm::vec4 baseColor{1.0f};
};

struct GltfAsset {
    std::vector<GltfMesh> meshes;
    std::vector<GltfNode> nodes;
    // Roots of scene 0; empty means every node that is nobody's child.
    std::vector<int> sceneNodes;
    bool withScene = true;  // false: the file has no "scenes" and no "scene"
    std::vector<std::string> extensionsUsed;
    std::vector<std::string> extensionsRequired;
    std::vector<GltfMaterial> materials;  // what the primitives' `material` indices refer to
};

struct GltfDocument {
    nlohmann::json json;            // buffers[0] has no "uri" yet: writeGltf() sets it
    std::vector<std::uint8_t> bin;  // the contents of buffer 0
};

GltfDocument buildGltf(const GltfAsset& asset);

enum class BufferStorage { ExternalFile, DataUri, Glb };

// Writes `file`; BufferStorage::ExternalFile also writes the buffer to `binFileName`, relative
// to the glTF file's folder (it may contain spaces or "../"; the URI is its percent-encoding),
// by default "<stem>.bin". Aborts on an I/O failure: a test bug.
void writeGltf(const std::filesystem::path& file, const GltfDocument& document,
               BufferStorage storage = BufferStorage::ExternalFile,
               const std::string& binFileName = {});
void writeGltf(const std::filesystem::path& file, const GltfAsset& asset,
               BufferStorage storage = BufferStorage::ExternalFile,
               const std::string& binFileName = {});

// RFC 3986 percent-encoding of a relative path: unreserved characters and '/' stay.
std::string percentEncodeUri(const std::string& path);

// One mesh placed once by one untransformed node.
GltfAsset singleMeshAsset(GltfPrimitive primitive, const std::string& name = "Mesh");
// A flat grid on the XZ plane centred on the origin, normal +Y, UVs spanning [0, 1]²,
// counter-clockwise seen from +Y: `cells`² quads of two triangles each.
GltfPrimitive gridPrimitive(float sizeX, float sizeZ, int cells);
// An axis-aligned box with 24 vertices (own normal and UVs per face) and outward winding.
GltfPrimitive boxPrimitive(glm::vec3 min, glm::vec3 max);

}  // namespace grass::test
