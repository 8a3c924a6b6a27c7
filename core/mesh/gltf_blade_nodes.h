// The blades of grass's own glTF exports (core/export), told apart from their terrain. An export
// is a terrain plus, per layer, a group node of blades (instanced unit blades, or baked meshes);
// imported as a ground (File › New from mesh, `grass render --mesh`), only the terrain is ground:
// grass grown on the exported blades would stand on blades, and the hundreds of thousands of
// blade triangles would slow every surface query for nothing.
#pragma once

#include <string_view>
#include <vector>

namespace tinygltf {
class Model;
}

namespace grass::core::gltf {

// The key of a blade group node's extras (its value: true).
inline constexpr std::string_view BLADE_GROUP_EXTRAS_KEY = "grass_blades";

// Per node, whether it is a blade group or lies under one. A blade group is a node whose extras
// hold BLADE_GROUP_EXTRAS_KEY: true, or, in exports written before that marker, a root of a
// scene whose extras hold "grass_runtime" (the export's runtime block) named "<layer> blades".
std::vector<char> bladeGroupNodes(const tinygltf::Model& model);

}  // namespace grass::core::gltf
