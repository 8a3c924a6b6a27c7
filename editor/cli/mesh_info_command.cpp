// grass mesh-info: what the loader made of a glTF file, after merging and node transforms.
#include <cstdio>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/parse_arguments.h"
#include "mesh/gltf_loader.h"
#include "mesh/mesh_frame.h"
#include "util/arg_parser.h"

namespace grass::cli {

int runMeshInfo(const std::vector<std::string>& args) {
    std::string file;
    std::string unit = "m";
    bool json = false;
    ArgParser parser("grass mesh-info <file.gltf|file.glb> [--unit UNIT] [--json]",
                     "Loads a glTF 2.0 file as grass sees it (every triangle primitive of every "
                     "mesh in the scene, node transforms applied) and prints its vertex and "
                     "triangle counts, surface area (in the file's units, squared), whether it "
                     "carried normals and UV0, and its bounds (in the file's frame). A file "
                     "whose mesh lies farther than 32 km from its origin also gets the point "
                     "that grass's origin stands for when it is a project's ground "
                     "(docs/meshes.md).");
    parser.positional("file", "a .gltf or .glb file", &file, true);
    parser.text("--unit", "UNIT",
                "what one unit of the file measures (mm, cm, m, in, ft, or metres per unit), to "
                "judge how far from its origin the mesh lies",
                &unit);
    parser.flag("--json", "print one JSON object instead of text", &json);
    if (const auto exitCode = parseArguments(parser, args, "mesh-info"))
        return *exitCode;
    const auto metresPerUnit = core::parseMeshUnit(unit);
    if (!metresPerUnit)
        return reportFailure("mesh-info", makeError("--unit", metresPerUnit.error().message),
                             EXIT_USAGE);
    auto imported = core::loadGltf(file, core::GltfPlacement::GroundNearOrigin, *metresPerUnit);
    if (!imported)
        return reportFailure("mesh-info", imported.error(), EXIT_FAILED);
    const core::SurfaceMesh& mesh = imported->mesh;
    const core::Bounds local = core::meshBounds(mesh);
    // The file's frame: the ground's vertices were moved by minus its origin.
    const glm::dvec3 origin = imported->origin;
    const glm::dvec3 lo = glm::dvec3(local.min) + origin, hi = glm::dvec3(local.max) + origin;
    const double area = core::surfaceArea(mesh);
    // Named as render's notes are, so that notes of several files checked in a row stay apart.
    for (std::string& note : imported->notes)
        note = file + ": " + note;
    printNotes(imported->notes);
    const bool moved = origin != glm::dvec3(0.0);
    if (json) {
        nlohmann::ordered_json out;
        out["vertices"] = mesh.n_vertices();
        out["triangles"] = mesh.n_faces();
        out["area"] = area;
        out["has_normals"] = imported->hasNormals;
        out["has_uv"] = imported->hasUv;
        out["bounds"] = {{lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z}};
        out["ground_origin"] = {origin.x, origin.y, origin.z};
        std::printf("%s\n", out.dump().c_str());
        return 0;
    }
    std::printf(
        "%s\n  vertices   %zu\n  triangles  %zu\n  area       %.6g\n  normals    %s\n"
        "  uv0        %s\n  bounds     [%.9g %.9g %.9g] .. [%.9g %.9g %.9g]\n",
        file.c_str(), mesh.n_vertices(), mesh.n_faces(), area,
        imported->hasNormals ? "from file" : "computed (area-weighted)",
        imported->hasUv ? "from file" : "generated (planar)", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
    if (moved)
        std::printf("  origin     [%.0f %.0f %.0f] of the file is grass's origin as a ground\n",
                    origin.x, origin.y, origin.z);
    return 0;
}

}  // namespace grass::cli
