// Internal to core/project/: the parts of the project.json schema that live in their own files
// (physics_json.cpp: physics, wind, colliders), called by project_json.cpp's reader and writer.
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "project/json_reader.h"
#include "project/project.h"

namespace grass::core::json {

// Fails `pointer` when `path` is not a well-formed relative asset path (resolveAssetPath's rules).
void checkAssetPath(Reader& reader, const std::string& pointer, const std::string& path);

void readPhysics(Reader& reader, const Json& node, PhysicsParams& physics);
void readWind(Reader& reader, const Json& node, const std::string& pointer, WindDesc& wind);
void readCollider(Reader& reader, const Json& node, const std::string& pointer,
                  ColliderDesc& collider);

// billboard_json.cpp: "billboards" (SPEC §8) and the names of techniques and animation modes.
inline constexpr std::array<std::string_view, 4> TECHNIQUE_NAMES{"blades", "billboards",
                                                                 "hybrid", "growth"};
inline constexpr std::array<std::string_view, 3> ANIMATION_NAMES{"per-cluster", "per-vertex",
                                                                 "per-object"};
void readBillboards(Reader& reader, const Json& node, BillboardDesc& billboards);
Json billboardsJson(const BillboardDesc& billboards);

// growth_json.cpp: a layer's "growth" (SPEC §9).
void readGrowth(Reader& reader, const Json& node, const std::string& pointer, GrowthDesc& growth);
Json growthJson(const GrowthDesc& growth);

// lighting_json.cpp: "lighting" (SPEC §10).
void readLighting(Reader& reader, const Json& node, GrassLightingDesc& lighting);
Json lightingJson(const GrassLightingDesc& lighting);

// snow_json.cpp: "snow" (SPEC §11).
void readSnow(Reader& reader, const Json& node, SnowParams& snow);
Json snowJson(const SnowParams& snow);

Json physicsJson(const PhysicsParams& physics);
Json windJson(const WindDesc& wind);
Json colliderJson(const ColliderDesc& collider);

}  // namespace grass::core::json
