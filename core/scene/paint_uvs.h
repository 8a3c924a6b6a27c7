// The UVs a surface's grass maps are painted in (issue 27 item 3). A map is painted in UV0, so
// UVs that are missing (a planar projection is generated) or overlap would let a stroke on one
// surface paint another: such a surface gets a generated non-overlapping atlas
// (core/mesh/uv_atlas.h), kept in the project (mesh "uv_atlas") so its maps stay where they
// were each time it opens. A textured surface keeps its own UVs even when they overlap: its
// texture needs them (noted).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <stop_token>
#include <string>
#include <vector>

#include "mesh/surface_mesh.h"
#include "mesh/uv_atlas.h"
#include "project/project.h"
#include "util/result.h"

namespace grass::core {

struct PaintUvs {
    bool generated = false;  // UV0 is an atlas made now: a save should keep it (corners)
    bool fromFile = false;   // UV0 is the project's kept atlas
    CornerUvs corners;       // when generated
    std::uint64_t fingerprint = 0;
};

// Makes `mesh`'s UV0 paintable (`mesh` as its file holds it, before its frame is applied, so a
// change of unit or up axis keeps its atlas). `hasUv`: every primitive had TEXCOORD_0;
// `textured`: whether the surface draws a texture through its UVs, asked only when they are not
// paintable (it decodes the surface's material); `atlasFile`: the project's kept
// atlas (empty: none); `mapResolution`: the coarsest map side painted in it, which the atlas
// keeps its gutters for (a brush's texels reach one texel past a chart, a bilinear read one
// more). Notes say what was done and why. A request on `stop` ends the check of the UVs early
// and leaves them as they are (the caller checks the token: the result means nothing then).
PaintUvs makeUvsPaintable(SurfaceMesh& mesh, bool hasUv, const std::function<bool()>& textured,
                          const std::filesystem::path& atlasFile, int mapResolution,
                          std::vector<std::string>& notes, const std::stop_token& stop = {});

// What a save of maps painted in a generated atlas must do: write it next to the project's mesh
// file (terrain.glb → terrain.uvatlas, atomically) and name it in project.mesh.uvAtlas; `uvs`
// then counts as read from the file. Nothing when `uvs` was not generated. Returns whether the
// project changed; errors name the file.
Result<bool> keepGeneratedUvs(Project& project, const std::filesystem::path& folder, PaintUvs& uvs);

}  // namespace grass::core
