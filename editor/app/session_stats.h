// What a `--wall-clock` script session measured (issue 24): every frame's wall time by script
// phase, the simulated time the physics skipped in it, and how long the full picture took to
// come back after input stopped. Printed at the end of the session; `grass bench`'s editor case
// reads those lines (cli/bench_editor.cpp), so their format is kept.
#pragma once

#include <string>
#include <vector>

namespace grass::editor {

class SessionStats {
public:
    // A frame of `phase` took `frameMs` of wall time, in which the physics skipped `skippedS`.
    void frameEnded(const std::string& phase, double frameMs, double skippedS);
    // Input stopped and the next full-quality frame was done `seconds` later.
    void fullQualityAfter(double seconds);
    // One line per phase, in the order they began:
    //   frames PHASE: N, median X ms, 95th percentile Y ms, slowest Z ms, real time F
    // (F: the share of the phase's wall time the physics simulated rather than skipped), then
    //   full quality after input stops: S s (slowest of N)
    std::string summary() const;

private:
    struct Frame {
        std::string phase;
        double ms = 0.0;
        double skippedS = 0.0;
    };
    std::vector<Frame> mFrames;
    std::vector<double> mFullQualityS;
};

}  // namespace grass::editor
