// grass mesh-info: what the loader made of a glTF file, after merging and node transforms.
#include <cstdio>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/parse_arguments.h"
#include "mesh/gltf_loader.h"
#include "util/arg_parser.h"

namespace grass::cli {

int runMeshInfo(const std::vector<std::string>& args) {
    std::string file;
    bool json = false;
    ArgParser parser("grass mesh-info <file.gltf|file.glb> [--json]",
                     "Loads a glTF 2.0 file as grass sees it (every triangle primitive of every "
                     "mesh in the scene, node transforms applied) and prints its vertex and "
                     "triangle counts, surface area (in the file's units, squared), whether it "
                     "carried normals and UV0, and its bounds.");
    parser.positional("file", "a .gltf or .glb file", &file, true);
    parser.flag("--json", "print one JSON object instead of text", &json);
    if (const auto exitCode = parseArguments(parser, args, "mesh-info"))
        return *exitCode;
    auto imported = core::loadGltf(file);
    if (!imported)
        return reportFailure("mesh-info", imported.error(), EXIT_FAILED);
    const core::SurfaceMesh& mesh = imported->mesh;
    const core::Bounds bounds = core::meshBounds(mesh);
    const double area = core::surfaceArea(mesh);
    printNotes(imported->notes);
    if (json) {
        nlohmann::ordered_json out;
        out["vertices"] = mesh.n_vertices();
        out["triangles"] = mesh.n_faces();
        out["area"] = area;
        out["has_normals"] = imported->hasNormals;
        out["has_uv"] = imported->hasUv;
        out["bounds"] = {{bounds.min.x, bounds.min.y, bounds.min.z},
                         {bounds.max.x, bounds.max.y, bounds.max.z}};
        std::printf("%s\n", out.dump().c_str());
        return 0;
    }
    std::printf(
        "%s\n  vertices   %zu\n  triangles  %zu\n  area       %.6g\n  normals    %s\n"
        "  uv0        %s\n  bounds     [%g %g %g] .. [%g %g %g]\n",
        file.c_str(), mesh.n_vertices(), mesh.n_faces(), area,
        imported->hasNormals ? "from file" : "computed (area-weighted)",
        imported->hasUv ? "from file" : "generated (planar)", bounds.min.x, bounds.min.y,
        bounds.min.z, bounds.max.x, bounds.max.y, bounds.max.z);
    return 0;
}

}  // namespace grass::cli
