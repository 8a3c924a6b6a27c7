// The far field follows the near field (issue 30 item 3): the star billboards of SPEC §8 stand
// for the blades the layers grow, so where the layers grow none (a painted-out path, a rule that
// clears a rock) there are no billboards, where growth colours the blades poor the billboards
// are tinted so, where it grows them short the tufts are short, and the wind bends the tufts as
// it bends blades of the layers' stiffness (billboard/billboard_motion.h).
//
// For an object at UV u, layer i keeps the share p_i = density_i(u) · rule_i of its blades (its
// density map times its placement rules there, as keepsCandidate thins a scattered blade); with
// w_i the layer's candidate count, the near field keeps F = Σ w_i·p_i / Σ w_i of its blades
// there, and the object lives where its keep < F. A living object's height is scaled by the
// kept blades' mean growth height scale (1 without growth), and its tint takes the texture's
// mean colour to the kept blades' mean visible colour: a distant field shows its blades' upper
// halves, root + 0.75·(tip − root) on average, of the healthy or (by the growth model's wilt)
// poor colours. Without the tint a generated texture of the same colours drew the far field of
// projects/helicopter at 0.62× the brightness of its blades (docs/rendering.md).
#pragma once

#include <vector>

#include "billboard/star_billboards.h"
#include "mesh/surface_mesh.h"
#include "project/project.h"
#include "scatter/placement_rules.h"
#include "scene/layer_growth.h"

namespace grass::core {

struct LayerField;

// What does not change when a map is repainted, computed once per scene.
struct BillboardFollow {
    // [layer][object] the layer's placement rules at each placed object; empty: 1 everywhere.
    std::vector<std::vector<float>> ruleFactors;
    std::vector<double> layerWeights;  // w_i: the layer's blade candidates
    float stiffness = 0.0f;            // the mean stiffness s of every layer's candidates
    glm::vec3 textureColour{1.0f};     // meanGrassColour of the billboards' texture
};

BillboardFollow billboardFollow(const std::vector<GrassObject>& placed,
                                const std::vector<LayerField>& layers,
                                const std::vector<PlacementRules>& rules, const SurfaceMesh& mesh,
                                const RuleWorld& world, glm::vec3 textureColour);

// The placed objects the layers keep, with their height (and width) scaled and their tint set;
// cluster numbers and order as placed. Without layers every object lives, untinted.
// The colour a far view of a layer's blades shows, healthy (wilt 0) to poor (wilt 1).
glm::vec3 visibleBladeColour(const LayerField& layer, float wilt);

std::vector<GrassObject> followLayers(const std::vector<GrassObject>& placed,
                                      const BillboardFollow& follow,
                                      const std::vector<LayerField>& layers);

}  // namespace grass::core
