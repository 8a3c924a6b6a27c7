// Paths that keep moving (issue 11, `grass soak`): a project's wind and collider paths are held at
// both ends (docs/project-format.md), so an hour of simulation would leave them still after their
// last key. pingPongWindow goes over a path forth and back, forever, by returning the keys of the
// cycles that cover a span of time; a driver swaps them in before stepping past the window.
// Times in seconds of simulation, positions in world space.
#pragma once

#include <vector>

#include "physics/physics.h"
#include "physics/wind.h"

namespace grass::core {

// The period of the forth-and-back loop: twice the time from the first key to the last; 0 for a
// path that does not move (fewer than two keys or no time between its ends).
float pingPongPeriodS(const std::vector<PathKey>& path);

// Keys (sorted by time) that samplePath reads, on [fromS, untilS], as the path driven forth from
// its first key to its last, back to its first, and again: the whole cycles that cover the span.
// Before the first key's time the path is held there, as samplePath holds it. A path with a zero
// period comes back unchanged. Precondition: keys sorted by time, fromS <= untilS.
std::vector<PathKey> pingPongWindow(const std::vector<PathKey>& path, float fromS, float untilS);

// Keeps every wind source and collider of a scene on its ping-pong loop: holds the project's own
// paths and, before each step, swaps in the windows of the next WINDOW_S seconds once the current
// ones end within the step (so sampling anywhere inside a step, substeps included, is covered).
class PathLooper {
public:
    // Seconds of simulation each window covers: a few cycles of a short path, and the window
    // keys of a packed mesh (one path per sphere) stay small.
    static constexpr float WINDOW_S = 64.0f;

    PathLooper(const std::vector<WindSource>& wind, const std::vector<SphereCollider>& colliders);

    // Before a step of dtS from timeS; true when it replaced the paths. wind and colliders are
    // the ones the constructor saw (same sizes and order).
    bool update(std::vector<WindSource>& wind, std::vector<SphereCollider>& colliders, float timeS,
                float dtS);
    // Paths that loop (a period > 0), and the longest period.
    std::size_t loopingPaths() const { return mLooping; }
    float longestPeriodS() const { return mLongestPeriodS; }

private:
    std::vector<std::vector<PathKey>> mWindPaths, mColliderPaths;
    std::size_t mLooping = 0;
    float mLongestPeriodS = 0.0f;
    float mWindowEndS = -1.0f;  // before any update: every step swaps in a window
};

}  // namespace grass::core
