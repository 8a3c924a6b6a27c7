// The side panel's Layers section (issue 27): each layer a species, added, duplicated, removed,
// renamed and reordered here, with its blades, colours, growth and placement rules (the names of
// the surface's glTF nodes, meshes and materials as a checklist, slope, altitude, clearance).
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "app/panel_rows.h"
#include "app/panels.h"
#include "edit/layer_list.h"
#include "mesh/mesh_parts.h"
#include "scatter/placement_rules.h"
#include "scene/bending_cues.h"
#include "project/settings.h"
#include "ui/curve_edit.h"
#include "ui/text_edit.h"
#include "ui/ui.h"

namespace grass::editor {

namespace {

void growthCurves(ui::Ui& ui, EditorState& s, core::GrowthCurves& c) {
    std::array<float, 3> soil{c.gy0, c.gy1, c.gy2};
    std::array<float, 5> width{c.wy0, c.wy1, c.wy2, c.wy3, c.wy4};
    std::array<float, 5> height{c.hy0, c.hy1, c.hy2, c.hy3, c.hy4};
    const ui::Vec2 size{ui.availableWidth() - 8.0f, 80.0f};
    regrow(s, ui::bezierCurveEdit(ui, "soil → growth  f1(g)", soil, size)
                  .onHoverText("How growth responds to the soil map's value, both 0 to 1; "
                               "drag a handle up or down"));
    regrow(s, ui::twoPieceCurveEdit(ui, "light → width  f2(l)", width, size)
                  .onHoverText("How blade width responds to the light map's value, both 0 to 1; "
                               "drag a handle up or down"));
    regrow(s, ui::twoPieceCurveEdit(ui, "light → height  f3(l)", height, size)
                  .onHoverText("How blade height responds to the light map's value, both 0 to 1; "
                               "drag a handle up or down"));
    c.gy0 = soil[0], c.gy1 = soil[1], c.gy2 = soil[2];
    c.wy0 = width[0], c.wy1 = width[1], c.wy2 = width[2], c.wy3 = width[3], c.wy4 = width[4];
    c.hy0 = height[0], c.hy1 = height[1], c.hy2 = height[2], c.hy3 = height[3],
    c.hy4 = height[4];
}

// A name of the surface's parts in one of a rule's lists: a checkbox that adds or removes it.
bool nameToggle(ui::Ui& row, std::vector<std::string>& names, const std::string& name,
                const char* label, std::string_view tooltip) {
    const auto at = std::find(names.begin(), names.end(), name);
    bool on = at != names.end();
    if (!row.checkbox(on, label).onHoverText(tooltip).changed())
        return false;
    if (on)
        names.push_back(name);
    else
        names.erase(at);
    return true;
}

// The rules of a layer: the surface's names as a checklist (grow only on, never on, keep clear
// of), then the windows and the clearance.
void rulesBody(ui::Ui& ui, EditorState& s, core::PlacementRules& rules) {
    const std::vector<std::string> names =
        s.scene ? core::partNames(s.scene->mesh) : std::vector<std::string>{};
    if (names.empty()) {
        ui.wrappedColoredLabel("this surface names no parts (a procedural shape)",
                               ui.style().textWeak);
    } else {
        ui.collapsingHeader("names (" + std::to_string(names.size()) + ")##names", [&](ui::Ui& list) {
            list.coloredLabel("only  never  clear of", list.style().textWeak);
            for (std::size_t i = 0; i < names.size(); ++i) {
                list.pushId(std::uint64_t(i));
                list.horizontal([&](ui::Ui& row) {
                    bool changed = nameToggle(row, rules.include, names[i], "##only",
                                              "Grow only on the parts this name marks (and on "
                                              "the other names ticked here)");
                    changed |= nameToggle(row, rules.exclude, names[i], "##never",
                                          "Never grow on the parts this name marks");
                    changed |= nameToggle(row, rules.clearOf, names[i], "##clear",
                                          "Keep the clearance distance of bare ground around "
                                          "the parts this name marks");
                    row.label(names[i]);
                    if (changed)
                        s.transient.draft.regrow = true;
                });
                list.popId();
            }
        });
    }
    const auto rows = core::settings::rules();
    for (const std::string_view key :
         {"slope", "slope_soft", "altitude", "altitude_soft", "clearance", "clear_colliders"})
        regrowRow(ui, s, rows, key, rules);
}

void layerBody(ui::Ui& ui, EditorState& s, std::size_t index) {
    const auto rows = core::settings::layer();
    core::GrassLayer& layer = s.transient.draft.project.layers[index];
    core::LayerField* field =
        s.scene && index < s.scene->layers.size() ? &s.scene->layers[index] : nullptr;
    // Shape and colours reach the drawn field at once; the rest re-grows it.
    if (settingWidget(ui, rows, "shape", layer).changed() && field)
        core::takeLayerLook(*field, layer);
    for (const std::string_view key : {"height", "width", "stiffness"})
        regrowRow(ui, s, core::settings::blade(), key, layer.scatter.blade);
    // The format takes any density; the scene refuses one that would grow more blades than a
    // scene may hold (all its layers together, as core::buildScene counts them): a typed one is
    // refused in its box, with the count, and a dragged one is not taken, said in the status
    // bar (before, the slider's lowest step on a 60 km mesh asked for 1e10 blades: the field
    // could not grow, and the project kept a density it could not grow from).
    const double area = s.scene ? s.scene->area : 0.0;
    double otherLayersBlades = 0.0;
    for (std::size_t other = 0; other < s.transient.draft.project.layers.size(); ++other)
        if (other != index)
            otherLayersBlades +=
                core::estimateLayerBlades(s.transient.draft.project.layers[other].scatter, area);
    double lastAsked = 0.0;
    const auto densityLimit = [&](double asked) -> std::string {
        lastAsked = asked;
        core::ScatterParams scatter = layer.scatter;
        scatter.density = static_cast<float>(asked);
        const double blades = core::estimateLayerBlades(scatter, area) + otherLayersBlades;
        // Written so that a NaN estimate is refused too.
        if (blades <= core::MAX_SCENE_BLADES)
            return {};
        char reason[160];
        std::snprintf(reason, sizeof reason,
                      "would grow %.3g blades on this %.3g m² surface; a scene holds at most %.3g",
                      blades, area, core::MAX_SCENE_BLADES);
        return reason;
    };
    std::string refusedDrag;
    regrow(s, settingWidget(ui, rows, "density", layer, nullptr, densityLimit, &refusedDrag));
    if (!refusedDrag.empty()) {
        char asked[64];
        std::snprintf(asked, sizeof asked, "density not changed: %.3g /m² ", lastAsked);
        s.transient.message = asked + refusedDrag;
        s.transient.warningMessage = s.transient.message;
    }
    for (const std::string_view key : {"root_color", "tip_color"})
        if (settingWidget(ui, rows, key, layer).changed() && field)
            core::takeLayerLook(*field, layer);
    regrowRow(ui, s, core::settings::growth(), "enabled", layer.growth);
    if (layer.growth.enabled)
        ui.collapsingHeader("growth curves", [&](ui::Ui& curves) {
            growthCurves(curves, s, layer.growth.curves);
            regrowRow(curves, s, core::settings::growth(), "stem_tip_width", layer.growth);
        });
    // How fast a path mown with the brush's cut map grows back (issue 30 item 10).
    regrowRow(ui, s, rows, "regrow_rate", layer);
    const bool open = core::rulesAreOpen(layer.rules);
    ui.collapsingHeader(open ? "placement rules##rules" : "placement rules (on)##rules",
                        [&](ui::Ui& rules) { rulesBody(rules, s, layer.rules); });
    const bool bent = !core::bendingIsOff(layer.bending);
    ui.collapsingHeader(bent ? "bending (on)##bending" : "bending##bending", [&](ui::Ui& bending) {
        for (const std::string_view key : {"slope", "neighbours", "neighbour_radius", "sway"})
            regrowRow(bending, s, core::settings::bending(), key, layer.bending);
    });
}


// A change to the list of layers, done after the loop that draws them.
struct LayerAction {
    enum class Kind { None, Duplicate, Remove, Up, Down } kind = Kind::None;
    std::size_t index = 0;
};

// The row over a layer's settings: its name (a rename is refused when another layer has it),
// move up and down, duplicate, remove.
void layerControls(ui::Ui& ui, EditorState& s, std::size_t index, LayerAction& action) {
    core::Project& project = s.transient.draft.project;
    const std::size_t count = project.layers.size();
    {
        // Typed into a buffer and taken when the entry ends: the project never holds two layers
        // of one name, and a rename is one undo step.
        std::string& name = project.layers[index].name;
        LayerNameEntry& entry = s.transient.layerNames[index];
        if (!entry.editing)
            entry.text = name;
        bool committed = false;
        entry.editing = ui::textEdit(ui, "name##layername", entry.text, 160.0f, &committed)
                            .onHoverText("The layer's name, unique among layers; Enter renames")
                            .hasFocus();
        if (committed && entry.text != name && !core::renameLayer(project, index, entry.text)) {
            s.transient.message = entry.text.empty()
                                      ? "a layer needs a name"
                                      : "another layer is named \"" + entry.text + "\"";
            entry.text = name;
        }
        // The live field's layer takes the name at once, so the maps painted on it follow it
        // through a re-grow (core::matchLayers).
        if (s.scene && index < s.scene->layers.size())
            s.scene->layers[index].name = name;
    }
    ui.horizontal([&](ui::Ui& row) {
        using Kind = LayerAction::Kind;
        if (index > 0 && row.button("up").onHoverText("Move this layer up the list").clicked())
            action = {Kind::Up, index};
        if (index + 1 < count &&
            row.button("down").onHoverText("Move this layer down the list").clicked())
            action = {Kind::Down, index};
        if (count < core::MAX_LAYERS &&
            row.button("duplicate").onHoverText("Duplicate this layer: its settings, rules and maps")
                .clicked())
            action = {Kind::Duplicate, index};
        if (count > 1 &&
            row.button("remove").onHoverText("Remove this layer (Ctrl+Z brings it back)").clicked())
            action = {Kind::Remove, index};
    });
}

// A duplicate starts from its source's maps as they are now, painted or not yet saved: those
// wait under the copy's name until the re-grow gives it its field.
void carryMapsIntoCopy(EditorState& s, std::size_t source, const std::string& copyName) {
    if (!s.scene || source >= s.scene->layers.size())
        return;
    for (const auto& [layer, map] : s.doc.paintedMaps)
        if (layer == source)
            s.doc.waitingMaps[{copyName, map}] =
                core::layerMap(s.scene->layers[source].source.maps, map);
}

void applyLayerAction(EditorState& s, const LayerAction& action) {
    core::Project& project = s.transient.draft.project;
    using Kind = LayerAction::Kind;
    bool done = false;
    switch (action.kind) {
    case Kind::None: return;
    case Kind::Duplicate:
        done = core::duplicateLayer(project, action.index);
        if (done)
            carryMapsIntoCopy(s, action.index, project.layers[action.index + 1].name);
        break;
    case Kind::Remove: done = core::removeLayer(project, action.index); break;
    case Kind::Up: done = core::moveLayer(project, action.index, true); break;
    case Kind::Down: done = core::moveLayer(project, action.index, false); break;
    }
    if (!done)
        return;
    s.transient.draft.regrow = true;
    // The brush keeps painting the layer it painted, wherever it moved.
    std::size_t& brush = s.view.paint.layer;
    if (action.kind == Kind::Up && brush == action.index)
        brush = action.index - 1;
    else if (action.kind == Kind::Up && brush == action.index - 1)
        brush = action.index;
    else if (action.kind == Kind::Down && brush == action.index)
        brush = action.index + 1;
    else if (action.kind == Kind::Down && brush == action.index + 1)
        brush = action.index;
    else if (action.kind == Kind::Remove && brush > action.index)
        --brush;
    brush = std::min(brush, project.layers.size() - 1);
}

}  // namespace

void layerSection(ui::Ui& ui, EditorState& s) {
    auto& layers = s.transient.draft.project.layers;
    ui.collapsingHeader(
        "Layers (" + std::to_string(layers.size()) + ")##layers",
        [&](ui::Ui& section) {
            LayerAction action;
            for (std::size_t i = 0; i < layers.size(); ++i) {
                section.pushId(std::uint64_t(i));
                section.collapsingHeader(
                    layers[i].name + "##layer",
                    [&](ui::Ui& body) {
                        layerControls(body, s, i, action);
                        layerBody(body, s, i);
                    },
                    i == 0);
                section.popId();
            }
            applyLayerAction(s, action);
            if (layers.size() < core::MAX_LAYERS &&
                section.button("add layer")
                    .onHoverText("Add a grass layer (a species) with default settings, growing "
                                 "everywhere; paint or give it rules to place it")
                    .clicked() &&
                core::addLayer(s.transient.draft.project))
                s.transient.draft.regrow = true;
        },
        true);
}

}  // namespace grass::editor
