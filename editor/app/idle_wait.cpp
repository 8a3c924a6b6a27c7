#include "app/idle_wait.h"

#include <algorithm>

namespace grass::editor {

double idleWaitS(const RestingFrame& frame) {
    double waitS = frame.progressShown ? PROGRESS_IDLE_WAIT_S : LONGEST_IDLE_WAIT_S;
    if (frame.playing)
        waitS = std::min(waitS, PLAYING_IDLE_WAIT_S);
    for (const std::optional<double>& change :
         {frame.panelsChangeInS, frame.fullPictureInS, frame.autosaveInS, frame.statusUpdateInS})
        if (change)
            waitS = std::min(waitS, *change);
    return std::max(waitS, 0.0);
}

}  // namespace grass::editor
