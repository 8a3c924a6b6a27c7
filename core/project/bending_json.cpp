// A layer's "bending" object in project.json: the bending cues of SPEC §10 (BendingCues,
// core/scene/bending_cues.h).
#include <array>

#include "project/project_json_parts.h"

namespace grass::core {

namespace {

using settings::field;

// The growth model's rest lean stops at 60° (growth_curves.h); the cues share that bound.
constexpr json::NumberRule LEAN_DEGREES{0.0, 60.0};

constexpr std::array BENDING{
    field<&BendingCues::slope>(
        {.key = "slope",
         .rule = json::UNIT_INTERVAL,
         .help = "rest lean downhill as a share of the ground's slope against gravity (0.5: "
                 "blades on a 40° slope lean 20°); 0: off",
         .label = "lean on slopes",
         .ui = {.min = 0.0f, .max = 1.0f, .decimals = 2, .speed = 0.01f, .slider = true}}),
    field<&BendingCues::neighboursDeg>(
        {.key = "neighbours",
         .rule = LEAN_DEGREES,
         .unit = "°",
         .help = "rest lean of a blade fully shaded by taller, denser neighbours (it grows "
                 "sideways, towards the light); 0: off",
         .label = "lean in shade",
         .ui = {.min = 0.0f, .max = 60.0f, .decimals = 1, .speed = 0.5f, .slider = true}}),
    field<&BendingCues::neighbourRadiusM>(
        {.key = "neighbour_radius",
         .rule = {MIN_BENDING_RADIUS_M, MAX_BENDING_RADIUS_M},
         .unit = "m",
         .help = "Gaussian σ over which neighbours shade a blade",
         .ui = {.min = 0.01f, .max = 2.0f, .decimals = 2, .speed = 0.01f}}),
    field<&BendingCues::sway>(
        {.key = "sway",
         .rule = json::UNIT_INTERVAL,
         .help = "how much more a leaning blade sways: its stiffness becomes s·(1 − sway·sin "
                 "lean)",
         .label = "sway when leaning",
         .ui = {.min = 0.0f, .max = 1.0f, .decimals = 2, .speed = 0.01f, .slider = true}}),
};

}  // namespace

std::span<const settings::Setting<BendingCues>> settings::bending() { return BENDING; }

}  // namespace grass::core
