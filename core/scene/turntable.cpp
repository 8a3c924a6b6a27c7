#include "scene/turntable.h"

#include <algorithm>
#include <string>

#include "util/assert.h"

namespace grass::core {

OrbitCamera turntableCamera(const OrbitCamera& start, int frame, int frameCount) {
    GRASS_ASSERT(frameCount >= 1 && frame >= 0 && frame < frameCount);
    // The step is computed in double and added once (not accumulated frame by frame), so the
    // last view lands exactly one step short of the first, without drift.
    constexpr double TWO_PI = 6.283185307179586476925;
    const double stepRad = TWO_PI * static_cast<double>(frame) / static_cast<double>(frameCount);
    OrbitCamera camera = start;
    camera.yawRad = static_cast<float>(static_cast<double>(start.yawRad) + stepRad);
    return camera;
}

std::filesystem::path turntableFramePath(const std::filesystem::path& out, int frame,
                                         int frameCount) {
    GRASS_ASSERT(frameCount >= 1 && frame >= 0 && frame < frameCount);
    const std::size_t width = std::max<std::size_t>(4, std::to_string(frameCount - 1).size());
    std::string number = std::to_string(frame);
    number.insert(0, width - number.size(), '0');
    std::filesystem::path file = out;
    file.replace_filename(out.stem().string() + "_" + number + out.extension().string());
    return file;
}

std::filesystem::path turntableSheetPath(const std::filesystem::path& out) {
    std::filesystem::path file = out;
    file.replace_filename(out.stem().string() + "_sheet" + out.extension().string());
    return file;
}

}  // namespace grass::core
