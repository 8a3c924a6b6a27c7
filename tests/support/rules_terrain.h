// The terrain of issue 27's checks, written as a glTF file without UVs (as many downloaded
// terrains come): a 20 m ground ("Ground", material "Soil"), a 70° cliff standing on it ("Cliff",
// "Rock"), a sphere floating 6 m up ("Cloud", "Cloud") and a tree-like blob ("Tree" with children
// "Trunk", "Bark" and "Canopy", "Leaves").
#pragma once

#include <filesystem>
#include <string>

#include <glm/glm.hpp>

#include "project/project.h"

namespace grass::test {

// Where the fixture's parts stand, for tests that measure around them.
inline constexpr float RULES_CLIFF_SLOPE_DEG = 70.0f;
inline constexpr glm::vec3 RULES_CLOUD_CENTRE{-5.0f, 6.0f, -5.0f};
inline constexpr float RULES_CLOUD_RADIUS = 1.5f;
inline constexpr glm::vec3 RULES_TREE_BASE{3.0f, 0.0f, 4.0f};

void writeRulesTerrain(const std::filesystem::path& file);

// `folder`/terrain.glb (the terrain above) and `folder`/project.json holding `projectJson`,
// loaded (a test failure when it does not load).
core::LoadedProject writeRulesTerrainProject(const std::filesystem::path& folder,
                                             const std::string& projectJson);

}  // namespace grass::test
