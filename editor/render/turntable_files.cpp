#include "render/turntable_files.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "scene/turntable.h"
#include "render/turntable_render.h"
#include "util/contact_sheet.h"
#include "util/image_file.h"

namespace grass::render {

Result<TurntableRun> writeTurntable(const core::Scene& scene, const core::OrbitCamera& start,
                                    const OffscreenRequest& request, int frameCount,
                                    const std::filesystem::path& out, std::stop_token stop) {
    const auto begin = std::chrono::steady_clock::now();
    const ContactSheetLayout layout = contactSheetLayout(frameCount, request.width, request.height);
    Rgba8Pixels sheet = blankContactSheet(layout);
    TurntableRun run;
    double wallSumMs = 0.0;
    auto sink = [&](int frame, const gl::Rgba8Image& image, const FrameTimings& timings,
                    double wallMs) -> Result<void> {
        const std::filesystem::path file = core::turntableFramePath(out, frame, frameCount);
        if (auto written = writeRgba8Image(file, image.width, image.height, image.pixels); !written)
            return written.error();
        if (const int cell = layout.cellOf(frame); cell >= 0)
            placeInContactSheet(sheet, layout, cell,
                                Rgba8Pixels{image.width, image.height, image.pixels});
        const double yawDeg = 360.0 * frame / frameCount;
        std::fprintf(stderr, "render: turntable frame %d/%d (%+.1f°) -> %s\n", frame + 1,
                     frameCount, yawDeg, file.string().c_str());
        if (frame == 0)
            run.firstFrame = file;
        run.lastFrame = file;
        run.framesWritten = frame + 1;
        run.last = timings;
        run.lastWallMs = wallMs;
        wallSumMs += wallMs;
        // Ends the turn here (an error the caller below takes as the stop).
        if (stop.stop_requested() && frame + 1 < frameCount) {
            run.stopped = true;
            return makeError(out.string(), "stopped");
        }
        return {};
    };
    if (auto turned = renderTurntable(scene, start, request, frameCount, sink);
        !turned && !run.stopped)
        return turned.error();
    if (run.stopped)
        std::fprintf(stderr, "render: stopped after %d of %d views: the sheet holds those\n",
                     run.framesWritten, frameCount);
    run.sheet = core::turntableSheetPath(out);
    if (auto written = writeRgba8Image(run.sheet, sheet.width, sheet.height, sheet.pixels);
        !written)
        return written.error();
    run.meanWallMs = wallSumMs / std::max(run.framesWritten, 1);
    run.totalMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
    std::printf("wrote %d frames %s .. %s (%dx%d)\n", run.framesWritten,
                run.firstFrame.string().c_str(), run.lastFrame.string().c_str(), request.width,
                request.height);
    // A stopped turn's sheet keeps its layout, the cells of the views not drawn left blank.
    int onSheet = 0;
    for (int frame = 0; frame < run.framesWritten; ++frame)
        onSheet += layout.cellOf(frame) >= 0 ? 1 : 0;
    std::printf("wrote %s (%dx%d, %d of %d frames in %d column(s))\n", run.sheet.string().c_str(),
                sheet.width, sheet.height, onSheet, frameCount, layout.columns);
    std::printf("  turntable  %.1f ms per view (draw), %.1f ms in all (views, files, sheet)\n",
                run.meanWallMs, run.totalMs);
    return run;
}

}  // namespace grass::render
