// Turntable renders (`grass render --turntable N`): N views orbiting 360° about the vertical
// axis through the camera's target, for artists to share a field from every side. Angles in
// radians, about +Y (the OrbitCamera convention); pitch, distance, target and lens stay those
// of the start camera, so frame 0 is the plain render.
#pragma once

#include <filesystem>

#include "scene/camera.h"

namespace grass::core {

// The fewest and most views `--turntable` accepts: one view is not a turn, and 3600 (a tenth
// of a degree per view) is far beyond what anyone shares.
inline constexpr int TURNTABLE_MIN_FRAMES = 2;
inline constexpr int TURNTABLE_MAX_FRAMES = 3600;

// View `frame` of `frameCount`: yaw = start yaw + 2π·frame/frameCount, all else unchanged.
// Precondition: frameCount ≥ 1 and 0 ≤ frame < frameCount.
OrbitCamera turntableCamera(const OrbitCamera& start, int frame, int frameCount);

// "dir/meadow.png" → "dir/meadow_0007.png": the stem, "_", the frame number zero padded to at
// least 4 digits (more when frameCount − 1 needs them), and the extension of `out`, so the
// files sort in turning order.
std::filesystem::path turntableFramePath(const std::filesystem::path& out, int frame,
                                         int frameCount);

// "dir/meadow.png" → "dir/meadow_sheet.png": the contact sheet of the turn.
std::filesystem::path turntableSheetPath(const std::filesystem::path& out);

}  // namespace grass::core
