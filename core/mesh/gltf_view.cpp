#include "mesh/gltf_view.h"

#include <array>
#include <cmath>

#include "mesh/gltf_decoded_meshes.h"
#include "mesh/gltf_scene_walk.h"
#include "mesh/gltf_source.h"

namespace grass::core {

namespace {

// Appends one primitive placed by `world` with `tint` (instance colour × material colour).
void addPrimitive(GltfView& view, const gltf::PrimitiveData& data, const glm::dmat4& world,
                  glm::vec4 tint) {
    const glm::dmat3 normalMatrix = gltf::normalMatrix(world);
    const double det = glm::determinant(glm::dmat3(world));  // < 0: a mirror, winding reversed
    const auto first = static_cast<std::uint32_t>(view.positions.size());
    for (std::size_t i = 0; i < data.positions.size(); ++i) {
        view.positions.emplace_back(world * glm::dvec4(data.positions[i], 1.0));
        glm::dvec3 n = data.normals.empty() ? glm::dvec3(0.0) : normalMatrix * glm::dvec3(data.normals[i]);
        const double length = glm::length(n);
        view.normals.emplace_back(length > 0.0 && std::isfinite(length) ? n / length : glm::dvec3(0.0));
        view.colors.push_back(tint * (data.colors.empty() ? glm::vec4(1.0f) : data.colors[i]));
    }
    for (const auto& t : data.triangles) {
        const std::array<std::uint32_t, 3> v{first + t[0], first + (det < 0.0 ? t[2] : t[1]),
                                             first + (det < 0.0 ? t[1] : t[2])};
        view.indices.insert(view.indices.end(), v.begin(), v.end());
        // A vertex without a usable normal takes its (first) triangle's.
        const glm::vec3 face = glm::cross(view.positions[v[1]] - view.positions[v[0]],
                                          view.positions[v[2]] - view.positions[v[0]]);
        const float area = glm::length(face);
        for (const std::uint32_t k : v)
            if (view.normals[k] == glm::vec3(0.0f) && area > 0.0f)
                view.normals[k] = face / area;
    }
}

}  // namespace

Result<GltfView> loadGltfView(const std::filesystem::path& file, std::size_t maxVertices) {
    const std::string display = file.string();
    auto source = gltf::parseGltfFile(file);
    if (!source)
        return source.error();
    const tinygltf::Model& model = source->model;
    GltfView view;
    view.notes = std::move(source->notes);
    const auto instances = gltf::collectInstances(model, view.notes, true);
    if (!instances)
        return makeError(display, instances.error().message);
    gltf::DecodedMeshes decoded(model, view.notes, true);
    for (const gltf::MeshInstance& instance : *instances) {
        const auto primitives = decoded.primitives(instance);
        if (!primitives)
            return makeError(display, primitives.error().message);
        for (const gltf::PrimitiveData& data : **primitives) {
            if (view.positions.size() + data.positions.size() > maxVertices)
                return makeError(display, "places more than " + std::to_string(maxVertices) +
                                              " vertices, more than this view draws");
            const bool known = data.material >= 0 &&
                               static_cast<std::size_t>(data.material) < source->baseColors.size();
            const glm::vec4 base =
                known ? source->baseColors[static_cast<std::size_t>(data.material)] : glm::vec4(1.0f);
            addPrimitive(view, data, instance.world, instance.color * base);
        }
        ++view.placedMeshes;
    }
    return view;
}

}  // namespace grass::core
