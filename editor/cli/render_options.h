// The command line of `grass render`: its options, what the command line alone can refute, and
// the offscreen request (size, samples, render options) they ask of the loaded project.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gl/debug_output.h"
#include "project/project.h"
#include "render/offscreen_render.h"
#include "util/result.h"

namespace grass::cli {

struct RenderArgs {
    std::string project, mesh, out, camera, geometry = "project", msaa = "project";
    // With --mesh: the file's unit and up axis (core/mesh/mesh_frame.h).
    std::string unit = "m", up = "+Y";
    // "auto" becomes "cpu" on software GL and "gpu" elsewhere once the context is up.
    std::string backend = "auto", shape = "project";
    std::string cull = "all", stats, lighting = "project", technique = "project",
                animation = "project", preset = "project";
    // The snow surface's exposure: "auto" as the renderer suits (per vertex on software GL).
    std::string snowExposure = "auto";
    double timeS = 0.0;
    double lodDistanceM = render::CullSettings{}.lodDistanceM;
    double lodBlend = core::LOD_BLEND;
    int width = 0, height = 0, frames = 3, blades = 60000, turntable = 0;
    std::uint64_t seed = 0;
    bool glDebug = gl::GL_DEBUG_BY_DEFAULT;
    bool lightPerVertex = false;
    bool lightPerPixel = false;
    bool snow = false;
    // Given on the command line: they override the project's, which they default to.
    bool seedGiven = false, lodDistanceGiven = false;
};

// Reads the command line into `args`. Returns the exit code when the command ends here (--help,
// or a usage error printed); nothing when it goes on.
std::optional<int> parseRenderArgs(const std::vector<std::string>& argv, RenderArgs& args);

// Refutes, before any file is read, what the command line alone can: a project and --mesh both
// or neither, a glTF given as the project, a bad --cull list, an --out or --stats that cannot
// be written. Returns the culling tests --cull names.
Result<render::CullSettings> checkRenderArgs(const RenderArgs& args);

// The frame buffers asked for: --width, --height and --msaa over the project's.
struct FrameSize {
    int width = 0, height = 0, samples = 0;
};
FrameSize frameSize(const RenderArgs& args, const core::RenderSettings& settings);

// The image size and samples (frameSize), and the render options the project asks for with the
// command line's overrides; cull statistics always on.
render::OffscreenRequest offscreenRequest(const RenderArgs& args, const core::Project& project,
                                          const render::CullSettings& cullTests);

}  // namespace grass::cli
