#include "tools/ui_cost.h"

#include <vector>

#include "app/panels.h"
#include "tools/median.h"
#include "tools/ms_since.h"
#include "ui/tessellator.h"

namespace grass::tools {

UiCost measureUi(const ui::FontAtlas& fonts, core::LoadedProject loaded, core::Scene& scene,
                 const render::RenderOptions& options, const render::FrameTimings& timings) {
    editor::EditorState state;
    state.doc.loaded = std::move(loaded);
    state.scene = &scene;
    state.view.options = options;
    state.transient.status.blades = scene.totalBlades();
    state.transient.status.timings = timings;
    ui::Context ctx(fonts);
    ui::Input input;
    input.screenRect = {{0.0f, 0.0f}, {1280.0f, 720.0f}};
    input.hasPointer = true;
    input.pointerPos = {160.0f, 240.0f};
    std::vector<ui::Mesh> meshes;
    std::vector<double> ms;
    UiCost cost;
    // Two frames first: the first lays out with no remembered sizes.
    for (int frame = 0; frame < UI_FRAMES + 2; ++frame) {
        const auto start = Clock::now();
        ctx.beginFrame(input);
        editor::buildPanels(ctx, state);
        const ui::Output& output = ctx.endFrame();
        ui::tessellate(output.shapes, fonts, input.pixelsPerPoint, meshes);
        if (frame >= 2)
            ms.push_back(msSince(start));
        cost.shapes = output.shapes.size();
    }
    cost.ms = median(ms);
    for (const ui::Mesh& mesh : meshes)
        cost.vertices += mesh.vertices.size();
    return cost;
}

}  // namespace grass::tools
