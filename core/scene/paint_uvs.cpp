#include "scene/paint_uvs.h"

#include <algorithm>

#include "mesh/mesh_parts.h"
#include "mesh/uv_atlas_file.h"

namespace grass::core {

namespace {

// `mesh` with UV0 = `corners`, keeping its per-face part table (withCornerUvs keeps face order).
void adoptCornerUvs(SurfaceMesh& mesh, const CornerUvs& corners) {
    SurfaceMesh next = withCornerUvs(mesh, corners);
    if (const MeshParts* parts = meshPartsOf(mesh))
        setMeshParts(next, *parts);
    mesh = std::move(next);
}

std::string overlapText(const UvOverlapReport& report) {
    std::string text;
    const auto add = [&](std::size_t count, const char* what) {
        if (count > 0)
            text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + what;
    };
    add(report.overlappingPairs, "overlapping face pairs");
    add(report.degenerateFaces, "faces without UV area");
    add(report.outsideUnitSquare, "faces outside [0, 1]²");
    return text;
}

}  // namespace

PaintUvs makeUvsPaintable(SurfaceMesh& mesh, bool hasUv, const std::function<bool()>& textured,
                          const std::filesystem::path& atlasFile, int mapResolution,
                          std::vector<std::string>& notes, const std::stop_token& stop) {
    PaintUvs result;
    const UvOverlapReport report = findUvOverlaps(cornerUvsOf(mesh), mesh, stop);
    if ((hasUv && report.paintable()) || stop.stop_requested())
        return result;
    if (textured()) {
        notes.push_back("UVs are not paintable (" + overlapText(report) +
                        "): a stroke may paint more than one place; kept, since the surface's "
                        "texture needs them");
        return result;
    }
    if (!atlasFile.empty()) {
        auto kept = loadUvAtlas(atlasFile, mesh);
        if (kept) {
            adoptCornerUvs(mesh, *kept);
            result.fromFile = true;
            return result;
        }
        notes.push_back(kept.error().str() + "; a new atlas is made (maps painted on the old "
                                             "one no longer line up)");
    }
    AtlasStats stats;
    AtlasParams params;
    // Two texels of gutter at the coarsest map, and never coarser than 64 texels a side.
    params.resolution = std::clamp(mapResolution, 64, 4096);
    params.gutterTexels = 2;
    result.corners = generateUvAtlas(mesh, params, &stats);
    result.fingerprint = meshFingerprint(mesh);
    result.generated = true;
    adoptCornerUvs(mesh, result.corners);
    notes.push_back("UVs for painting generated (" +
                    (hasUv ? overlapText(report) : std::string("the file has none")) + "): " +
                    std::to_string(stats.charts) + " charts; a save keeps them in the project");
    return result;
}

Result<bool> keepGeneratedUvs(Project& project, const std::filesystem::path& folder, PaintUvs& uvs) {
    MeshSource& mesh = project.mesh;
    if (!uvs.generated || !mesh.isFile)
        return false;
    const std::string relative =
        std::filesystem::path(mesh.file).replace_extension(".uvatlas").generic_string();
    auto target = resolveAssetPath(folder, relative, "/mesh/uv_atlas");
    if (!target)
        return target.error();
    if (auto saved = saveUvAtlas(*target, uvs.corners, uvs.fingerprint); !saved)
        return saved.error();
    uvs.generated = false;
    uvs.fromFile = true;
    const bool changed = mesh.uvAtlas != relative;
    mesh.uvAtlas = relative;
    return changed;
}

}  // namespace grass::core
