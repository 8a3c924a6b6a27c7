// Merged blades (issue 25, `grass export --format mesh`): for viewers without
// EXT_mesh_gpu_instancing (Blender 3.4's importer shows one blade at the origin otherwise), every
// blade of a layer baked into plain triangle meshes, one per cell of the instances' grid
// (blade_instances.h), so any glTF viewer draws the field — leaning, with each blade's own
// root-to-tip colour as vertex colours — at the cost of its size: a blade is its lean bin's unit
// blade (gltf_export.h) placed by its instance transform, ~15 triangles for a triangle blade of
// 8 segments. ExportOptions::maxMergedTriangles (4M) bounds what one export may hold: what a
// viewer draws without trouble; --lod thins a denser field under it.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace grass::core {

struct MergedBladeMesh {
    int cell = 0;
    std::vector<float> positions;  // xyz, metres
    std::vector<float> normals;    // xyz, unit
    std::vector<float> colors;     // rgb, linear: mix(root, tip, v) of the blade, after its wilt
    std::vector<std::uint32_t> indices;
    std::size_t blades = 0;
    std::size_t triangles() const { return indices.size() / 3; }
};

// The triangles `layer` at `lod` would make, without building them.
std::size_t mergedBladeTriangles(const LayerField& layer, int lod, int segments);

// One mesh per non-empty cell, in cell order.
std::vector<MergedBladeMesh> mergedBlades(const LayerField& layer, int lod, int segments);

}  // namespace grass::core
