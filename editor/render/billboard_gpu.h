// BillboardField: star billboard grass objects (SPEC §8, GPU Gems 1 ch. 7) on the GPU: the star
// vertices of core/billboard/star_billboards.h grouped by cluster, their triangle indices, the
// grass texture (RGBA8 with mipmaps, bound to BILLBOARD_TEXTURE_UNIT) and the program of
// shaders/billboard.{vert,frag}. World space, metres, seconds.
//
// draw() sets and restores the state it needs: alpha-to-coverage on (with an MSAA target it
// shapes the blades; without one a 0.5 alpha cutoff does), depth test and depth write on, face
// culling off (two-sided). The light is the caller's: the LightingBlock it uploaded
// (render/lighting_block.h), whose uGrassLighting picks the wrapped Lambert or SPEC §10. Clusters
// wholly outside the fade range or the view frustum are skipped (bounding spheres, with the largest
// wind offset added); the rest are drawn back to front by cluster-centre distance: one draw per
// cluster in the per-cluster mode (each with its CPU-computed sway and scene wind), one
// glMultiDrawElements otherwise. The scene's wind sources go to the shader each draw (their
// centres at the draw's time) so the far field moves with them (core/billboard/billboard_motion.h).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "billboard/star_billboards.h"
#include "physics/wind.h"
#include "gl/buffer.h"
#include "gl/gl_handle.h"
#include "gl/program.h"
#include "gl/vertex_array.h"
#include "util/image_file.h"

namespace grass::render {

inline constexpr std::uint32_t BILLBOARD_TEXTURE_UNIT = 0;
// The scene's wind sources and their centres (shaders/include/billboard_wind.glsl).
inline constexpr std::uint32_t BILLBOARD_WIND_SOURCE_BINDING = 13;
inline constexpr std::uint32_t BILLBOARD_WIND_CENTRE_BINDING = 14;

using BillboardWindMode = core::BillboardWindMode;

struct BillboardDrawParams {
    glm::mat4 viewProj{1.0f};
    glm::vec3 cameraPosWorld{0.0f};
    float timeS = 0.0f;
    BillboardWindMode mode = BillboardWindMode::PerObject;
    core::BillboardWind wind;
    core::BillboardFade fade;
    // The scene's wind sources and the stiffness of the blades the billboards stand for
    // (core::BillboardFollow::stiffness); no sources: GPU Gems' sway alone.
    std::vector<core::WindSource> sceneWind;
    float stiffness = 0.0f;
    // The program variant with the sun's shadows (the caller binds the map and the lighting).
    bool sunShadows = false;
    // Skips clusters whose bounding sphere lies outside the view frustum of viewProj.
    bool frustumCull = true;
    // The editor's reduced picture while the user interacts (RenderOptions::cull.keepEvery and
    // widthScale): one object in keepEvery is drawn, its stars widened by widthScale about the
    // object's centre so the field keeps its cover.
    std::uint32_t keepEvery = 1;
    float widthScale = 1.0f;
};

class BillboardField {
public:
    // Uploads the objects' star vertices and the texture, loads the program (its errors name the
    // shader file and line). Texture: RGBA8, row 0 = top (util/image_file.h).
    static Result<BillboardField> create(const std::vector<core::GrassObject>& objects,
                                         const Rgba8Pixels& texture,
                                         std::string_view label = "billboards");

    void draw(const BillboardDrawParams& params);
    // New objects (a repaint changed which live, how tall and how tinted), same texture and
    // program.
    void setObjects(const std::vector<core::GrassObject>& objects);

    std::size_t objectCount() const { return mObjectCount; }
    std::size_t clusterCount() const { return mClusters.size(); }
    const std::vector<core::StarCluster>& clusters() const { return mClusters; }
    // Of the last draw(): objects in the clusters drawn, and draw calls issued.
    std::size_t drawnObjects() const { return mDrawnObjects; }
    std::size_t drawCalls() const { return mDrawCalls; }
    // For uniforms draw() does not set (uCameraPosition and uFieldAo of the grass lighting).
    // With the sun's shadows compiled in or not (loaded on first use).
    const gl::Program& program(bool sunShadows = false);

private:
    BillboardField() = default;
    // The steps of draw().
    std::vector<std::uint32_t> visibleClusters(const BillboardDrawParams& params) const;
    void bindForDraw(const BillboardDrawParams& params, bool multisampled);
    void uploadSceneWind(const BillboardDrawParams& params);
    void drawEachCluster(const std::vector<std::uint32_t>& order,
                         const BillboardDrawParams& params);
    void drawClustersAtOnce(const std::vector<std::uint32_t>& order, std::uint32_t keepEvery);

    gl::Program mPrograms[2];  // [sun shadows]
    std::string mLabel;
    // One core::StarInstance a star, drawn instanced: its 18 indices name vertex ids 0…11,
    // which billboard.vert makes into the star's vertices (star_vertex.glsl).
    gl::Buffer mStars;
    gl::Buffer mIndices;
    gl::Buffer mDrawCommands;  // one indirect command per cluster, filled each frame
    gl::VertexArray mVertexArray;
    gl::TextureHandle mTexture;
    // The scene's wind sources and their centres, re-made when the source count grows.
    gl::Buffer mWindSources;
    gl::Buffer mWindCentres;
    std::vector<core::StarCluster> mClusters;
    float mTallestObjectM = 0.0f;  // how far the scene's wind can move a top, at most
    std::size_t mObjectCount = 0;
    std::size_t mDrawnObjects = 0;
    std::size_t mDrawCalls = 0;
};

}  // namespace grass::render
