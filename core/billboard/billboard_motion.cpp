#include "billboard/billboard_motion.h"

#include <cmath>

namespace grass::core {

glm::vec3 billboardWindBend(glm::vec3 wind, glm::vec3 up, float heightM, float stiffness) {
    if (!(heightM > 0.0f) || !(stiffness > 0.0f))
        return glm::vec3(0.0f);
    const glm::vec3 across = wind - up * glm::dot(wind, up);
    const float push = glm::length(across) / stiffness;  // |Δ|, metres
    if (!(push > 0.0f) || !std::isfinite(push))
        return glm::vec3(0.0f);
    const float x = push / heightM;
    const float reach = heightM * (x / (1.0f + x));  // < h
    const float sink = heightM - std::sqrt(heightM * heightM - reach * reach);
    return across * (reach / (push * stiffness)) - up * sink;
}

glm::vec3 billboardPhasePoint(const StarVertex& vertex, BillboardWindMode mode,
                              glm::vec3 clusterCentre) {
    switch (mode) {
        case BillboardWindMode::PerVertex: return vertex.position;
        case BillboardWindMode::PerObject: return vertex.objectCentre;
        case BillboardWindMode::PerCluster: break;
    }
    return clusterCentre;
}

glm::vec3 billboardTranslation(const StarVertex& vertex, glm::vec3 phasePoint, float timeS,
                               const BillboardWind& sway, glm::vec3 sceneWindAtPhasePoint,
                               float stiffness) {
    return billboardWindOffset(phasePoint, timeS, sway) +
           billboardWindBend(sceneWindAtPhasePoint, vertex.normal, vertex.objectHeight,
                             stiffness);
}

StarVertexMotion animateStarVertex(const StarVertex& vertex, glm::vec3 translation) {
    if (vertex.sway <= 0.0f)
        return {vertex.position, vertex.normal};
    const glm::vec3 turned = vertex.normal * vertex.objectHeight + translation;
    const float length = glm::length(turned);
    return {vertex.position + vertex.sway * translation,
            length > 0.0f ? turned / length : vertex.normal};
}

StarVertexMotion billboardVertexMotion(const StarVertex& vertex, BillboardWindMode mode,
                                       glm::vec3 clusterCentre, float timeS,
                                       const BillboardWind& sway,
                                       const BillboardSceneWind& scene) {
    const glm::vec3 at = billboardPhasePoint(vertex, mode, clusterCentre);
    glm::vec3 wind(0.0f);
    for (const WindSource& source : scene.sources)
        wind += windAt(source, at, timeS);
    return animateStarVertex(
        vertex, billboardTranslation(vertex, at, timeS, sway, wind, scene.stiffness));
}

}  // namespace grass::core
