// The snow depth pass (SPEC §11): the terrain and the props rendered orthographically along the
// snowfall into a depth texture of the project's map resolution, which the mesh shaders read to
// find where the sky reaches (shaders/include/snow.glsl). Runs only when snow is on.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>

#include "gl/framebuffer.h"
#include "gl/gl_ref.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/uniform_block.h"
#include "render/snow_block.h"
#include "render/snow_view_block.h"
#include "snow/snow.h"
#include "util/result.h"

namespace grass::render {

// What a depth map's occluders were when drawn: the geometry (a count the renderer moves on
// whenever it loads other meshes) and where each prop stood.
struct Occluders {
    std::uint64_t geometry = 0;
    std::vector<glm::mat4> models;
    bool operator==(const Occluders&) const = default;
};

class SnowPass {
public:
    static Result<SnowPass> create();

    // Renders the depth map of `view` at `resolution`²; `draw(program)` draws every occluder
    // with the program's uModel set. Uploads the view's SnowViewBlock. Restores the framebuffer
    // and viewport. A map of the same view, resolution and `occluders` as the last is kept, not
    // drawn again (a still scene under snow redrew it every frame: 6–9 ms of projects/winter's
    // frame on llvmpipe); returns whether it drew.
    bool run(const core::OrthoSnowView& view, int resolution, const Occluders& occluders,
             const std::function<void(const gl::Program&)>& draw);
    // The same, always drawn (occluders the caller does not describe).
    void run(const core::OrthoSnowView& view, int resolution,
             const std::function<void(const gl::Program&)>& draw);
    // What shaders/include/snow.glsl reads, for every program drawn after it: uploads the
    // SnowBlock of `params` at `amountM`, binds it with the last run()'s view block, and binds
    // the map on SNOW_MAP_UNIT. While the snow drifts (params' drift direction resolved:
    // core::snowWithWindDrift) it also computes the drift cells (snow_drift.comp) and binds
    // them on SNOW_DRIFT_UNIT. Returns whether it did.
    bool bind(const core::SnowParams& params, float amountM);
    // The depth texture (depth / depthRange), for tests.
    gl::TextureRef depthTexture() const { return mDepth.texture; }
    // The drift cells of the last bind() (R32F, resolution / SNOW_DRIFT_CELL_TEXELS a side;
    // none while the snow does not drift), for tests.
    gl::TextureRef driftTexture() const { return mDrift; }
    int driftCells() const { return mDriftCells; }
    const core::OrthoSnowView& view() const { return mView; }

private:
    void computeDrift();

    gl::Program mProgram;
    std::optional<gl::Program> mDriftProgram;  // loaded the first time the snow drifts
    gl::TextureHandle mDrift;
    int mDriftCells = 0;
    gl::UniformBlock<SnowBlock> mSnowBlock{"snow"};
    gl::UniformBlock<SnowViewBlock> mViewBlock{"snow view"};
    gl::DepthTarget mDepth;
    int mResolution = 0;
    core::OrthoSnowView mView;
    std::optional<Occluders> mDrawn;  // the occluders of the map held (none: nothing drawn yet)
};

}  // namespace grass::render
