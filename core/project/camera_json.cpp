// A "cameras" entry of project.json: a named view the editor and `grass render` start from.
#include <array>

#include "project/project_json_parts.h"

namespace grass::core {

namespace {

using settings::field;

// A field of view of 0 or 180 degrees has no perspective projection.
constexpr json::NumberRule FOV_RULE{0.0, 180.0, true, true};

constexpr std::array CAMERA{
    field<&CameraDesc::name>({.key = "name", .help = "unique among cameras"}),
    field<&CameraDesc::position>({.key = "position"}),
    field<&CameraDesc::target>({.key = "target", .help = "not equal to `position`"}),
    field<&CameraDesc::fovYDeg>(
        {.key = "fov_y_deg", .rule = FOV_RULE, .unit = "°", .help = "vertical field of view"}),
};

}  // namespace

std::span<const settings::Setting<CameraDesc>> settings::camera() { return CAMERA; }

void json::checkCamera(Reader& reader, const Object& object, const CameraDesc& camera) {
    if (camera.position == camera.target)
        reader.fail(object.pointerTo("target"), "must differ from position (got the same point)");
}

}  // namespace grass::core
