// The tables of project.json: one per section, each row describing one key (setting.h). This is
// where a setting is added: a row in its section's table (in the *_json.cpp file named below)
// makes the reader read it, the writer write it, docs/project-format.md list it (a test checks)
// and, where a panel draws the section, the editor show it.
#pragma once

#include <span>

#include "project/project.h"
#include "project/setting.h"

namespace grass::core::settings {

std::span<const Setting<Project>> project();          // project_json.cpp: the top level
std::span<const Setting<MeshSource>> mesh();          // project_json.cpp
std::span<const Setting<GrassLayer>> layer();         // layer_json.cpp
std::span<const Setting<BladeRanges>> blade();        // layer_json.cpp: a layer's "blade"
std::span<const Setting<GrowthDesc>> growth();        // growth_json.cpp: a layer's "growth"
std::span<const Setting<PlacementRules>> rules();     // rules_json.cpp: a layer's "rules"
std::span<const Setting<BendingCues>> bending();     // bending_json.cpp: a layer's "bending"
std::span<const Setting<CameraDesc>> camera();        // project_json.cpp
std::span<const Setting<SunDesc>> sun();              // lighting_json.cpp
std::span<const Setting<GrassLightingDesc>> lighting();  // lighting_json.cpp
std::span<const Setting<RenderSettings>> render();    // render_json.cpp
std::span<const Setting<BillboardDesc>> billboards();  // billboard_json.cpp
std::span<const Setting<PhysicsParams>> physics();    // physics_json.cpp
std::span<const Setting<WindDesc>> wind();            // wind_json.cpp
std::span<const Setting<ColliderDesc>> collider();    // collider_json.cpp
std::span<const Setting<SnowParams>> snow();          // snow_json.cpp

}  // namespace grass::core::settings
