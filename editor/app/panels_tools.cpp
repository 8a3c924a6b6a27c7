// The side panel's tool section (brush and gizmo settings, adding and removing wind sources and
// colliders, keying their motion) and the timeline (play, pause, step, loop, speed, scrub).
#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "app/panels.h"
#include "scene/scene.h"
#include "ui/text_edit.h"
#include "ui/ui.h"

namespace grass::editor {

namespace {

void brushSettings(ui::Ui& ui, EditorState& s) {
    core::Project& project = s.transient.draft.project;
    std::vector<std::string> layers;
    for (const core::GrassLayer& layer : project.layers)
        layers.push_back(layer.name);
    int layer = int(s.view.paint.layer);
    if (!layers.empty() && ui.comboBox("layer", layer, layers)
                               .onHoverText("The grass layer the brush paints")
                               .changed())
        s.view.paint.layer = std::size_t(layer);
    int map = int(s.view.paint.map);
    if (ui.comboBox("map", map, core::LAYER_MAP_NAMES)
            .onHoverText("Which of the layer's maps the brush paints: density, soil, light or cut (the height blades are mown to)")
            .changed())
        s.view.paint.map = core::LayerMap(map);
    ui.horizontal([&](ui::Ui& row) {
        row.checkbox(s.view.paint.showMap, "show map")
            .onHoverText("Colour the surface by the map being painted: purple 0, yellow 1");
        if (row.button("import…")
                .onHoverText("Replace this map with a picture (PNG, EXR, TIFF, JPEG); one undo step")
                .clicked())
            openBrowser(s, BrowsePurpose::ImportMap);
        if (row.button("export…")
                .onHoverText("Write this map as it is now to a PNG (16-bit), EXR or TIFF file")
                .clicked())
            openBrowser(s, BrowsePurpose::ExportMap);
    });
    core::BrushSettings& b = s.view.paint.brush;
    ui.horizontal([&](ui::Ui& row) {
        row.radioValue(b.mode, core::BrushMode::Add, "add")
            .onHoverText("The brush raises the map's value; hold Ctrl while painting to subtract");
        row.radioValue(b.mode, core::BrushMode::Subtract, "subtract")
            .onHoverText("The brush lowers the map's value; hold Ctrl while painting to add");
        row.radioValue(b.mode, core::BrushMode::Smooth, "smooth")
            .onHoverText("The brush moves the map's value toward the mean of its neighbours");
        row.radioValue(b.mode, core::BrushMode::Set, "set")
            .onHoverText("The brush moves the map's value toward the set value; "
                         "Ctrl paints toward 1 minus it");
    });
    // The radius the ring shows: before the user chooses one, the scene's default (the panel
    // read 1.00 m while the ring on a 1 m box had a radius of 9 cm, and [ started from 1 m).
    sizeBrushToScene(s);
    const BrushRadiusRange radii = brushRadiusRange(s);
    char radiusTip[128];
    std::snprintf(radiusTip, sizeof radiusTip,
                  "Brush radius in metres (%g to %g on this scene); [ and ] shrink and grow it",
                  double(radii.min), double(radii.max));
    if (ui::sliderWithEntry(ui, "radius  [ ]", b.radiusM, radii.min, radii.max,
                            {.logarithmic = true, .decimals = 2})
            .onHoverText(ui::withTypingHint(radiusTip))
            .changed())
        s.view.paint.radiusChosen = true;
    ui::sliderWithEntry(ui, "strength", b.strength, 0.0f, 1.0f, {.decimals = 2})
        .onHoverText(ui::withTypingHint("How much each dab changes the map (0 to 1)"));
    static constexpr std::array<const char*, 3> FALLOFFS{"smooth", "linear", "constant"};
    int falloff = int(b.falloff);
    if (ui.comboBox("falloff", falloff, FALLOFFS)
            .onHoverText("How the brush's effect fades from its centre to its edge")
            .changed())
        b.falloff = core::BrushFalloff(falloff);
    if (b.mode == core::BrushMode::Set)
        ui::sliderWithEntry(ui, "set value", b.setValue, 0.0f, 1.0f, {.decimals = 2})
            .onHoverText(ui::withTypingHint("The value the set mode paints toward (0 to 1)"));
    ui.wrappedColoredLabel("Ctrl inverts; right-drag orbits", ui.style().textWeak);
}

void placeSettings(ui::Ui& ui, EditorState& s) {
    core::Project& project = s.transient.draft.project;
    ui.horizontal([&](ui::Ui& row) {
        row.radioValue(s.view.place.mode, core::GizmoMode::Translate, "move (w)")
            .onHoverText("The gizmo moves the selected wind source or collider (w)");
        row.radioValue(s.view.place.mode, core::GizmoMode::Rotate, "rotate (e)")
            .onHoverText("The gizmo turns the selected wind source; colliders do not turn (e)");
        row.radioValue(s.view.place.mode, core::GizmoMode::Scale, "scale (r)")
            .onHoverText("The gizmo resizes the selected wind source or collider uniformly (r)");
    });
    ui.checkbox(s.view.place.snap.enabled, "snap (or hold Ctrl)")
        .onHoverText("Gizmo drags snap to fixed steps; holding Ctrl while dragging snaps too");
    if (s.view.place.snap.enabled) {
        ui::dragValueWithEntry(ui, "step m", s.view.place.snap.translateStepM, 0.01f, 0.001f,
                               100.0f, 3)
            .onHoverText(ui::withTypingHint("Snap step for moving, in metres (0.001 to 100)"));
        ui::dragValueWithEntry(ui, "step °", s.view.place.snap.rotateStepDeg, 0.5f, 0.5f, 90.0f, 1)
            .onHoverText(ui::withTypingHint("Snap step for turning, in degrees (0.5 to 90)"));
    }
    ui.horizontal([&](ui::Ui& row) {
        if (row.button("add wind")
                .onHoverText("Add a point wind source above the scene's centre and select it")
                .clicked())
            addWindSource(s);
        if (row.button("add ball")
                .onHoverText("Add a ball collider above the scene's centre and select it")
                .clicked())
            addBallCollider(s);
    });
    if (!s.view.place.selected) {
        ui.coloredLabel("click a marker to select it", ui.style().textWeak);
        return;
    }
    const PlacedObject o = *s.view.place.selected;
    const bool isWind = o.kind == PlacedKind::Wind;
    if (o.index >= (isWind ? project.wind.size() : project.colliders.size())) {
        s.view.place.selected.reset();  // removed (an undo, a delete): nothing is selected any more
        return;
    }
    std::vector<core::PathKey>& path =
        isWind ? project.wind[o.index].source.path : project.colliders[o.index].path;
    const std::string& name = isWind ? project.wind[o.index].name : project.colliders[o.index].name;
    ui.label("selected: " + name + " (" + std::to_string(path.size()) + " keys)");
    const float timeS = float(s.view.timeline.timeS());
    const float tolerance = 0.5f * float(s.view.timeline.stepS());
    ui.horizontal([&](ui::Ui& row) {
        if (row.button("key here")
                .onHoverText("Key the selected object's position at the current time")
                .clicked()) {
            core::setKey(path, timeS, placedPosition(project, o, timeS), tolerance);
            s.transient.draft.regrow = true;
        }
        if (row.button("remove key")
                .onHoverText("Remove the selected object's key at the current time, if any")
                .clicked() &&
            core::removeKey(path, timeS, tolerance))
            s.transient.draft.regrow = true;
        if (row.button("delete")
                .onHoverText("Delete the selected wind source or collider (Delete)")
                .clicked())
            removeFromDraft(s, o);
    });
}

}  // namespace

// An added point wind: the strength that holds default blades (core::BladeRanges) about a
// third of a metre off their rest tips at the source (strength / stiffness, 20 / 60 s⁻¹: the
// meadow's breeze), scaled with the field's blades; a core a tenth of its reach (the meadow's
// 1 m core of a 10 m reach), inside which the wind fades to nothing at the centre.
constexpr float POINT_WIND_STRENGTH = 20.0f;
constexpr float POINT_WIND_CORE_SHARE = 0.1f;

glm::vec3 newObjectPosition(const EditorState& s) {
    return s.scene
               ? s.scene->bounds.centre() + glm::vec3(0.0f, 0.5f * s.scene->bounds.size().y, 0.0f)
               : glm::vec3(0.0f);
}

void addWindSource(EditorState& s) {
    core::Project& project = s.transient.draft.project;
    core::WindDesc wind;
    wind.name = "wind " + std::to_string(project.wind.size() + 1);
    wind.source.kind = core::WindKind::Point;
    wind.source.position = newObjectPosition(s);
    wind.source.radiusM = s.scene ? 0.25f * glm::length(s.scene->bounds.size()) : 5.0f;
    wind.source.coreRadiusM = POINT_WIND_CORE_SHARE * wind.source.radiusM;
    // A wind that visibly bends the field's blades, whatever their size: the default 1 m/s
    // held the meadow's blades 2 cm off their rest, and a 60 km sphere's 3 km blades not at
    // all (core::physicsScaleFor).
    float scale = 0.0f;
    for (const core::GrassLayer& layer : project.layers)
        scale += core::physicsScaleFor(layer.scatter.blade);
    wind.source.strength = POINT_WIND_STRENGTH *
                           (project.layers.empty() ? 1.0f : scale / float(project.layers.size()));
    project.wind.push_back(wind);
    s.view.place.selected = PlacedObject{PlacedKind::Wind, project.wind.size() - 1};
    s.transient.draft.regrow = true;
}

void addBallCollider(EditorState& s) {
    core::Project& project = s.transient.draft.project;
    core::ColliderDesc ball;
    ball.name = "ball " + std::to_string(project.colliders.size() + 1);
    ball.position = newObjectPosition(s);
    ball.radiusM = s.scene ? 0.05f * glm::length(s.scene->bounds.size()) : 0.5f;
    project.colliders.push_back(ball);
    s.view.place.selected = PlacedObject{PlacedKind::Collider, project.colliders.size() - 1};
    s.transient.draft.regrow = true;
}

void removeFromDraft(EditorState& s, PlacedObject o) {
    core::Project& project = s.transient.draft.project;
    const bool isWind = o.kind == PlacedKind::Wind;
    if (o.index >= (isWind ? project.wind.size() : project.colliders.size()))
        return;
    if (isWind)
        project.wind.erase(project.wind.begin() + std::ptrdiff_t(o.index));
    else
        project.colliders.erase(project.colliders.begin() + std::ptrdiff_t(o.index));
    // The selection keeps its object: gone with it, or one place down after it.
    std::optional<PlacedObject>& selected = s.view.place.selected;
    if (selected && selected->kind == o.kind) {
        if (selected->index == o.index)
            selected.reset();
        else if (selected->index > o.index)
            --selected->index;
    }
    s.transient.draft.regrow = true;
}

void toolSection(ui::Ui& ui, EditorState& s) {
    ui.collapsingHeader(
        "Tools",
        [&](ui::Ui& section) {
            section.horizontal([&](ui::Ui& row) {
                row.radioValue(s.view.tool, ViewportTool::Camera, "camera (c)")
                    .onHoverText("Left-drag orbits, Shift+drag or middle-drag pans, "
                                 "the wheel zooms (c)");
                row.radioValue(s.view.tool, ViewportTool::Paint, "brush (b)")
                    .onHoverText("Left-drag paints a layer's map on the ground (b)");
                row.radioValue(s.view.tool, ViewportTool::Place, "gizmo (g)")
                    .onHoverText("Click a wind source or collider to select it, "
                                 "drag its gizmo to place it (g)");
            });
            if (s.view.tool == ViewportTool::Paint)
                brushSettings(section, s);
            else if (s.view.tool == ViewportTool::Place)
                placeSettings(section, s);
        },
        true);
}

}  // namespace grass::editor
