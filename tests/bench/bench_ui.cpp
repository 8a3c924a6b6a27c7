// CPU cost of the editor's UI per frame (issue 7: "the UI costs less than 1 ms of CPU per frame
// for the full editor panel set"): the real panels of grass-editor (editor/app/panels.h) on
// projects/meadow, built, laid out and tessellated exactly as a frame does, without GL (the
// GPU draw of a few thousand UI triangles is not CPU time). Two states: as the editor opens, and
// with every collapsing section open (growth curves, wind, colliders), the most the side panel
// shows. Mouse over the panel, so hover tests run.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <variant>

#include "app/panels.h"
#include "scene/scene.h"
#include "ui/font.h"
#include "ui/tessellator.h"

namespace {

using namespace grass;

struct Editor {
    ui::FontAtlas fonts;
    core::Scene scene;
    editor::EditorState state;
};

Editor& editorOnMeadow() {
    static Editor* editor = [] {
        std::string error;
        auto fonts = ui::FontAtlas::load(ui::FontAtlas::defaultFontPath(), &error);
        auto loaded = core::loadProject(std::string(GRASS_SOURCE_DIR) + "/projects/meadow");
        if (!fonts || !loaded) {
            std::fprintf(stderr, "bench_ui: %s\n",
                         !fonts ? error.c_str() : loaded.error().str().c_str());
            std::exit(1);
        }
        auto scene = core::buildScene(*loaded);
        if (!scene) {
            std::fprintf(stderr, "bench_ui: %s\n", scene.error().str().c_str());
            std::exit(1);
        }
        auto* out = new Editor{std::move(*fonts), std::move(*scene), {}};
        out->state.doc.loaded = std::move(*loaded);
        out->state.scene = &out->scene;
        out->state.view.options = render::renderOptionsFor(out->state.doc.loaded.project, true);
        return out;
    }();
    return *editor;
}

ui::Input frameInput(ui::Vec2 pointer, bool down) {
    ui::Input input;
    input.screenRect = {{0.0f, 0.0f}, {1280.0f, 720.0f}};
    input.pixelsPerPoint = 1.0f;
    input.hasPointer = true;
    input.pointerPos = pointer;
    input.buttonDown[0] = down;
    return input;
}

const ui::Output& frame(ui::Context& ctx, editor::EditorState& state, const ui::Input& input) {
    ctx.beginFrame(input);
    editor::buildPanels(ctx, state);
    return ctx.endFrame();
}

// Opens a collapsing section by clicking its title (found among the painted text).
void clickText(ui::Context& ctx, editor::EditorState& state, std::string_view prefix) {
    const ui::Output& out = frame(ctx, state, frameInput({1000.0f, 700.0f}, false));
    std::optional<ui::Vec2> at;
    for (const ui::ClippedShape& shape : out.shapes)
        if (const auto* text = std::get_if<ui::TextShape>(&shape.shape);
            text && text->text.rfind(prefix, 0) == 0)
            at = text->pos + ui::Vec2(4.0f, 6.0f);
    if (!at) {
        std::fprintf(stderr, "bench_ui: no section \"%.*s\" in the panel\n",
                     static_cast<int>(prefix.size()), prefix.data());
        std::exit(1);
    }
    frame(ctx, state, frameInput(*at, false));
    frame(ctx, state, frameInput(*at, true));
    frame(ctx, state, frameInput(*at, false));
}

void BM_EditorUiFrame(benchmark::State& benchState) {
    Editor& editor = editorOnMeadow();
    ui::Context ctx(editor.fonts);
    if (benchState.range(0) == 1)
        // Bottom first: an open section pushes the ones below it out of the scrolled view.
        for (std::string_view section : {"Colliders", "Wind", "growth curves"})
            clickText(ctx, editor.state, section);
    std::vector<ui::Mesh> meshes;
    std::size_t shapes = 0, vertices = 0;
    const ui::Input input = frameInput({160.0f, 240.0f}, false);  // over the side panel
    for (auto _ : benchState) {
        const ui::Output& out = frame(ctx, editor.state, input);
        ui::tessellate(out.shapes, editor.fonts, input.pixelsPerPoint, meshes);
        shapes = out.shapes.size();
        benchmark::DoNotOptimize(meshes.data());
    }
    vertices = 0;
    for (const ui::Mesh& mesh : meshes)
        vertices += mesh.vertices.size();
    benchState.counters["shapes"] = static_cast<double>(shapes);
    benchState.counters["vertices"] = static_cast<double>(vertices);
}
// 0: the panel as the editor opens; 1: every section open.
BENCHMARK(BM_EditorUiFrame)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
