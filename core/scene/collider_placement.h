// The field after its colliders moved, where a layer's placement rules clear the ground under
// them (PlacementRules::clearColliders): blades come back where a collider left and go where it
// now stands. Before, the editor grew the whole field again for it once a drag ended, and every
// blade restarted from rest; now only the patches whose candidates' rule factors (or, through
// their neighbours' shade, bends) changed grow again, and the result is the field a fresh build
// with the colliders where they now stand grows, bit for bit (CollidersPlacement.*).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "project/project.h"
#include "scene/scene.h"
#include "util/result.h"

namespace grass::core {

// `scene`'s props already stand where `project`'s colliders do (the editor's followMotion placed
// them). Every layer whose rules clear the colliders takes the rule factors and bends of the
// colliders there, and the patches holding a candidate whose factor or bend changed grow again
// (regrowLayerRegion: the shading around blades gained or lost re-baked exactly); the
// billboards' placement follows the new factors too. Returns the layers that changed, each with
// the patches to upload.
Result<std::vector<std::pair<std::size_t, RegrowReport>>> followColliderPlacement(
    Scene& scene, const Project& project);

}  // namespace grass::core
