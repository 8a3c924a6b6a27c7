#include "app/session_stats.h"

#include <algorithm>
#include <cstdio>

namespace grass::editor {

void SessionStats::frameEnded(const std::string& phase, double frameMs, double skippedS) {
    mFrames.push_back({phase, frameMs, skippedS});
}

void SessionStats::fullQualityAfter(double seconds) {
    mFullQualityS.push_back(seconds);
}

std::string SessionStats::summary() const {
    std::vector<std::string> phases;
    for (const Frame& f : mFrames)
        if (std::find(phases.begin(), phases.end(), f.phase) == phases.end())
            phases.push_back(f.phase);
    std::string text;
    char line[256];
    for (const std::string& phase : phases) {
        std::vector<double> ms;
        double wallS = 0.0, skippedS = 0.0;
        for (const Frame& f : mFrames)
            if (f.phase == phase) {
                ms.push_back(f.ms);
                wallS += f.ms / 1000.0;
                skippedS += f.skippedS;
            }
        std::sort(ms.begin(), ms.end());
        const auto at = [&](double q) {
            return ms[std::min(ms.size() - 1, std::size_t(q * double(ms.size())))];
        };
        const double realTime = wallS > 0.0 ? std::max(0.0, 1.0 - skippedS / wallS) : 1.0;
        std::snprintf(line, sizeof line,
                      "frames %s: %zu, median %.1f ms, 95th percentile %.1f ms, slowest %.1f ms, "
                      "real time %.2f\n",
                      phase.empty() ? "-" : phase.c_str(), ms.size(), at(0.5), at(0.95),
                      ms.back(), realTime);
        text += line;
    }
    if (!mFullQualityS.empty()) {
        std::snprintf(line, sizeof line,
                      "full quality after input stops: %.2f s (slowest of %zu)\n",
                      *std::max_element(mFullQualityS.begin(), mFullQualityS.end()),
                      mFullQualityS.size());
        text += line;
    }
    return text;
}

}  // namespace grass::editor
