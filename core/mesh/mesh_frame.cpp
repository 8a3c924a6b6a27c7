#include "mesh/mesh_frame.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace grass::core {

Result<float> parseMeshUnit(std::string_view text) {
    for (const MeshUnit& unit : MESH_UNITS)
        if (text == unit.name)
            return unit.metres;
    float value = 0.0f;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    std::string names;
    for (const MeshUnit& unit : MESH_UNITS)
        names += std::string(names.empty() ? "" : ", ") + std::string(unit.name);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return makeError("", "unknown unit \"" + std::string(text) + "\": use " + names +
                                 ", or the metres one unit of the file measures (0.001 for mm)");
    if (!(value >= MIN_METRES_PER_UNIT && value <= MAX_METRES_PER_UNIT))
        return makeError("", "a unit of " + std::string(text) +
                                 " m is outside 1e-06 to 1e+06 m (" + names + " are named units)");
    return value;
}

std::string meshUnitText(float metresPerUnit) {
    for (const MeshUnit& unit : MESH_UNITS)
        if (metresPerUnit == unit.metres)
            return std::string(unit.name);
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", static_cast<double>(metresPerUnit));
    return text;
}

Result<UpAxis> parseUpAxis(std::string_view text) {
    if (text == "+Y" || text == "y" || text == "Y" || text == "+y")
        return UpAxis::Y;
    if (text == "+Z" || text == "z" || text == "Z" || text == "+z")
        return UpAxis::Z;
    return makeError("", "unknown up axis \"" + std::string(text) + "\": use +Y or +Z");
}

std::string_view upAxisText(UpAxis up) {
    return up == UpAxis::Z ? "+Z" : "+Y";
}

void applyMeshFrame(SurfaceMesh& mesh, float metresPerUnit, UpAxis up) {
    if (metresPerUnit == 1.0f && up == UpAxis::Y)
        return;
    const auto turn = [up](const OpenMesh::Vec3f& v) {
        return up == UpAxis::Z ? OpenMesh::Vec3f(v[0], v[2], -v[1]) : v;
    };
    for (const auto vh : mesh.vertices()) {
        mesh.set_point(vh, turn(mesh.point(vh)) * metresPerUnit);
        if (mesh.has_vertex_normals())
            mesh.set_normal(vh, turn(mesh.normal(vh)));
    }
    if (mesh.has_face_normals())
        for (const auto fh : mesh.faces())
            mesh.set_normal(fh, turn(mesh.normal(fh)));
}

}  // namespace grass::core
