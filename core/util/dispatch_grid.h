// Compute dispatches over more items than one row of work groups may hold: GL guarantees at
// least 65535 work groups per dimension (a 10M-blade layer in groups of 32 needs 312,500), so a
// pass over a long buffer runs as one two-dimensional grid of groups. One call, not a call per
// 65535 groups: on a GPU the calls ran one after the other, so a slow group in one of them (the
// blades under a collider walking its spheres, docs/physics.md) held up every call after it,
// while in one grid the rest of the field runs beside it. GL-free and header-only, for the
// editor's passes and the reference runtime alike; shaders/include/dispatch_grid.glsl turns a
// group of the grid back into its place in the pass.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "util/assert.h"

namespace grass::core {

inline constexpr std::size_t MAX_DISPATCH_GROUPS = 65535;

// A grid row holds at most this many groups, so that the second dimension is in use from 8,192
// blades on (groups of 32): every GL test with a field that size runs the path a 10M-blade
// field takes. The order of the groups is the same whatever the row length.
inline constexpr std::size_t DISPATCH_ROW_GROUPS = 256;

struct DispatchGrid {
    std::uint32_t x = 0;  // groups a row
    std::uint32_t y = 0;  // rows
};

// The grid of groups of `groupSize` items over `items`: group y·x + x' covers items
// [(y·x + x')·groupSize, +groupSize); the last groups may lie partly or wholly past `items`
// (fewer than y of them). {0, 0} for no items: nothing to dispatch.
inline DispatchGrid dispatchGrid(std::size_t items, std::size_t groupSize) {
    const std::size_t groups = (items + groupSize - 1) / groupSize;
    if (groups == 0)
        return {};
    const std::size_t rows = (groups + DISPATCH_ROW_GROUPS - 1) / DISPATCH_ROW_GROUPS;
    GRASS_ASSERT(rows <= MAX_DISPATCH_GROUPS);
    const std::size_t perRow = (groups + rows - 1) / rows;
    return {static_cast<std::uint32_t>(perRow), static_cast<std::uint32_t>(rows)};
}

}  // namespace grass::core
