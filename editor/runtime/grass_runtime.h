// The reference runtime (issue 28): a grass field exported with `grass export --format raw`
// brought to life in a host's own GL 4.5 renderer — the editor's physics (wind, gravity,
// colliders), its per-blade culling with indirect draws, and its grass lighting, with the
// editor's shaders. Depends on GL through libepoxy, GLM and nlohmann-json only.
//
//   grass::runtime::Field field;                    // with the host's GL context current
//   if (!field.load("exports/meadow", error)) ...   // reads the export, uploads it
//   each frame:
//     field.moveCollider(0, playerPosition);        // optional: the host moves colliders
//     field.update(frameSeconds);                   // physics, in the export's fixed steps
//     field.drawMeshes(view);                       // optional: the export's terrain and props
//     field.draw(view);                             // cull + blades into the bound framebuffer
//
// World space is the export's: metres, +Y up, right-handed; time in seconds. docs/runtime.md.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/export_reader.h"

namespace grass::runtime {

// The host's camera for one frame, and the size of the framebuffer it draws into.
struct View {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 cameraPosition{0.0f};
    int width = 1;
    int height = 1;
};

// The view of the export's own camera (the project's first) at a framebuffer size.
View exportCameraView(const ExportData& data, int width, int height);

enum class GeometryPath { Strips, Tessellation };

struct DrawStats {
    std::size_t bladesDrawn = 0;  // after culling (read back from the GPU: statistics only)
};

class Field {
public:
    Field();
    ~Field();
    Field(Field&&) noexcept;
    Field& operator=(Field&&) noexcept;

    // Reads `folder` (a raw export) and uploads it; needs a current GL 4.5 core context. On
    // failure returns false with one line in `error` naming the file or shader and the problem.
    bool load(const std::filesystem::path& folder, std::string& error);
    // The same for an export already read (readExport), e.g. checked before a window opens.
    bool load(ExportData data, std::string& error);
    const ExportData& data() const;

    // --- physics (SPEC §3–5, shaders/physics.comp) ---
    // Advances the simulation by `seconds` in whole steps of the export's step (the rest carries
    // to the next call); at most 8 steps a call, so a stalled frame does not snowball.
    void update(float seconds);
    // One step of the export's step length.
    void step();
    float timeS() const;

    // --- colliders: the export's, by index (ExportData::colliders) ---
    // Where collider i stands now: its path at timeS(), or where the host put it.
    glm::vec3 colliderOrigin(std::size_t i) const;
    // From now on collider i (all its spheres) stands at `origin`; its path no longer moves it.
    void moveCollider(std::size_t i, glm::vec3 origin);
    // Collider i follows its path again.
    void releaseCollider(std::size_t i);

    // --- drawing into the bound framebuffer (the host's viewport, depth test as it has it) ---
    // Culls every layer (frustum, orientation, distance thinning; SPEC §6) and draws the
    // survivors with the grass lighting (SPEC §10). Leaves program and vertex array unbound.
    void draw(const View& view);
    // The export's terrain and collider props, lit as the editor lights them; a host that draws
    // its own ground and objects skips it.
    void drawMeshes(const View& view);
    // Strips or tessellation; the export's "auto" picks strips on software GL, else tessellation.
    // load() compiles the programs of that path alone; switching compiles the other path's on
    // the first switch. It returns false, naming the shader in `error` and keeping the path
    // drawn so far, when they do not compile (the form without `error` drops the message).
    GeometryPath geometry() const;
    void setGeometry(GeometryPath path);
    bool setGeometry(GeometryPath path, std::string& error);
    // Blades the last draw() kept, summed over layers (waits for the GPU).
    DrawStats readStats() const;

    // The blades of layer `layer` as they stand now (a read-back, for tests and tools).
    std::vector<core::Blade> readBlades(std::size_t layer) const;

private:
    struct State;
    std::unique_ptr<State> mState;
};

}  // namespace grass::runtime
