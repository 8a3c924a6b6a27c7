// Edits that move what moves a grown field — its wind sources, its colliders — without changing
// the field itself. The editor's live physics and the colliders' props follow such an edit at
// once, frame by frame during a gizmo drag, and the field keeps its blades, their motion and
// their trails; before, every such edit re-grew the whole field once it ended, and its blades
// started again from rest (app/live_scene.h, followMotion).
#pragma once

#include "project/project.h"

namespace grass::core {

// Whether `after` differs from `before` at most in its wind sources, its colliders (any
// change: added, deleted, moved, another mesh or packing) and how the physics steps (the step,
// the substeps and their limits, η's decay, the front gravity, the crushed floor: what a quality
// preset changes). The grown field is then the same, unless a layer clears the ground under the
// colliders (placementFollowsColliders) and they changed. The gravity is the field's: blades
// grow leaning under it.
bool onlyMotionChanged(const Project& before, const Project& after);

// Whether two collider lists hold the same props: as many colliders, each of the same shape,
// mesh file and packing (they may stand elsewhere, at another size, on another path, in
// another colour, under another name). Then the props only move; else they are made again.
bool sameProps(const std::vector<ColliderDesc>& before, const std::vector<ColliderDesc>& after);

// Whether where a layer's blades (and the billboards that follow its rules) grow depends on the
// colliders: a layer whose placement rules clear the ground under them.
bool placementFollowsColliders(const Project& project);

}  // namespace grass::core
