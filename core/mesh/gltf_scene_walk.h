// Walking a parsed glTF 2.0 scene: which meshes its nodes place and where (node hierarchy,
// matrices or T·R·S, EXT_mesh_gpu_instancing), and a mesh's triangle primitives decoded. Shared
// by the geometry import (gltf_loader.cpp) and the stock viewer's picture (gltf_view.h). Errors
// carry no path: the caller adds the file's.
#pragma once

#include <tiny_gltf.h>
#include <cstddef>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "mesh/gltf_accessors.h"
#include "util/result.h"

namespace grass::core::gltf {

// A mesh placed in the world by one node, or by one of its GPU instances (or by the file itself
// when it has no scenes).
struct MeshInstance {
    std::size_t mesh = 0;
    glm::dmat4 world{1.0};
    glm::vec4 color{1.0f};  // the instance's _COLOR_0; white for plain nodes
    int node = -1;          // the node that placed it; -1 for a file without scenes
};

// Normals go by the inverse-transpose of `world`'s linear part, whose columns are the cross
// products of its columns over its determinant; only the direction matters, so this divides by
// the determinant's sign alone. A mirroring transform (determinant < 0) also reverses the
// winding (spec §3.7.4).
glm::dmat3 normalMatrix(const glm::dmat4& world);

// Every mesh the default scene (else scene 0) places, with its world transform. A file without
// scenes places each mesh once, untransformed (noted). Errors: a node index out of range, a
// cycle, more than a million node visits, a bad transform or instancing attribute. Instance
// colours are read only `withColors`.
Result<std::vector<MeshInstance>> collectInstances(const tinygltf::Model& model,
                                                   std::vector<std::string>& notes,
                                                   bool withColors = false);

// The triangle primitives of one mesh; points, lines and primitives without POSITION are
// skipped with a note, morph targets ignored (noted). COLOR_0 is decoded only `withColors`.
Result<std::vector<PrimitiveData>> decodeMesh(const tinygltf::Model& model, std::size_t meshIndex,
                                              std::vector<std::string>& notes,
                                              bool withColors = false);

// Each mesh decoded once (decodeMesh), shared by every node and GPU instance that places it.
class DecodedMeshes {
public:
    DecodedMeshes(const tinygltf::Model& model, std::vector<std::string>& notes, bool withColors)
        : mModel(model), mNotes(notes), mWithColors(withColors), mDecoded(model.meshes.size()) {}
    // `mesh` < model.meshes.size() (collectInstances checks it).
    Result<const std::vector<PrimitiveData>*> primitives(std::size_t mesh) {
        auto& decoded = mDecoded[mesh];
        if (!decoded) {
            auto read = decodeMesh(mModel, mesh, mNotes, mWithColors);
            if (!read)
                return read.error();
            decoded = std::move(*read);
        }
        return &*decoded;
    }

private:
    const tinygltf::Model& mModel;
    std::vector<std::string>& mNotes;
    bool mWithColors;
    std::vector<std::optional<std::vector<PrimitiveData>>> mDecoded;
};

}  // namespace grass::core::gltf
