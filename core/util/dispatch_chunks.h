// Compute dispatches over more items than one call may launch: GL guarantees at least 65535 work
// groups per dimension (a 10M-blade layer in groups of 32 needs 312,500), so a pass over a long
// buffer is cut into calls, each told where it starts. GL-free and header-only, for the editor's
// passes and the reference runtime alike.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace grass::core {

inline constexpr std::size_t MAX_DISPATCH_GROUPS = 65535;

// Calls dispatch(first, groups) once per chunk: `first` the chunk's first item, `groups` the
// work groups of `groupSize` items it needs (the last may be partly past `items`).
template <class Dispatch>
void forEachDispatchChunk(std::size_t items, std::size_t groupSize, Dispatch&& dispatch) {
    const std::size_t chunk = groupSize * MAX_DISPATCH_GROUPS;
    for (std::size_t first = 0; first < items; first += chunk) {
        const std::size_t count = std::min(items - first, chunk);
        dispatch(first, static_cast<std::uint32_t>((count + groupSize - 1) / groupSize));
    }
}

}  // namespace grass::core
