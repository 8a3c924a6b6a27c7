#include "mesh/gltf_pose_accessors.h"

#include "mesh/gltf_accessor_read.h"

namespace grass::core::gltf {
namespace {

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

}  // namespace

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
                                                std::size_t vertexCount, const std::string& where) {
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
