#include "mesh/gltf_parts.h"

namespace grass::core::gltf {

namespace {

std::string nameOr(const std::string& name, const char* kind, std::size_t index) {
    return name.empty() ? std::string(kind) + " " + std::to_string(index) : name;
}

}  // namespace

PartTable::PartTable(const tinygltf::Model& model, std::vector<std::string> materialNames)
    : mModel(model), mMaterialNames(std::move(materialNames)), mParent(model.nodes.size(), -1) {
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
        for (const int child : model.nodes[n].children)
            if (child >= 0 && static_cast<std::size_t>(child) < mParent.size() &&
                mParent[static_cast<std::size_t>(child)] < 0)
                mParent[static_cast<std::size_t>(child)] = static_cast<int>(n);
}

std::uint32_t PartTable::partOf(int node, std::size_t mesh, int material) {
    const auto key = std::make_tuple(node, mesh, material);
    if (const auto found = mIndex.find(key); found != mIndex.end())
        return found->second;
    MeshPart part;
    // Up the hierarchy, at most once per node (collectInstances refused cycles, but the first
    // parent found here need not be the one it walked).
    for (int at = node; at >= 0 && part.nodes.size() <= mParent.size();
         at = mParent[static_cast<std::size_t>(at)]) {
        const auto index = static_cast<std::size_t>(at);
        part.nodes.push_back(nameOr(mModel.nodes[index].name, "node", index));
    }
    part.mesh = nameOr(mModel.meshes[mesh].name, "mesh", mesh);
    const auto materialIndex = static_cast<std::size_t>(material);
    part.material = material < 0 ? "(no material)"
                    : materialIndex < mMaterialNames.size()
                        ? nameOr(mMaterialNames[materialIndex], "material", materialIndex)
                        : "material " + std::to_string(materialIndex);
    const auto index = static_cast<std::uint32_t>(mParts.parts.size());
    mParts.parts.push_back(std::move(part));
    mIndex.emplace(key, index);
    return index;
}

void PartTable::addFaces(int node, std::size_t mesh, int material, std::size_t endFace) {
    if (endFace > mParts.faceParts.size())
        mParts.faceParts.resize(endFace, partOf(node, mesh, material));
}

}  // namespace grass::core::gltf
