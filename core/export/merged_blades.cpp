#include "export/merged_blades.h"

#include <map>

#include "export/blade_instances.h"
#include "export/gltf_export.h"

namespace grass::core {

namespace {

// The unit blade of every lean bin in use, built once.
class UnitBlades {
public:
    UnitBlades(const LayerField& layer, int segments) : mLayer(layer), mSegments(segments) {}
    const UnitBladeMesh& of(int bin) {
        auto found = mMeshes.find(bin);
        if (found == mMeshes.end())
            found = mMeshes
                        .emplace(bin, unitBladeMesh(mLayer.shape, mLayer.tipStart, mSegments,
                                                    leanBinRad(bin)))
                        .first;
        return found->second;
    }

private:
    const LayerField& mLayer;
    int mSegments;
    std::map<int, UnitBladeMesh> mMeshes;
};

}  // namespace

std::size_t mergedBladeTriangles(const LayerField& layer, int lod, int segments) {
    UnitBlades unit(layer, segments);
    std::size_t triangles = 0;
    for (const BladeInstance& b : bladeInstances(layer, lod))
        triangles += unit.of(b.leanBin).indices.size() / 3;
    return triangles;
}

std::vector<MergedBladeMesh> mergedBlades(const LayerField& layer, int lod, int segments) {
    const std::vector<BladeInstance> instances = bladeInstances(layer, lod);
    UnitBlades unit(layer, segments);
    std::vector<MergedBladeMesh> meshes;
    for (const InstanceGroup& group : groupInstances(instances)) {
        if (meshes.empty() || meshes.back().cell != group.cell)
            meshes.push_back(MergedBladeMesh{group.cell, {}, {}, {}, {}, 0});
        MergedBladeMesh& out = meshes.back();
        const UnitBladeMesh& blade = unit.of(group.bin);
        out.blades += group.members.size();
        for (const std::uint32_t i : group.members) {
            const BladeInstance& b = instances[i];
            const auto first = static_cast<std::uint32_t>(out.positions.size() / 3);
            for (std::size_t v = 0; v < blade.heights.size(); ++v) {
                const glm::vec3 p(blade.positions[3 * v], blade.positions[3 * v + 1],
                                  blade.positions[3 * v + 2]);
                const glm::vec3 n(blade.normals[3 * v], blade.normals[3 * v + 1],
                                  blade.normals[3 * v + 2]);
                // The instance transform, T · R · S. Normals have no x (the blade is flat across
                // its width) and y and z scale alike (h), so R · n is already the
                // inverse-transpose's direction.
                const glm::vec3 world = b.translation + b.rotation * (b.scale * p);
                const glm::vec3 normal = glm::normalize(b.rotation * n);
                const glm::vec3 colour = glm::mix(b.rootColor, b.tipColor, blade.heights[v]);
                out.positions.insert(out.positions.end(), {world.x, world.y, world.z});
                out.normals.insert(out.normals.end(), {normal.x, normal.y, normal.z});
                out.colors.insert(out.colors.end(), {colour.r, colour.g, colour.b});
            }
            for (const std::uint32_t index : blade.indices)
                out.indices.push_back(first + index);
        }
    }
    return meshes;
}

}  // namespace grass::core
