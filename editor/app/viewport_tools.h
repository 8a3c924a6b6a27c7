// The viewport's tools (issue 8): the brush that paints a layer's density, soil or light map on
// the mesh under the mouse, and the gizmo that places wind sources and colliders. They read the
// pointer over the 3D view in its pixels and work on EditorState; no window code, so tests drive
// them with simulated pointer events exactly as the Editor does with GLFW's.
#pragma once

#include <cstddef>
#include <future>
#include <optional>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "edit/gizmo_drag.h"
#include "edit/scene_paint.h"
#include "mesh/bvh.h"
#include "scene/camera.h"
#include "ui/context.h"

namespace grass::editor {

struct EditorState;

enum class ViewportTool { Camera, Paint, Place };

// The pointer over the viewport this frame: pixels with the origin at the viewport's top-left,
// y down (core::cameraRay's convention). `pressure` is the pen's, 1 for a mouse (GLFW reports no
// tablet pressure; scripts may set it).
struct ViewportPointer {
    glm::vec2 pixel{0.0f};
    glm::vec2 viewportSize{1.0f};
    bool inside = false;  // over the viewport and not over a panel
    bool down = false;
    bool pressed = false;
    bool released = false;
    bool ctrl = false;
    bool shift = false;
    float pressure = 1.0f;
    // Where the pointer went on its way to `pixel` since the tool last saw it, the button held
    // (viewport pixels, in order): a brush stroke follows it however few frames come.
    std::vector<glm::vec2> pathBefore;
};

struct PaintToolSettings {
    std::size_t layer = 0;
    core::LayerMap map = core::LayerMap::Density;
    core::BrushSettings brush;
    bool radiusChosen = false;  // false: the first stroke sizes the brush to the scene
    // Show the brush's map over the terrain in colour (0 purple, 1 yellow) while painting.
    bool showMap = false;
};

enum class PlacedKind { Wind, Collider };
struct PlacedObject {
    PlacedKind kind = PlacedKind::Wind;
    std::size_t index = 0;
    bool operator==(const PlacedObject&) const = default;
};

struct PlaceToolSettings {
    core::GizmoMode mode = core::GizmoMode::Translate;
    core::GizmoSnap snap;  // Ctrl held snaps too
    std::optional<PlacedObject> selected;
};

// What the tools work on, rebuilt with the live scene: the mesh's BVH for picking and the brush.
// The BVH is built on a worker thread from a copy of the mesh's triangles (an 8-million-triangle
// ground took 4 s, all of it before the window could draw), so the field shows at once; the
// first pick waits for the rest of the build. Tools for a field re-grown on the same surface
// (core::regrowOnSameSurface) share the BVH of the tools before them instead of building it again.
struct SceneTools {
    SceneTools(core::Scene& scene, const core::GrassLightingDesc& lighting,
               const SceneTools* sameSurface = nullptr);
    // Waits for the build the first time.
    const core::TriangleBvh& bvh() const { return mBvh.get(); }
    core::ScenePainter painter;

private:
    std::shared_future<core::TriangleBvh> mBvh;
};

// Where the mouse meets the mesh (for the brush cursor), if it does.
std::optional<core::RayHit> pickSurface(const SceneTools& tools, const core::OrbitCamera& camera,
                                        const ViewportPointer& pointer);

// Runs the active tool for this frame's pointer. Returns true when the tool used the pointer
// (the camera must then leave it alone). Regrown patches are queued in state.regrown for the
// renderer; finished strokes and drags become history steps.
bool runViewportTool(EditorState& state, const core::OrbitCamera& camera,
                     const ViewportPointer& pointer);

// The brush radius's range: 0.01 to 100 m, widened to a ten-thousandth and the whole of the
// scene's diagonal (a part modelled in millimetres, a 60 km sphere).
struct BrushRadiusRange {
    float min = 0.01f;
    float max = 100.0f;
};
BrushRadiusRange brushRadiusRange(const EditorState& state);
// The radius the brush paints with: the one chosen, else (until the user chooses one) a
// twentieth of the scene's diagonal, within the range.
float brushRadius(const EditorState& state);
// Sets the brush's radius to brushRadius, so that the panel shows, and [ and ] start from, the
// radius the ring shows.
void sizeBrushToScene(EditorState& state);

// Keys of the tools when the UI does not want the keyboard: '[' and ']' (typed text) shrink and
// grow the brush, 'w' 'e' 'r' pick the gizmo's translate / rotate / scale, 'b' the brush,
// 'g' the gizmo, 'c' the camera.
void applyToolKeys(EditorState& state, std::string_view typed);

// The brush ring lying on the mesh, the objects' markers, radii and directions, and the gizmo of
// the selected one, drawn over the viewport `view` (points); pixelsPerPoint maps pixels to points.
void drawViewportOverlay(ui::Context& ctx, ui::Rect view, float pixelsPerPoint,
                         const EditorState& state, const core::OrbitCamera& camera,
                         const ViewportPointer& pointer);

// The position an object is drawn and dragged at (its path's position at `timeS` if keyed).
glm::vec3 placedPosition(const core::Project& project, PlacedObject object, float timeS);

// The box F frames when an object is selected: around where it stands at `timeS`, as large as
// its reach (a collider's radius or scale, a wind source's radius or core), at least 1 m.
std::optional<core::Bounds> selectionBounds(const EditorState& state, float timeS);
// Delete: removes the selected wind source or collider (one undo step, the field re-grows).
// Returns its name, or nothing when nothing is selected.
std::optional<std::string> deleteSelection(EditorState& state);

}  // namespace grass::editor
