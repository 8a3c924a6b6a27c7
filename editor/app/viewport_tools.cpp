#include "app/viewport_tools.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "mesh/surface_ring.h"
#include "app/commands.h"
#include "app/panels.h"
#include "ui/painter.h"

namespace grass::editor {

namespace {

// The first brush spans this share of the scene's diagonal: readable on any mesh, whatever
// its units (the CLI's `grass paint` default too).
constexpr float DEFAULT_RADIUS_SHARE = 0.05f;
// A click this close to an object's marker (pixels) selects it.
constexpr float SELECT_PIXELS = 14.0f;
constexpr int RING_POINTS = 48;

// Ctrl paints the opposite: add ↔ subtract, set toward 1 − value; smooth stays smooth.
core::BrushSettings effectiveBrush(const core::BrushSettings& brush, bool invert) {
    core::BrushSettings b = brush;
    if (!invert)
        return b;
    if (b.mode == core::BrushMode::Add)
        b.mode = core::BrushMode::Subtract;
    else if (b.mode == core::BrushMode::Subtract)
        b.mode = core::BrushMode::Add;
    else if (b.mode == core::BrushMode::Set)
        b.setValue = 1.0f - b.setValue;
    return b;
}

void queue(EditorState& s, std::size_t layer, const Result<core::RegrowReport>& report) {
    if (!report)
        s.transient.message = "re-grow failed: " + report.error().str();
    else if ((!report->patches.empty() || !report->shadedPatches.empty()) && s.regrown)
        s.regrown(layer, *report);
}

void endStroke(EditorState& s) {
    s.view.toolDragActive = false;
    // The dabs re-baked only their own blades' shading; now their neighbours' (one pause at the
    // end of a density stroke instead of one per dab).
    queue(s, s.tools->painter.layer(), s.tools->painter.settleShading());
    if (auto edit = s.tools->painter.end())
        apply(s, RecordStroke{std::move(*edit)});
}

bool runPaint(EditorState& s, const core::OrbitCamera& camera, const ViewportPointer& p) {
    core::ScenePainter& painter = s.tools->painter;
    const bool stroking = painter.active();
    if (!stroking && !(p.pressed && p.inside))
        return false;
    // The stroke goes where the pointer went since the last frame, not straight to where it is
    // (at 1–3 frames a second a curve drawn within a frame would be a chord); the dabs are laid
    // now and grow with this frame's.
    if (stroking)
        for (const glm::vec2 pixel : p.pathBefore) {
            ViewportPointer along = p;
            along.pixel = pixel;
            const auto hit = pickSurface(*s.tools, camera, along);
            if (!hit) {
                endStroke(s);  // off the mesh, as below
                return true;
            }
            painter.addHits(std::span<const glm::vec3>(&hit->posWorld, 1));
        }
    if (stroking && (!p.down || p.released)) {
        // The stroke reaches where the button came up: at 1–3 frames a second the last frame
        // saw the pointer a long way before it (a hit where the last one was paints nothing).
        if (const auto hit = pickSurface(*s.tools, camera, p))
            queue(s, painter.layer(), painter.paintTo(hit->posWorld, p.pressure));
        endStroke(s);
        return true;
    }
    const auto hit = pickSurface(*s.tools, camera, p);
    if (!hit) {
        // Off the mesh: the stroke ends rather than jump across the gap when it comes back.
        if (stroking)
            endStroke(s);
        return true;
    }
    if (!stroking) {
        if (s.view.paint.layer >= s.scene->layers.size())
            return true;
        sizeBrushToScene(s);
        s.view.paint.radiusChosen = true;
        const core::GrassLayer& layer = s.doc.loaded.project.layers[s.view.paint.layer];
        painter.begin(s.view.paint.layer, s.view.paint.map, layer.mapResolution,
                      effectiveBrush(s.view.paint.brush, p.ctrl));
        s.view.toolDragActive = true;
    }
    queue(s, s.view.paint.layer, painter.paintTo(hit->posWorld, p.pressure));
    return true;
}

core::GizmoView gizmoView(const core::OrbitCamera& camera, const ViewportPointer& p) {
    return core::GizmoView{camera, p.viewportSize};
}

// The project with a drag's delta applied to the object as it was when the drag began.
core::Project movedByGizmo(const EditorState& s, PlacedObject object, const core::GizmoDelta& d,
                           float timeS) {
    core::Project project = s.doc.project();
    const core::Project& start = s.view.gizmoStart;
    const auto moved = [&](glm::vec3 position, std::vector<core::PathKey>& path,
                           const std::vector<core::PathKey>& startPath) -> glm::vec3 {
        if (startPath.empty())
            return position + d.translationWorld;
        // A keyed object: the drag moves its key at the current time (made if missing).
        path = startPath;
        const glm::vec3 at = core::samplePath(startPath, timeS, position);
        core::setKey(path, timeS, at + d.translationWorld, 0.5f * float(s.view.timeline.stepS()));
        return position;
    };
    const glm::mat3 rotation =
        d.angleRad != 0.0f && glm::length(d.rotationAxis) > 0.0f
            ? glm::mat3(glm::rotate(glm::mat4(1.0f), d.angleRad, d.rotationAxis))
            : glm::mat3(1.0f);
    const float uniform = std::max({d.scale.x, d.scale.y, d.scale.z}) >= 1.0f
                              ? std::max({d.scale.x, d.scale.y, d.scale.z})
                              : std::min({d.scale.x, d.scale.y, d.scale.z});
    if (object.kind == PlacedKind::Wind) {
        core::WindSource& w = project.wind[object.index].source;
        const core::WindSource& w0 = start.wind[object.index].source;
        w.position = moved(w0.position, w.path, w0.path);
        w.direction = rotation * w0.direction;
        w.axis = rotation * w0.axis;
        w.radiusM = w0.radiusM * uniform;
        w.coreRadiusM = w0.coreRadiusM * uniform;
    } else {
        core::ColliderDesc& c = project.colliders[object.index];
        const core::ColliderDesc& c0 = start.colliders[object.index];
        c.position = moved(c0.position, c.path, c0.path);
        c.radiusM = c0.radiusM * uniform;
        c.scale = c0.scale * uniform;
    }
    return project;
}

std::optional<PlacedObject> objectUnder(const EditorState& s, const core::OrbitCamera& camera,
                                        const ViewportPointer& p) {
    std::optional<PlacedObject> best;
    float bestDistance = SELECT_PIXELS;
    const auto consider = [&](PlacedObject object) {
        const auto at = core::projectToPixel(
            camera, placedPosition(s.doc.loaded.project, object, float(s.view.timeline.timeS())),
            p.viewportSize);
        if (!at)
            return;
        const float d = glm::length(*at - p.pixel);
        if (d < bestDistance) {
            bestDistance = d;
            best = object;
        }
    };
    for (std::size_t i = 0; i < s.doc.loaded.project.wind.size(); ++i)
        consider({PlacedKind::Wind, i});
    for (std::size_t i = 0; i < s.doc.loaded.project.colliders.size(); ++i)
        consider({PlacedKind::Collider, i});
    return best;
}

bool validSelection(const EditorState& s) {
    if (!s.view.place.selected)
        return false;
    const PlacedObject o = *s.view.place.selected;
    return o.kind == PlacedKind::Wind ? o.index < s.doc.loaded.project.wind.size()
                                      : o.index < s.doc.loaded.project.colliders.size();
}

// The gizmo's drag with the pointer at `pixel`: the selection moved by its delta from where the
// drag began, as an ongoing edit (the drag's end makes it one step).
void dragSelectionTo(EditorState& s, glm::vec2 pixel, float timeS) {
    if (validSelection(s))
        apply(s, EditProject{.after = movedByGizmo(s, *s.view.place.selected,
                                                   s.view.gizmoDrag->update(pixel), timeS),
                             .ongoing = true});
}

bool runPlace(EditorState& s, const core::OrbitCamera& camera, const ViewportPointer& p) {
    const float timeS = float(s.view.timeline.timeS());
    if (s.view.gizmoDrag) {
        if (!p.down || p.released) {
            // The object goes where the button came up (the drag's delta depends on the pointer
            // alone, so the same place again changes nothing).
            dragSelectionTo(s, p.pixel, timeS);
            s.view.gizmoDrag.reset();
            s.view.toolDragActive = false;
            // The drag ends as one step; the renderer's props and the GPU physics are built
            // from the project: re-grow.
            const bool moved = s.doc.project() != s.view.gizmoStart;
            apply(s, EditProject{.after = s.doc.project(),
                                 .effect = moved ? EditEffect::Regrow : EditEffect::Live});
            return true;
        }
        dragSelectionTo(s, p.pixel, timeS);
        return true;
    }
    if (!(p.pressed && p.inside))
        return false;
    if (validSelection(s)) {
        const glm::vec3 pivot = placedPosition(s.doc.loaded.project, *s.view.place.selected, timeS);
        const core::GizmoHandle handle =
            core::pickGizmoHandle(s.view.place.mode, gizmoView(camera, p), pivot, p.pixel);
        if (handle != core::GizmoHandle::None) {
            core::GizmoSnap snap = s.view.place.snap;
            snap.enabled = snap.enabled || p.ctrl;
            s.view.gizmoDrag.emplace(s.view.place.mode, handle, pivot, gizmoView(camera, p), p.pixel, snap);
            s.view.gizmoStart = s.doc.loaded.project;
            s.view.toolDragActive = true;
            return true;
        }
    }
    const auto under = objectUnder(s, camera, p);
    s.view.place.selected = under;
    // A click on empty ground keeps the camera's drag; a click on an object selects it.
    return under.has_value();
}

// Wind sources and colliders as the overlay shows them: marker, radius, direction.
void drawObjects(ui::Painter& painter, ui::Rect view, float ppp, const EditorState& s,
                 const core::OrbitCamera& camera, glm::vec2 size) {
    const core::Project& project = s.doc.loaded.project;
    const float timeS = float(s.view.timeline.timeS());
    const auto toPoints = [&](glm::vec2 px) {
        return ui::Vec2(view.min.x + px.x / ppp, view.min.y + px.y / ppp);
    };
    // A circle of radius r about `centre` in the plane perpendicular to `normal`.
    const auto worldCircle = [&](glm::vec3 centre, glm::vec3 normal, float r, ui::Color32 color) {
        const glm::vec3 n = glm::normalize(normal);
        const glm::vec3 t = glm::normalize(glm::abs(n.y) < 0.9f ? glm::cross(n, {0, 1, 0})
                                                                : glm::cross(n, {1, 0, 0}));
        const glm::vec3 b = glm::cross(n, t);
        std::vector<ui::Vec2> points;
        for (int i = 0; i < RING_POINTS; ++i) {
            const float a = 6.2831853f * float(i) / RING_POINTS;
            if (auto px = core::projectToPixel(camera, centre + r * (std::cos(a) * t + std::sin(a) * b),
                                               size))
                points.push_back(toPoints(*px));
        }
        if (points.size() == RING_POINTS)
            painter.path(std::move(points), true, ui::Color32::transparent(), {1.5f, color});
    };
    const auto marker = [&](glm::vec3 at, ui::Color32 color, bool selected) {
        if (auto px = core::projectToPixel(camera, at, size))
            painter.circle(toPoints(*px), selected ? 6.0f : 4.5f, color,
                           {1.0f, ui::Color32::rgb(20, 20, 20)});
    };
    // A keyed motion path: the piecewise-linear track between its keys, and a dot per key.
    const auto pathTrack = [&](const std::vector<core::PathKey>& path, ui::Color32 color) {
        std::vector<ui::Vec2> points;
        for (const core::PathKey& key : path)
            if (auto px = core::projectToPixel(camera, key.posWorld, size))
                points.push_back(toPoints(*px));
        if (points.size() >= 2)
            painter.path(points, false, ui::Color32::transparent(), {1.0f, color});
        for (const ui::Vec2 point : points)
            painter.circle(point, 3.0f, color);
    };
    const auto isSelected = [&](PlacedKind kind, std::size_t i) {
        return s.view.place.selected && *s.view.place.selected == PlacedObject{kind, i};
    };
    const ui::Color32 windColor = ui::Color32::rgb(120, 190, 255);
    for (std::size_t i = 0; i < project.wind.size(); ++i) {
        const core::WindSource& w = project.wind[i].source;
        const glm::vec3 at = placedPosition(project, {PlacedKind::Wind, i}, timeS);
        marker(at, windColor, isSelected(PlacedKind::Wind, i));
        if (w.radiusM > 0.0f)
            worldCircle(at, {0, 1, 0}, w.radiusM, windColor);
        if (w.kind == core::WindKind::Vortex)
            worldCircle(at, w.axis, std::max(w.coreRadiusM, 1e-3f), windColor);
        if (w.kind == core::WindKind::Directional && glm::length(w.direction) > 0.0f) {
            const float arrow = core::worldLengthForPixels({camera, size}, at, 60.0f);
            const auto a = core::projectToPixel(camera, at, size);
            const auto b = core::projectToPixel(camera, at + arrow * glm::normalize(w.direction), size);
            if (a && b)
                painter.line(toPoints(*a), toPoints(*b), {2.0f, windColor});
        }
        pathTrack(w.path, ui::Color32::rgb(60, 90, 140));
    }
    const ui::Color32 colliderColor = ui::Color32::rgb(255, 170, 90);
    for (std::size_t i = 0; i < project.colliders.size(); ++i) {
        const core::ColliderDesc& c = project.colliders[i];
        const glm::vec3 at = placedPosition(project, {PlacedKind::Collider, i}, timeS);
        marker(at, colliderColor, isSelected(PlacedKind::Collider, i));
        if (c.shape == core::ColliderShape::Sphere)
            worldCircle(at, camera.position() - at, c.radiusM, colliderColor);
        pathTrack(c.path, ui::Color32::rgb(140, 90, 50));
    }
}

ui::Color32 handleColor(core::GizmoHandle handle, bool hot) {
    const auto pick = [&](ui::Color32 normal) { return hot ? ui::Color32::rgb(255, 230, 80) : normal; };
    switch (handle) {
    case core::GizmoHandle::X:
    case core::GizmoHandle::PlaneYZ: return pick(ui::Color32::rgb(230, 70, 70));
    case core::GizmoHandle::Y:
    case core::GizmoHandle::PlaneZX: return pick(ui::Color32::rgb(90, 210, 90));
    case core::GizmoHandle::Z:
    case core::GizmoHandle::PlaneXY: return pick(ui::Color32::rgb(80, 130, 240));
    default: return pick(ui::Color32::rgb(220, 220, 220));
    }
}

}  // namespace

SceneTools::SceneTools(core::Scene& scene, const core::GrassLightingDesc& lighting,
                       const SceneTools* sameSurface)
    : painter(scene, lighting),
      mBvh(sameSurface != nullptr
               ? sameSurface->mBvh
               : std::async(std::launch::async,
                            [soup = core::triangleSoupOf(scene.mesh)]() mutable {
                                return core::TriangleBvh(std::move(soup));
                            })
                     .share()) {}

std::optional<core::RayHit> pickSurface(const SceneTools& tools, const core::OrbitCamera& camera,
                                        const ViewportPointer& pointer) {
    return tools.bvh().intersect(core::cameraRay(camera, pointer.pixel, pointer.viewportSize));
}

std::optional<core::Bounds> selectionBounds(const EditorState& state, float timeS) {
    if (!validSelection(state))
        return std::nullopt;
    const core::Project& project = state.doc.project();
    const PlacedObject object = *state.view.place.selected;
    float reach = 1.0f;
    if (object.kind == PlacedKind::Wind) {
        const core::WindSource& w = project.wind[object.index].source;
        reach = std::max({reach, w.radiusM, w.coreRadiusM});
    } else {
        const core::ColliderDesc& c = project.colliders[object.index];
        reach = std::max({reach, c.shape == core::ColliderShape::Sphere ? c.radiusM : c.scale});
    }
    const glm::vec3 at = placedPosition(project, object, timeS);
    return core::Bounds{at - glm::vec3(reach), at + glm::vec3(reach)};
}

std::optional<std::string> deleteSelection(EditorState& state) {
    if (!validSelection(state) || state.busy())
        return std::nullopt;
    core::Project project = state.doc.project();
    const PlacedObject object = *state.view.place.selected;
    std::string name;
    if (object.kind == PlacedKind::Wind) {
        name = project.wind[object.index].name;
        project.wind.erase(project.wind.begin() + std::ptrdiff_t(object.index));
    } else {
        name = project.colliders[object.index].name;
        project.colliders.erase(project.colliders.begin() + std::ptrdiff_t(object.index));
    }
    state.view.place.selected.reset();
    apply(state, EditProject{.after = std::move(project), .effect = EditEffect::Regrow,
                             .label = "delete " + name});
    return name;
}

glm::vec3 placedPosition(const core::Project& project, PlacedObject object, float timeS) {
    if (object.kind == PlacedKind::Wind) {
        const core::WindSource& w = project.wind[object.index].source;
        return core::samplePath(w.path, timeS, w.position);
    }
    const core::ColliderDesc& c = project.colliders[object.index];
    return core::samplePath(c.path, timeS, c.position);
}

bool runViewportTool(EditorState& state, const core::OrbitCamera& camera,
                     const ViewportPointer& pointer) {
    if (!state.tools || !state.scene || state.busy())
        return false;
    // A stroke ends when the tool changes under it.
    if (state.view.tool != ViewportTool::Paint && state.tools->painter.active())
        endStroke(state);
    switch (state.view.tool) {
    case ViewportTool::Paint: return runPaint(state, camera, pointer);
    case ViewportTool::Place: return runPlace(state, camera, pointer);
    case ViewportTool::Camera: return false;
    }
    return false;
}

// The keys of `typed` that choose a tool or a gizmo mode ('b' 'g' 'c' 'w' 'e' 'r').
static void applyToolChoiceKeys(EditorState& state, std::string_view typed) {
    for (const char c : typed) {
        switch (c) {
            case 'b':
                state.view.tool = ViewportTool::Paint;
                break;
            case 'g':
                state.view.tool = ViewportTool::Place;
                break;
            case 'c':
                state.view.tool = ViewportTool::Camera;
                break;
            case 'w':
                state.view.place.mode = core::GizmoMode::Translate;
                break;
            case 'e':
                state.view.place.mode = core::GizmoMode::Rotate;
                break;
            case 'r':
                state.view.place.mode = core::GizmoMode::Scale;
                break;
            default:
                break;
        }
    }
}

BrushRadiusRange brushRadiusRange(const EditorState& state) {
    BrushRadiusRange range;
    const float diagonal = state.scene ? glm::length(state.scene->bounds.size()) : 0.0f;
    if (std::isfinite(diagonal) && diagonal > 0.0f) {
        range.min = std::min(range.min, 1e-4f * diagonal);
        range.max = std::max(range.max, diagonal);
    }
    return range;
}

float brushRadius(const EditorState& state) {
    const BrushRadiusRange range = brushRadiusRange(state);
    const float radius = state.view.paint.radiusChosen || !state.scene
                             ? state.view.paint.brush.radiusM
                             : DEFAULT_RADIUS_SHARE * glm::length(state.scene->bounds.size());
    return std::clamp(radius, range.min, range.max);
}

void sizeBrushToScene(EditorState& state) {
    state.view.paint.brush.radiusM = brushRadius(state);
}

void applyToolKeys(EditorState& state, std::string_view typed) {
    applyToolChoiceKeys(state, typed);
    core::BrushSettings& brush = state.view.paint.brush;
    const BrushRadiusRange range = brushRadiusRange(state);
    for (const char c : typed) {
        if (c != '[' && c != ']')
            continue;
        // From the radius the ring shows (before a first choice, the scene's default).
        sizeBrushToScene(state);
        brush.radiusM = std::clamp(c == '[' ? brush.radiusM / 1.25f : brush.radiusM * 1.25f,
                                   range.min, range.max);
        state.view.paint.radiusChosen = true;
    }
}

void drawViewportOverlay(ui::Context& ctx, ui::Rect view, float ppp, const EditorState& s,
                         const core::OrbitCamera& camera, const ViewportPointer& pointer) {
    ui::Painter painter = ctx.painter(ui::Layer::Background, view);
    // Adaptive quality's indicator, in a corner away from the work: the picture is reduced
    // while the user moves or plays (the status bar says by how much).
    // And a field grown again after an edit: what is shown is the field before it meanwhile.
    ui::Vec2 at = view.min + ui::Vec2(8.0f, 6.0f);
    const auto badge = [&](const std::string& text) {
        const std::size_t backdrop = painter.addPlaceholder();
        const ui::Rect label =
            painter.text(at + ui::Vec2(6.0f, 3.0f), text, 12.0f, ui::Color32::rgb(200, 225, 255));
        painter.set(backdrop, ui::RectShape{{at, label.max + ui::Vec2(6.0f, 3.0f)}, 3.0f,
                                            ui::Color32{20, 40, 70, 170}, {}});
        at.y = label.max.y + 8.0f;
    };
    if (!s.transient.status.reduced.empty())
        badge("reduced while moving");
    if (s.transient.status.placingBillboards)
        badge("placing the billboards …");
    if (s.regrowJob) {
        char elapsed[32];
        std::snprintf(elapsed, sizeof elapsed, " … %.0f s", s.regrowJob->elapsedS());
        badge("growing the field after the edit" + std::string(elapsed));
        // Below it, the build's stage: which layer grows now, or the mesh read again.
        if (const std::string stage = s.regrowJob->stage(); !stage.empty())
            badge(stage);
    }
    const auto toPoints = [&](glm::vec2 px) {
        return ui::Vec2(view.min.x + px.x / ppp, view.min.y + px.y / ppp);
    };
    if (s.view.tool == ViewportTool::Paint && s.tools && (pointer.inside || s.tools->painter.active())) {
        if (const auto hit = pickSurface(*s.tools, camera, pointer)) {
            const float radius = brushRadius(s);
            std::vector<ui::Vec2> points;
            for (const glm::vec3 p : core::surfacePointsOnRing(s.tools->bvh(), hit->posWorld,
                                                               hit->normal, radius, RING_POINTS))
                if (auto px = core::projectToPixel(camera, p, pointer.viewportSize))
                    points.push_back(toPoints(*px));
            // What a stroke now would do, Ctrl included: a red ring and a minus sign when it
            // lowers the map, a plus when it raises it.
            const core::BrushMode mode = effectiveBrush(s.view.paint.brush, pointer.ctrl).mode;
            const bool lowers = mode == core::BrushMode::Subtract;
            const ui::Color32 color = lowers ? ui::Color32::rgb(255, 120, 100)
                                             : ui::Color32::rgb(255, 255, 255);
            if (points.size() > 2) {
                painter.path(points, true, ui::Color32::transparent(),
                             {2.5f, ui::Color32{0, 0, 0, 140}});
                painter.path(std::move(points), true, ui::Color32::transparent(), {1.2f, color});
            }
            if (mode == core::BrushMode::Add || lowers)
                if (auto centre = core::projectToPixel(camera, hit->posWorld, pointer.viewportSize)) {
                    const ui::Vec2 c = toPoints(*centre);
                    // A sign 12 points across, outlined like the ring so it reads on any grass.
                    for (const auto& [width, stroke] :
                         {std::pair{4.0f, ui::Color32{0, 0, 0, 160}}, std::pair{2.0f, color}}) {
                        painter.line(c - ui::Vec2(6.0f, 0.0f), c + ui::Vec2(6.0f, 0.0f), {width, stroke});
                        if (!lowers)
                            painter.line(c - ui::Vec2(0.0f, 6.0f), c + ui::Vec2(0.0f, 6.0f),
                                         {width, stroke});
                    }
                }
        }
    }
    if (s.view.tool != ViewportTool::Camera)
        drawObjects(painter, view, ppp, s, camera, pointer.viewportSize);
    if (s.view.tool == ViewportTool::Place && validSelection(s)) {
        const glm::vec3 pivot =
            placedPosition(s.doc.loaded.project, *s.view.place.selected, float(s.view.timeline.timeS()));
        const core::GizmoView gv = gizmoView(camera, pointer);
        const core::GizmoHandle hot =
            s.view.gizmoDrag ? s.view.gizmoDrag->handle()
                        : (pointer.inside ? core::pickGizmoHandle(s.view.place.mode, gv, pivot, pointer.pixel)
                                          : core::GizmoHandle::None);
        for (const core::GizmoPolyline& line : core::gizmoPolylines(s.view.place.mode, gv, pivot)) {
            std::vector<ui::Vec2> points;
            for (const glm::vec2 px : line.pointsPixels)
                points.push_back(toPoints(px));
            const ui::Color32 color = handleColor(line.handle, line.handle == hot);
            const ui::Color32 fill = line.filled ? color : ui::Color32::transparent();
            painter.path(std::move(points), line.closed, fill, {line.filled ? 1.0f : 2.0f, color});
        }
    }
}

}  // namespace grass::editor
