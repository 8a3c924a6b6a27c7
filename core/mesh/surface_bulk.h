// Where most of a surface is: the box holding all but the outermost few percent of its area.
// A third-party terrain often carries small far-off parts (a cloud, a skybox fragment, a stray
// triangle at the origin); framing the whole bounds would show them and a speck of field, so
// the first camera frames this box instead (issue 26 item 2).
#pragma once

#include "mesh/surface_mesh.h"

namespace grass::core {

// Per axis, the area-weighted quantiles `outside`/2 and 1 − `outside`/2 of the triangles'
// corners (a third of each triangle's area at each corner), widened by the mean triangle size so
// a box of one flat layer keeps its thickness;
// clamped to meshBounds. An empty mesh gives meshBounds.
Bounds surfaceBulkBounds(const SurfaceMesh& mesh, double outside = 0.04);

}  // namespace grass::core
