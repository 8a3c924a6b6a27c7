// The side panel's sections: wind, colliders, cameras, light, render settings (layers:
// panels_layers.cpp) (panels.h says which
// edits apply next frame and which re-grow the scene).
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "edit/timeline.h"
#include "app/panel_rows.h"
#include "app/panels.h"
#include "app/setting_widget.h"
#include "project/settings.h"
#include "physics/wind.h"
#include "ui/color_edit.h"
#include "ui/curve_edit.h"
#include "ui/text_edit.h"
#include "ui/ui.h"

namespace grass::editor {

namespace {

void vec3Row(ui::Ui& ui, EditorState& s, const char* label, glm::vec3& v, float speed,
             std::string_view tooltip) {
    const core::settings::UiHint hint{.min = -1e4f, .max = 1e4f, .speed = speed};
    regrow(s, setting_widget::vector(ui, label, v, core::json::ANY_NUMBER, hint)
                  .onHoverText(tooltip));
}

// An object on a keyed path stands where its path says, not at `position`: the row shows and
// edits the path at the timeline's time (the key there, added if none), so a typed position
// moves it as the gizmo would. Unkeyed, it edits `position`.
void positionRow(ui::Ui& ui, EditorState& s, glm::vec3& position, std::vector<core::PathKey>& path) {
    if (path.empty()) {
        vec3Row(ui, s, "position", position, 0.02f,
                ui::withTypingHint("World position x, y, z in metres (-10000 to 10000)"));
        return;
    }
    const float timeS = float(s.view.timeline.timeS());
    const glm::vec3 before = core::samplePath(path, timeS, position);
    glm::vec3 at = before;
    vec3Row(
        ui, s, "keyed position", at, 0.02f,
        ui::withTypingHint(
            "Position on the keyed path at the current time, in metres; an edit keys it there"));
    if (at != before)
        core::setKey(path, timeS, at, 0.5f * float(s.view.timeline.stepS()));
}

}  // namespace

void windSection(ui::Ui& ui, EditorState& s) {
    auto& winds = s.transient.draft.project.wind;
    ui.collapsingHeader("Wind (" + std::to_string(winds.size()) + ")##wind", [&](ui::Ui& section) {
        if (winds.empty())
            section.coloredLabel("no wind sources", section.style().textWeak);
        std::optional<std::size_t> removed;
        for (std::size_t i = 0; i < winds.size(); ++i) {
            section.pushId(std::uint64_t(i));
            section.collapsingHeader(winds[i].name, [&](ui::Ui& body) {
                core::WindDesc& wind = winds[i];
                const auto rows = core::settings::wind();
                for (const std::string_view key : {"kind", "strength", "radius"})
                    regrowRow(body, s, rows, key, wind);
                if (wind.source.kind == core::WindKind::Directional) {
                    for (const std::string_view key : {"direction", "wavelength", "speed", "gust"})
                        regrowRow(body, s, rows, key, wind);
                } else {
                    positionRow(body, s, wind.source.position, wind.source.path);
                    regrowRow(body, s, rows, "core_radius", wind);
                }
                if (body.button("delete")
                        .onHoverText("Delete this wind source (Ctrl+Z brings it back)")
                        .clicked())
                    removed = i;
            });
            section.popId();
        }
        if (removed)
            removeFromDraft(s, PlacedObject{PlacedKind::Wind, *removed});
        // Here as well as in the gizmo's tool: where a user looks for it first.
        if (section.button("add wind")
                .onHoverText(
                    "Add a point wind source above the scene's centre; the gizmo (g) moves it")
                .clicked())
            addWindSource(s);
    });
}

void colliderSection(ui::Ui& ui, EditorState& s) {
    auto& colliders = s.transient.draft.project.colliders;
    ui.collapsingHeader(
        "Colliders (" + std::to_string(colliders.size()) + ")##colliders", [&](ui::Ui& section) {
            if (colliders.empty())
                section.coloredLabel("no colliders", section.style().textWeak);
            std::optional<std::size_t> removed;
            for (std::size_t i = 0; i < colliders.size(); ++i) {
                section.pushId(std::uint64_t(i));
                core::ColliderDesc& c = colliders[i];
                section.horizontal([&](ui::Ui& row) {
                    row.label(c.name + (c.shape == core::ColliderShape::Mesh ? " (mesh)" : ""));
                    if (row.button("delete")
                            .onHoverText("Delete this collider (Ctrl+Z brings it back)")
                            .clicked())
                        removed = i;
                });
                section.indent([&](ui::Ui& body) {
                    positionRow(body, s, c.position, c.path);
                    regrowRow(body, s, core::settings::collider(),
                              c.shape == core::ColliderShape::Sphere ? "radius" : "scale", c);
                });
                section.popId();
            }
            if (removed)
                removeFromDraft(s, PlacedObject{PlacedKind::Collider, *removed});
            section.horizontal([&](ui::Ui& row) {
                if (row.button("add ball")
                        .onHoverText(
                            "Add a ball collider above the scene's centre; the gizmo (g) moves it")
                        .clicked())
                    addBallCollider(s);
                if (row.button("add mesh…")
                        .onHoverText("Add a .gltf/.glb mesh (a rock, a log) as a collider: packed "
                                     "into spheres for the physics, drawn as it is; copied into "
                                     "the project's folder")
                        .clicked())
                    openBrowser(s, BrowsePurpose::AddCollider);
            });
        });
}

// Named camera bookmarks (issue 26 item 5), the project's cameras: go to one, keep the view as a
// new one, rename or delete one; saved with the project, `grass render --camera NAME` renders it.
void cameraSection(ui::Ui& ui, EditorState& s) {
    auto& cameras = s.transient.draft.project.cameras;
    ui.collapsingHeader("Cameras (" + std::to_string(cameras.size()) + ")##cameras", [&](ui::Ui& section) {
        std::optional<std::size_t> removed;
        for (std::size_t i = 0; i < cameras.size(); ++i) {
            section.pushId(std::uint64_t(i));
            core::CameraDesc& camera = cameras[i];
            section.horizontal([&](ui::Ui& row) {
                if (row.button("go").onHoverText("Move the view to this camera").clicked())
                    s.view.cameraRequest = core::OrbitCamera::lookAt(
                        camera.position, camera.target, glm::radians(camera.fovYDeg));
                bool committed = false;
                ui::textEdit(row, "##name", camera.name, 150.0f, &committed)
                    .onHoverText("The camera's name; grass render --camera NAME renders it");
                // The first camera is what grass render draws by default: it stays.
                if (cameras.size() > 1 &&
                    row.button("delete").onHoverText("Delete this camera bookmark").clicked())
                    removed = i;
            });
            section.popId();
        }
        if (removed)
            cameras.erase(cameras.begin() + std::ptrdiff_t(*removed));
        if (cameras.size() < core::MAX_CAMERAS &&
            section.button("keep this view")
                .onHoverText("Save the current view as a new camera bookmark")
                .clicked()) {
            const core::OrbitCamera& view = s.view.camera;
            core::CameraDesc bookmark;
            // Names are unique among cameras (the format refuses twins): the first free "view N".
            for (std::size_t n = cameras.size() + 1;; ++n) {
                bookmark.name = "view " + std::to_string(n);
                if (std::none_of(cameras.begin(), cameras.end(),
                                 [&](const core::CameraDesc& c) { return c.name == bookmark.name; }))
                    break;
            }
            bookmark.position = view.position();
            bookmark.target = view.target;
            bookmark.fovYDeg = glm::degrees(view.fovYRad);
            cameras.push_back(bookmark);
        }
    });
}

// The sun, its shadows (issue 30 item 11) and the sky (issue 26 item 5): live edits, saved in
// the project (/sun, /render).
void lightSection(ui::Ui& ui, EditorState& s) {
    ui.collapsingHeader("Light", [&](ui::Ui& section) {
        core::Project& project = s.transient.draft.project;
        for (const char* key : {"direction", "color", "intensity", "shadows", "shadow_resolution"})
            settingWidget(section, core::settings::sun(), key, project.sun);
        for (const char* key : {"sky_color", "ground_color"})
            settingWidget(section, core::settings::render(), key, project.render);
    });
}

void renderSection(ui::Ui& ui, EditorState& s) {
    ui.collapsingHeader(
        "Render",
        [&](ui::Ui& section) {
            // The cull tests are the view's (a look at what each removes), not the project's.
            ViewOverrides& view = s.view.overrides;
            section.label("Culling (view only)");
            section.indent([&](ui::Ui& body) {
                body.checkbox(view.orientation, "orientation")
                    .onHoverText("Skip blades seen edge-on; view only, not saved (key 1)");
                body.checkbox(view.frustum, "frustum")
                    .onHoverText("Skip blades outside the camera's view; view only, not saved "
                                 "(key 2)");
                body.checkbox(view.distance, "distance")
                    .onHoverText("Thin out distant blades as the project's thinning says; "
                                 "view only, not saved (key 3)");
                body.checkbox(view.occlusion, "occlusion")
                    .onHoverText("Skip blades hidden behind the terrain; view only, not saved "
                                 "(key 4)");
            });
            // Adaptive quality: a reduced picture while moving (core/quality/interaction_quality.h).
            core::InteractionQualitySettings adapt = s.view.quality.settings();
            const bool before = adapt.enabled;
            const float budgetBefore = float(adapt.budgetMs);
            float budget = budgetBefore;
            // Two rows: on one, the box and its unit ran past the side panel's default width.
            section.checkbox(adapt.enabled, "adapt while moving")
                .onHoverText(
                    "Draw a reduced picture while you orbit, paint, drag or play, "
                    "to keep each frame within the budget");
            section.indent([&](ui::Ui& row) {
                ui::dragValueWithEntry(row, "budget ms##budget", budget, 1.0f, 5.0f, 1000.0f, 0)
                    .onHoverText(
                        ui::withTypingHint("Frame time budget while moving, in ms (5 to 1000)"));
            });
            if (adapt.enabled != before || budget != budgetBefore) {
                adapt.budgetMs = budget;
                s.view.quality.setSettings(adapt);
            }
            core::Project& project = s.transient.draft.project;
            settingWidget(section, core::settings::render(), "technique", project.render);
            settingWidget(section, core::settings::lighting(), "model", project.lighting);
            qualityRows(section, s);
        },
        true);
}

}  // namespace grass::editor
