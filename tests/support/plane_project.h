// The starting point of small test scenes: a project growing one grass layer (no clumps) on a
// procedural plane, loaded from nowhere (assets resolve against `folder`).
#pragma once

#include <filesystem>

#include "project/project.h"

namespace grass::test {

struct PlaneField {
    float sizeM = 1.0f;
    int resolution = 2;
    float density = 100.0f;  // blades per square metre
    float heightMinM = 0.3f;
    float heightMaxM = 0.5f;
};

inline core::LoadedProject planeFieldProject(const PlaneField& field,
                                             const std::filesystem::path& folder = {}) {
    core::LoadedProject loaded;
    loaded.folder = folder;
    core::ProceduralMeshParams& mesh = loaded.project.mesh.procedural;
    mesh.shape = core::ProceduralShape::Plane;
    mesh.size = field.sizeM;
    mesh.resolution = field.resolution;
    core::ScatterParams& scatter = loaded.project.layers.front().scatter;
    scatter.density = field.density;
    scatter.clumpSpacing = 0.0f;
    scatter.blade.heightMin = field.heightMinM;
    scatter.blade.heightMax = field.heightMaxM;
    return loaded;
}

// A sphere collider (a ball) over the field: the shelter of the snow tests.
inline void addBall(core::LoadedProject& loaded, glm::vec3 centre, float radiusM) {
    core::ColliderDesc ball;
    ball.position = centre;
    ball.radiusM = radiusM;
    loaded.project.colliders.push_back(ball);
}

}  // namespace grass::test
