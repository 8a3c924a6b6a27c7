// The side panel's sections: layers, wind, colliders, render settings (panels.h says which
// edits apply next frame and which re-grow the scene).
#include <array>
#include <cstdint>
#include <string>

#include "edit/timeline.h"
#include "app/panels.h"
#include "physics/wind.h"
#include "ui/color_edit.h"
#include "ui/curve_edit.h"
#include "ui/text_edit.h"
#include "ui/ui.h"

namespace grass::editor {

namespace {

// A value the renderer reads every frame changed: only the project needs saving.
void live(EditorState& s, const ui::Response& r) {
    if (r.changed())
        s.dirty = true;
}
// A value the scene is grown from changed: re-grow once the edit ends.
void regrow(EditorState& s, const ui::Response& r) {
    if (r.changed())
        s.dirty = s.rebuildPending = true;
}

// [min] [max] label on one row; min stays ≤ max.
void rangeRow(ui::Ui& ui, EditorState& s, const char* label, float& min, float& max, float speed,
              float lo, float hi, int decimals) {
    ui.withId(label, [&](ui::Ui& inner) {
        inner.horizontal([&](ui::Ui& row) {
            row.pushId("min");
            regrow(s, row.dragValue("", min, speed, lo, max, decimals));
            row.popId();
            regrow(s, row.dragValue(label, max, speed, min, hi, decimals));
        });
    });
}

void vec3Row(ui::Ui& ui, EditorState& s, const char* label, glm::vec3& v, float speed) {
    ui.withId(label, [&](ui::Ui& inner) {
        inner.horizontal([&](ui::Ui& row) {
            for (int c = 0; c < 3; ++c) {
                row.pushId(std::uint64_t(c));
                regrow(s, row.dragValue(c == 2 ? label : "", v[c], speed, -1e4f, 1e4f, 2));
                row.popId();
            }
        });
    });
}

// An object on a keyed path stands where its path says, not at `position`: the row shows and
// edits the path at the timeline's time (the key there, added if none), so a typed position
// moves it as the gizmo would. Unkeyed, it edits `position`.
void positionRow(ui::Ui& ui, EditorState& s, glm::vec3& position, std::vector<core::PathKey>& path) {
    if (path.empty()) {
        vec3Row(ui, s, "position", position, 0.02f);
        return;
    }
    const float timeS = float(s.timeline.timeS());
    const glm::vec3 before = core::samplePath(path, timeS, position);
    glm::vec3 at = before;
    vec3Row(ui, s, "position (key at now)", at, 0.02f);
    if (at != before)
        core::setKey(path, timeS, at, 0.5f * float(s.timeline.stepS()));
}

void growthCurves(ui::Ui& ui, EditorState& s, core::GrowthCurves& c) {
    std::array<float, 3> soil{c.gy0, c.gy1, c.gy2};
    std::array<float, 5> width{c.wy0, c.wy1, c.wy2, c.wy3, c.wy4};
    std::array<float, 5> height{c.hy0, c.hy1, c.hy2, c.hy3, c.hy4};
    const ui::Vec2 size{ui.availableWidth() - 8.0f, 80.0f};
    regrow(s, ui::bezierCurveEdit(ui, "soil → growth  f1(g)", soil, size));
    regrow(s, ui::twoPieceCurveEdit(ui, "light → width  f2(l)", width, size));
    regrow(s, ui::twoPieceCurveEdit(ui, "light → height  f3(l)", height, size));
    c.gy0 = soil[0], c.gy1 = soil[1], c.gy2 = soil[2];
    c.wy0 = width[0], c.wy1 = width[1], c.wy2 = width[2], c.wy3 = width[3], c.wy4 = width[4];
    c.hy0 = height[0], c.hy1 = height[1], c.hy2 = height[2], c.hy3 = height[3],
    c.hy4 = height[4];
}

void layerBody(ui::Ui& ui, EditorState& s, std::size_t index) {
    core::GrassLayer& layer = s.loaded.project.layers[index];
    core::LayerField* field =
        s.scene && index < s.scene->layers.size() ? &s.scene->layers[index] : nullptr;
    int shape = int(layer.shape);
    if (const ui::Response r = ui.comboBox("shape", shape, core::bladeShapeNames()); r.changed()) {
        layer.shape = core::BladeShape(shape);
        if (field)
            field->shape = layer.shape;
        live(s, r);
    }
    core::BladeRanges& b = layer.scatter.blade;
    rangeRow(ui, s, "height m", b.heightMin, b.heightMax, 0.005f, 0.01f, 5.0f, 3);
    rangeRow(ui, s, "width m", b.widthMin, b.widthMax, 0.0005f, 0.001f, 0.2f, 4);
    rangeRow(ui, s, "stiffness", b.stiffnessMin, b.stiffnessMax, 0.5f, 1.0f, 1000.0f, 1);
    regrow(s, ui::sliderWithEntry(ui, "density", layer.scatter.density, 1.0f, 5000.0f,
                                  {.logarithmic = true, .decimals = 0}));
    if (const ui::Response r = ui::colorEdit(ui, "root colour", layer.rootColor, true);
        r.changed()) {
        if (field)
            field->rootColor = layer.rootColor;
        live(s, r);
    }
    if (const ui::Response r = ui::colorEdit(ui, "tip colour", layer.tipColor, true);
        r.changed()) {
        if (field)
            field->tipColor = layer.tipColor;
        live(s, r);
    }
    regrow(s, ui.checkbox(layer.growth.enabled, "growth model (soil, light)"));
    if (layer.growth.enabled)
        ui.collapsingHeader("growth curves", [&](ui::Ui& curves) {
            growthCurves(curves, s, layer.growth.curves);
        });
}

}  // namespace

void layerSection(ui::Ui& ui, EditorState& s) {
    auto& layers = s.loaded.project.layers;
    ui.collapsingHeader(
        "Layers (" + std::to_string(layers.size()) + ")",
        [&](ui::Ui& section) {
            for (std::size_t i = 0; i < layers.size(); ++i) {
                section.pushId(std::uint64_t(i));
                section.collapsingHeader(
                    layers[i].name, [&](ui::Ui& body) { layerBody(body, s, i); }, i == 0);
                section.popId();
            }
        },
        true);
}

void windSection(ui::Ui& ui, EditorState& s) {
    auto& winds = s.loaded.project.wind;
    ui.collapsingHeader("Wind (" + std::to_string(winds.size()) + ")", [&](ui::Ui& section) {
        if (winds.empty())
            section.coloredLabel("no wind sources", section.style().textWeak);
        static constexpr std::array<const char*, 3> KINDS{"directional", "point", "vortex"};
        for (std::size_t i = 0; i < winds.size(); ++i) {
            section.pushId(std::uint64_t(i));
            section.collapsingHeader(winds[i].name, [&](ui::Ui& body) {
                core::WindSource& w = winds[i].source;
                int kind = int(w.kind);
                if (const ui::Response r = body.comboBox("kind", kind, KINDS); r.changed()) {
                    w.kind = core::WindKind(kind);
                    regrow(s, r);
                }
                regrow(s, body.dragValue("strength m/s", w.strength, 0.01f, 0.0f, 100.0f, 2));
                regrow(s, body.dragValue("radius m (0: all)", w.radiusM, 0.05f, 0.0f, 1e4f, 2));
                if (w.kind == core::WindKind::Directional) {
                    vec3Row(body, s, "direction", w.direction, 0.01f);
                    regrow(s, body.dragValue("wavelength m", w.wavelengthM, 0.05f, 0.0f, 1e3f, 2));
                    regrow(s, body.dragValue("speed m/s", w.speedMps, 0.02f, 0.0f, 100.0f, 2));
                    regrow(s, body.slider("gust", w.gust, 0.0f, 1.0f));
                } else {
                    positionRow(body, s, w.position, w.path);
                    regrow(s, body.dragValue("core radius m", w.coreRadiusM, 0.02f, 0.0f, 1e3f, 2));
                }
            });
            section.popId();
        }
    });
}

void colliderSection(ui::Ui& ui, EditorState& s) {
    auto& colliders = s.loaded.project.colliders;
    ui.collapsingHeader(
        "Colliders (" + std::to_string(colliders.size()) + ")", [&](ui::Ui& section) {
            if (colliders.empty())
                section.coloredLabel("no colliders", section.style().textWeak);
            for (std::size_t i = 0; i < colliders.size(); ++i) {
                section.pushId(std::uint64_t(i));
                core::ColliderDesc& c = colliders[i];
                section.label(c.name + (c.shape == core::ColliderShape::Mesh ? " (mesh)" : ""));
                section.indent([&](ui::Ui& body) {
                    positionRow(body, s, c.position, c.path);
                    if (c.shape == core::ColliderShape::Sphere)
                        regrow(s, body.dragValue("radius m", c.radiusM, 0.01f, 0.01f, 100.0f, 2));
                    else
                        regrow(s, body.dragValue("scale", c.scale, 0.01f, 0.001f, 1000.0f, 3));
                });
                section.popId();
            }
        });
}

void renderSection(ui::Ui& ui, EditorState& s) {
    ui.collapsingHeader(
        "Render",
        [&](ui::Ui& section) {
            // The cull tests are the view's (a look at what each removes), not the project's.
            ViewOverrides& view = s.view;
            section.label("Culling (view only)");
            section.indent([&](ui::Ui& body) {
                body.checkbox(view.orientation, "orientation");
                body.checkbox(view.frustum, "frustum");
                body.checkbox(view.distance, "distance");
                body.checkbox(view.occlusion, "occlusion");
            });
            static constexpr std::array<const char*, 4> TECHNIQUES{"blades", "billboards",
                                                                   "hybrid", "growth"};
            core::Project& project = s.loaded.project;
            int technique = int(project.render.technique);
            if (const ui::Response r = section.comboBox("technique", technique, TECHNIQUES);
                r.changed())
                project.render.technique = core::GrassTechnique(technique);
            static constexpr std::array<const char*, 2> LIGHTING{"grass", "simple"};
            int lighting = int(project.lighting.model);
            if (const ui::Response r = section.comboBox("lighting", lighting, LIGHTING);
                r.changed())
                project.lighting.model = core::LightingModel(lighting);
            qualityRows(section, s);
        },
        true);
}

}  // namespace grass::editor
