// StemSetField: Kim & Cho's own technique (SPEC §9) on the GPU: sets of 6 stems, each a clamped
// B-spline ribbon through its 1–4 level points, drawn by instancing one template mesh with the
// per-instance data of core::StemSetInstance (SSBO STEM_SET_BINDING). World space, metres.
//
// The template mesh has no vertex data: vertex v of a set is stem k = v / (2·samples), sample
// i = (v mod 2·samples) / 2, side v mod 2 (0 = −x, 1 = +x), with samples = 5·levels — the
// vertex order of core::stemSetVertices. shaders/stem_set.vert derives the vertex from
// gl_VertexID; a static index buffer turns each stem's ribbon into GL_TRIANGLES (two per pair
// of samples), so the six stems need no strip restarts and no degenerate triangles.
//
// The set's model frame: x across, y up, z the bend direction, one unit = metresPerUnit metres.
// It is placed by stemSetFrame(up, yaw): model y goes to the surface normal `up`, model x to
// T = normalize(cross(up, ref)) and model z to B = cross(T, up), where ref is world +z, or world
// +x when |up.z| > 0.9 (up within about 25° of ±z, where cross(up, z) would lose precision).
// For up = +y the frame is the identity (x, y, z stay x, y, z). Then the set turns by yaw about
// up, counter-clockwise seen from above (glm::rotate's sense): world = root + metresPerUnit ·
// (stemSetFrame(up, yaw) · p). shaders/include/stem_set.glsl holds the same formulas.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/vertex_array.h"
#include "growth/growth_stems.h"
#include "growth/stem_set_cull.h"
#include "util/result.h"

namespace grass::render {

// SSBO of the instances (shaders/stem_set.vert). 0–9 are taken by the blade passes.
inline constexpr std::uint32_t STEM_SET_BINDING = 10;
// Only in programs built with the define STEM_SET_CAPTURE (tests): for vertex v of instance i,
// the vertex shader writes the world position (w = 1) and the unit world normal (w = 0, not
// turned to any viewer) to vec4 2·(i · vertices per set + v) and the one after it.
inline constexpr std::uint32_t STEM_SET_CAPTURE_BINDING = 11;
// SSBO of the culled sets' indices (core::cullStemSets' lists, one after another).
inline constexpr std::uint32_t STEM_SET_VISIBLE_BINDING = 12;

// Vertices of one set's template mesh at `levels` (clamped to 1..4) and `samplesPerLevel`
// (clamped to 2..5; 5 is full detail): 6 · 2 · samplesPerLevel · levels.
int stemSetVertexCount(int levels, int samplesPerLevel = core::STEM_SAMPLES_PER_LEVEL);
// Triangle indices of one set's template mesh: 6 stems · (samples − 1) quads · 6.
int stemSetIndexCount(int levels, int samplesPerLevel = core::STEM_SAMPLES_PER_LEVEL);

// Columns: where model x, y, z go in world space (orthonormal, right-handed). A zero `up`
// counts as +y.
glm::mat3 stemSetFrame(glm::vec3 up, float yawRad);
// A model-frame point of the set (core::stemSetVertices' space) in world space, metres: the CPU
// mirror of stemSetWorldPosition in shaders/include/stem_set.glsl.
glm::vec3 stemSetWorldPosition(const core::StemSetInstance& instance, glm::vec3 modelPoint);
// The instance's growth parameters for core::stemSetVertices at `levels`.
core::StemSetParams stemSetParams(const core::StemSetInstance& instance, int levels);

// Root and tip colours of healthy (b = 1) and poor (b = 0) grass: albedo =
// mix(mix(poorRoot, healthyRoot, b), mix(poorTip, healthyTip, b), height along the stem).
struct StemSetColours {
    glm::vec3 healthyRoot{0.08f, 0.26f, 0.04f};
    glm::vec3 healthyTip{0.36f, 0.66f, 0.16f};
    glm::vec3 poorRoot{0.40f, 0.33f, 0.15f};
    glm::vec3 poorTip{0.86f, 0.76f, 0.45f};  // straw
};

// shaders/stem_set.{vert,frag}. Uniforms the caller sets: uViewProj, uCameraPosition, the
// colours (setStemSetColours) and uFieldAo (as for billboards); the light comes from the
// LightingBlock the caller uploaded (render/lighting_block.h). draw() sets uLevels.
Result<gl::Program> loadStemSetProgram(const std::vector<std::string>& defines = {});
void setStemSetColours(const gl::Program& program, const StemSetColours& colours);

class StemSetField {
public:
    explicit StemSetField(const std::vector<core::StemSetInstance>& instances,
                          const std::string& label = "stem sets");

    std::size_t instanceCount() const { return mInstanceCount; }
    // Replaces instances [first, first + instances.size()) after a re-grow (core::regrowPatches).
    void update(std::size_t first, std::span<const core::StemSetInstance> instances);

    // One instanced draw of every set at `levels` (clamped to 1..4), full detail. The caller
    // has bound `program` (loadStemSetProgram) and set its other uniforms. Opaque and two-sided:
    // depth test on and face culling off for the draw, both restored after it.
    void draw(const gl::Program& program, int levels) const;
    // The sets of `culled` only (core::cullStemSets over these instances), one instanced draw
    // per level of detail at its samples per level; otherwise as draw().
    void draw(const gl::Program& program, int levels, const core::StemSetCullResult& culled);

private:
    void drawList(const gl::Program& program, int levels, int samplesPerLevel, bool useVisible,
                  std::uint32_t first, std::size_t count) const;

    std::size_t mInstanceCount = 0;
    gl::Buffer mInstances;
    // The culled sets' indices, room for every set (STEM_SET_VISIBLE_BINDING).
    gl::Buffer mVisible;
    std::vector<std::uint32_t> mVisibleUpload;
    // The index lists of levels 1..4 at each LOD's samples per level, one after another.
    gl::Buffer mIndices;
    gl::VertexArray mVertexArray;  // no attributes: holds the index buffer
};

}  // namespace grass::render
