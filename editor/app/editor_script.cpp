// The editor replaying a --script: its steps (a `wait-s` step holds on the wall clock) and, on
// wall-clock time, the session's summary at the end (editor/app/session_stats.h).
#include <cstdio>

#include "app/editor.h"

namespace grass::editor {

std::optional<ScriptFrame> Editor::nextScriptStep(Clock::time_point now) {
    if (mScriptStep >= mScript.size())
        return std::nullopt;
    const ScriptFrame& step = mScript[mScriptStep];
    if (step.holdS > 0.0) {
        if (!mHoldStart)
            mHoldStart = now;
        if (std::chrono::duration<double>(now - *mHoldStart).count() < step.holdS)
            return step;  // held: the same idle input again
        mHoldStart.reset();
    }
    ++mScriptStep;
    return step;
}

bool Editor::finishScript(Clock::time_point lastFrame) {
    if (!mReplay) {
        // From the editor's start to the last frame that moved time.
        const double wallS = std::chrono::duration<double>(lastFrame - mStartTime).count();
        std::printf("wall clock %.2f s, %d frames, timeline moved %.2f s, physics skipped %.2f s\n",
                    wallS, mFrame, mState.view.timeline.timeS() - mTimelineStartS,
                    mLive.physics ? mLive.physics->droppedS : 0.0);
        std::fputs(mStats.summary().c_str(), stdout);
    }
    // How many frames drew the viewport's picture rather than showing the last one again
    // (app/view_redraw.h).
    std::printf("viewport drawn in %d of %d frames\n", mViewsDrawn, mFrame);
    if (mMinimisedFrames > 0)
        std::printf("minimised for %d frames, nothing drawn\n", mMinimisedFrames);
    // Whether the status bar's stage timings are those of the picture shown.
    std::printf("status timings of frame %d, last full picture drawn in frame %d\n", mTimingsFrame,
                mLastFullPictureFrame);
    // The status bar's blade counts, and whether the picture shown was reduced.
    const FrameStatus& status = mState.transient.status;
    std::printf("status bar: %zu blades, %zu drawn, picture %s\n", status.blades,
                status.timings.cull.drawn, status.reduced.empty() ? "full" : "reduced");
    return false;
}

}  // namespace grass::editor
