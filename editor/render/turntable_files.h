// Turntable files, for `grass render --turntable N` and the editor's File menu: renders the turn
// (turntable_render.h) and writes each view to <out stem>_0000.png ... and a contact sheet of the turn to <out stem>_sheet.png
// (the extension follows --out), with a progress line per view on stderr.
#pragma once

#include <filesystem>
#include <stop_token>

#include "render/offscreen_render.h"

namespace grass::render {

struct TurntableRun {
    int framesWritten = 0;
    std::filesystem::path firstFrame, lastFrame, sheet;
    double meanWallMs = 0.0;    // per view: draw, glFinish (not the read-back or the file)
    double totalMs = 0.0;       // the whole turn: renderer set-up, views, files, sheet
    FrameTimings last;  // GPU timings of the last view
    double lastWallMs = 0.0;
    bool stopped = false;  // ended early by the stop token: framesWritten views, and their sheet
};

// Each file is written atomically (temporary file, then rename) as soon as its view is drawn,
// so an interrupted turn leaves whole images of the views done, never a half-written one; the
// sheet is written last. Prints where the files went and the time per view on stdout. A stop
// requested (Ctrl+C) ends the turn after the view under way: the sheet holds the views done.
Result<TurntableRun> writeTurntable(const core::Scene& scene, const core::OrbitCamera& start,
                                    const OffscreenRequest& request, int frameCount,
                                    const std::filesystem::path& out, std::stop_token stop = {});

}  // namespace grass::render
