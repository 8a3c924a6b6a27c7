#include "physics/path_loop.h"

#include <algorithm>
#include <cmath>

#include "util/assert.h"

namespace grass::core {

float pingPongPeriodS(const std::vector<PathKey>& path) {
    if (path.size() < 2)
        return 0.0f;
    const float spanS = path.back().timeS - path.front().timeS;
    return spanS > 0.0f && std::isfinite(spanS) ? 2.0f * spanS : 0.0f;
}

std::vector<PathKey> pingPongWindow(const std::vector<PathKey>& path, float fromS, float untilS) {
    GRASS_ASSERT(fromS <= untilS);
    const float periodS = pingPongPeriodS(path);
    if (periodS == 0.0f)
        return path;
    // In double: cycle starts an hour in must not round to a neighbouring key's time.
    const double firstS = path.front().timeS, lastS = path.back().timeS;
    const double period = periodS;
    const double firstCycle = std::max(0.0, std::floor((double(fromS) - firstS) / period));
    const double lastCycle = std::max(firstCycle, std::floor((double(untilS) - firstS) / period));
    std::vector<PathKey> keys;
    keys.reserve(static_cast<std::size_t>(lastCycle - firstCycle + 1.0) * 2 * path.size());
    for (double cycle = firstCycle; cycle <= lastCycle; cycle += 1.0) {
        const double startS = firstS + cycle * period;
        // Forth: every key (the first is the previous cycle's last key, so skip it after cycle 1).
        for (std::size_t i = keys.empty() ? 0 : 1; i < path.size(); ++i)
            keys.push_back(
                {static_cast<float>(startS + (path[i].timeS - firstS)), path[i].posWorld});
        // Back: the keys in reverse, mirrored about the last key's time.
        for (std::size_t i = path.size() - 1; i-- > 0;)
            keys.push_back({static_cast<float>(startS + (lastS - firstS) + (lastS - path[i].timeS)),
                            path[i].posWorld});
    }
    return keys;
}

PathLooper::PathLooper(const std::vector<WindSource>& wind,
                       const std::vector<SphereCollider>& colliders) {
    const auto keep = [this](const std::vector<PathKey>& path) {
        const float periodS = pingPongPeriodS(path);
        if (periodS > 0.0f)
            ++mLooping;
        mLongestPeriodS = std::max(mLongestPeriodS, periodS);
        return path;
    };
    for (const WindSource& source : wind)
        mWindPaths.push_back(keep(source.path));
    for (const SphereCollider& sphere : colliders)
        mColliderPaths.push_back(keep(sphere.path));
}

bool PathLooper::update(std::vector<WindSource>& wind, std::vector<SphereCollider>& colliders,
                        float timeS, float dtS) {
    GRASS_ASSERT(wind.size() == mWindPaths.size() && colliders.size() == mColliderPaths.size());
    if (mLooping == 0 || timeS + dtS <= mWindowEndS)
        return false;
    const float untilS = timeS + std::max(WINDOW_S, dtS);
    for (std::size_t i = 0; i < wind.size(); ++i)
        wind[i].path = pingPongWindow(mWindPaths[i], timeS, untilS);
    for (std::size_t i = 0; i < colliders.size(); ++i)
        colliders[i].path = pingPongWindow(mColliderPaths[i], timeS, untilS);
    mWindowEndS = untilS;
    return true;
}

}  // namespace grass::core
