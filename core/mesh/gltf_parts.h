// The parts table of a glTF import (mesh_parts.h): one part per distinct node, mesh and material
// that placed triangles, named as the file names them.
#pragma once

#include <map>
#include <tiny_gltf.h>
#include <tuple>

#include "mesh/mesh_parts.h"

namespace grass::core::gltf {

class PartTable {
public:
    // `materialNames`: GltfSource's (the model itself holds no materials).
    PartTable(const tinygltf::Model& model, std::vector<std::string> materialNames);
    // The part of the faces a primitive with `material` of `mesh`, placed by `node` (-1: none),
    // adds; faces [faceCount() .. endFace) get it.
    void addFaces(int node, std::size_t mesh, int material, std::size_t endFace);
    MeshParts take() { return std::move(mParts); }

private:
    std::uint32_t partOf(int node, std::size_t mesh, int material);

    const tinygltf::Model& mModel;
    std::vector<std::string> mMaterialNames;
    std::vector<int> mParent;  // per node, the node listing it as a child (-1: a root)
    std::map<std::tuple<int, std::size_t, int>, std::uint32_t> mIndex;
    MeshParts mParts;
};

}  // namespace grass::core::gltf
