// SceneRenderer: draws a Scene (opaque mesh first, the cull pass, then every grass layer by the
// chosen geometry path through the visible lists) into a framebuffer, timing each pass with GL
// timer queries. The headless CLI and the editor's viewport both draw through it. The frame
// lives in scene_renderer.cpp, its opaque and snow passes in scene_renderer_opaque.cpp, its
// grass passes in scene_renderer_grass.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <future>
#include <memory>
#include <span>
#include <stop_token>
#include <string>
#include <utility>
#include <vector>

#include "blade/blade_program_variant.h"
#include "gl/gl_ref.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/timer_query.h"
#include "gl/uniform_block.h"
#include "render/billboard_gpu.h"
#include "render/cull_pass.h"
#include "render/field_gpu.h"
#include "render/frame_timings.h"
#include "render/lighting_block.h"
#include "render/mesh_gpu.h"
#include "render/render_options.h"
#include "render/snow_pass.h"
#include "render/stem_set_gpu.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace grass::render {

// The texture unit of a glTF surface's base colour (mesh.frag's uBaseTexture binding).
inline constexpr std::uint32_t SURFACE_TEXTURE_UNIT = 5;
// The texture unit of the editor's map overlay (mesh.frag's uMapOverlay binding). Not the snow
// map's: the snow surface's program samples both while the artist paints under snow.
inline constexpr std::uint32_t MAP_OVERLAY_UNIT = 7;
// The sun's depth map (shaders/include/sun_shadow.glsl's uSunShadowMap), bound while the
// project's shadows are on.
inline constexpr std::uint32_t SUN_SHADOW_UNIT = 13;
static_assert(MAP_OVERLAY_UNIT != SNOW_MAP_UNIT && SURFACE_TEXTURE_UNIT != SNOW_MAP_UNIT &&
              MAP_OVERLAY_UNIT != SURFACE_TEXTURE_UNIT);

class SceneRenderer {
public:
    // Compiles the programs; the error names the shader file and line. `sameSurface`: a renderer
    // of a scene on the same surface (core::sameSurface), whose surface mesh on the GPU this one
    // shares instead of uploading it again (0.35-1.4 s of the editor's frame for an
    // 8.4-million-triangle ground, at every re-grow after an edit of the layers).
    static Result<std::unique_ptr<SceneRenderer>> create(
        const core::Scene& scene, const SceneRenderer* sameSurface = nullptr);
    // A worker still placing billboards is asked to stop and waited for (the placing ends at its
    // next stage: a field replaced by an edit need not wait up to 1.5 s for billboards it will
    // never draw).
    ~SceneRenderer();
    // The surface mesh on the GPU (shared with the renderer `create` was given, if any).
    const MeshGpu& surfaceMesh() const { return *mMesh; }

    // Draws into `framebuffer` (a gl::Framebuffer, or 0 = the window's), viewport width × height.
    void render(const core::OrbitCamera& camera, int width, int height,
                gl::FramebufferRef framebuffer, const RenderOptions& options);
    // Waits for the timer queries of the last render().
    FrameTimings lastTimings() const;
    // The blade buffer of each layer (SSBO layout of core::Blade), for physics to step in place.
    std::vector<gl::BufferRef> bladeBuffers() const;
    // After core::regrowLayerRegion changed layer `layer` of the scene: re-uploads the regrown
    // patches' blades and stem sets and the re-baked shading; nothing else moves.
    // Replaces layer `layer`'s blades on the GPU with `blades` (the CPU physics' state, one
    // upload a frame; core/scene/field_simulation.h). Same slot count as the layer's.
    void uploadBlades(std::size_t layer, std::span<const core::Blade> blades);
    void uploadRegrown(std::size_t layer, const core::RegrowReport& report);
    // The scene's billboards follow other placement (core::followColliderPlacement): made to
    // follow the layers again when next drawn, even where no blade grew again.
    void billboardsChanged() {
        ++mContentGeneration;
        mBillboardsStale = true;
    }
    // The map the terrain shows as a colour overlay (values 0..1 in its UV space; a map without
    // texels shows 1 everywhere), uploaded now; null: no overlay. The editor calls it when the
    // painted map or the choice of map changes.
    void setMapOverlay(const core::MapImage* map);
    // Counts the changes made outside render() to what the next frame draws (uploadBlades,
    // uploadRegrown, setMapOverlay): with the camera, the options and the scene's looks, what
    // decides whether a frame would draw what the last one did (editor/app/view_redraw.h).
    std::uint64_t contentGeneration() const { return mContentGeneration; }
    // What the user is to be told about the frames drawn so far, each once (the editor shows it
    // in the status bar): billboards it could not place for a technique that draws them.
    std::vector<std::string> takeNotes() { return std::exchange(mNotes, {}); }
    // Billboards a scene kept unplaced are placed on a worker (the editor's window, which goes on
    // drawing meanwhile: the frames draw none until they are in), not in the frame that first
    // draws them (`grass render`, scripts and tests: the same picture whatever the speed).
    void placeBillboardsInBackground(bool background) { mPlaceInBackground = background; }
    // Whether such a worker is placing them now (the editor says so in the viewport).
    bool placingBillboards() const { return mPlacing.valid(); }
    // Snow read-backs for tests and tools (wait for the GPU): the depth pass of the last frame
    // with snow (null before one), and the tip whiteness the cull wrote for layer `layer`.
    const SnowPass* snowPass() const { return mSnow.get(); }
    // The scene's props were replaced (a collider added or deleted in the editor, which grows
    // the field no more for it): their meshes go up again.
    void reloadProps();
    std::size_t propCount() const { return mProps.size(); }
    std::vector<float> readTipSnow(std::size_t layer) const {
        return layer < mFields.size() ? mFields[layer].readTipSnow() : std::vector<float>{};
    }

private:
    SceneRenderer() = default;
    const core::Scene* mScene = nullptr;
    // The frame's lighting, uploaded once at the start of render().
    gl::UniformBlock<LightingBlock> mLighting{"lighting"};
    gl::Program mStemSetPrograms[2];  // [sun shadows]; the shadowed one loads on first use
    // The opaque surfaces' programs: lit, lit with the terrain's textures (its glTF base colour,
    // the editor's map overlay), depth alone (the cull's pre-pass), and the snow surface with its
    // exposure per pixel or per vertex (RenderOptions::snowExposurePerVertex); all but the lit
    // one load on first use.
    enum class Opaque { Lit, LitTextured, DepthOnly, Snow, SnowExposurePerVertex, Count };
    // [sun shadows][variant]
    gl::Program mOpaquePrograms[2][static_cast<int>(Opaque::Count)];
    static Result<gl::Program> loadOpaqueProgram(Opaque variant, bool sunShadows);
    const gl::Program& opaqueProgram(Opaque variant, bool sunShadows = false);
    // The snow surface's program for these options.
    static Opaque snowVariant(const RenderOptions& options) {
        return options.snowExposurePerVertex ? Opaque::SnowExposurePerVertex : Opaque::Snow;
    }
    // A blade program's compile-time variant (core/blade/blade_program_variant.h).
    using BladeVariant = core::BladeProgramVariant;
    // By BladeVariant::index(); all but the plain ones load on first use.
    std::array<gl::Program, core::BLADE_PROGRAM_VARIANTS> mBladePrograms;
    static Result<gl::Program> loadBladeProgram(const BladeVariant& variant);
    const gl::Program& bladeProgram(const BladeVariant& variant);
    // The passes of render(), in order (scene_renderer_opaque.cpp, scene_renderer_grass.cpp).
    void runSnowPass(const RenderOptions& options, int width, int height);
    void drawOpaquePass(const glm::mat4& viewProj, const RenderOptions& options);
    void drawGrass(const core::OrbitCamera& camera, const glm::mat4& projection, int width,
                   int height, const RenderOptions& options);
    void drawOpaque(const gl::Program& program, const RenderOptions& options, bool shaded,
                    bool snowSurface);
    void drawBlades(const core::OrbitCamera& camera, const glm::mat4& projection, int width,
                    int height, const RenderOptions& options);
    void drawBillboards(const core::OrbitCamera& camera, const glm::mat4& viewProj,
                        const RenderOptions& options);
    // Technique growth: Kim & Cho's stem sets, uploaded on first use (a scene that never draws
    // them pays nothing).
    void drawStemSets(const core::OrbitCamera& camera, const glm::mat4& viewProj,
                      const CullSettings& cull, bool sunShadows);
    std::shared_ptr<const MeshGpu> mMesh;  // shared by the renderers of one surface
    // The surface's base-colour texture (scene.look), bound to SURFACE_TEXTURE_UNIT; 0: none.
    gl::TextureHandle mSurfaceTexture;
    // The map overlay (setMapOverlay), R8; 0: none.
    gl::TextureHandle mMapOverlay;
    glm::ivec2 mMapOverlaySize{0};
    std::vector<MeshGpu> mProps;
    std::vector<FieldGpu> mFields;
    std::unique_ptr<CullPass> mCull;
    // Made on the first frame with snow on: a snow-free scene allocates no map.
    std::unique_ptr<SnowPass> mSnow;
    std::unique_ptr<SnowPass> mSunShadow;  // the sun's depth map, made when shadows are first on
    bool mSnowLies = false;  // this frame: snow on with an amount > 0
    // Whether the map was drawn (false: the last one, of the same view and occluders, is kept).
    bool renderSnowMap(const RenderOptions& options);
    void drawOccluders(const gl::Program& program, float timeS);
    // What drawOccluders draws at `timeS`, for the depth maps to tell whether theirs is still it.
    Occluders occluders(float timeS) const;
    // The frame's framebuffer, when the cull can read the occlusion depth from it
    // (floatDepthOf), else 0.
    GLuint mFrameDepth = 0;
    static GLuint floatDepthOf(GLuint framebuffer);
    void runSunShadowPass(const RenderOptions& options, LightingBlock& block);
    std::unique_ptr<BillboardField> mBillboards;
    // Billboards this renderer placed for a scene that kept them unplaced (billboardLayer()).
    std::unique_ptr<core::BillboardLayer> mPlacedHere;
    bool mBillboardsRefused = false;
    bool mPlaceInBackground = false;
    // The worker placing them (placeBillboardsInBackground); its future waits for it when the
    // renderer goes, before the scene it reads does (editor/app/live_scene.h: Live).
    std::future<Result<core::BillboardLayer>> mPlacing;
    std::stop_source mPlacingStop;
    std::vector<std::string> mNotes;  // takeNotes()
    const core::BillboardLayer* billboardLayer();
    bool mBillboardsStale = false;  // a repaint since they were last made to follow the layers
    BillboardField* billboardField();
    std::vector<StemSetField> mStemSets;
    core::StemSetCullResult mStemSetCull;  // reused frame to frame
    std::size_t mStemSetsDrawn = 0;
    gl::GpuTimer mMeshTimer, mGrassTimer, mCullTimer, mBillboardTimer, mStemSetTimer, mSnowTimer;
    bool mSoftwareGl = false;  // timers are synchronous there (set by create)
    std::size_t mBladesDrawn = 0;
    std::size_t mBillboardsDrawn = 0;
    float mFieldAo = 1.0f;
    std::size_t mBillboardDrawCalls = 0;
    bool mStatsFrame = false;
    std::vector<std::string> mPasses;
    std::uint64_t mContentGeneration = 0;
    std::uint64_t mOccluderGeometry = 0;  // moved on by reloadProps (Occluders::geometry)
};

}  // namespace grass::render
