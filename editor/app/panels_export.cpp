// File → Export…: where to, which format and LOD, then a progress bar while the worker writes.
#include <array>

#include "app/autosave.h"
#include "app/panels.h"
#include "ui/text_edit.h"
#include "ui/ui.h"
#include "ui/window.h"

namespace grass::editor {

void startExport(EditorState& s) {
    if (!s.scene || s.busy())
        return;
    // An export of the field before the edit would not be the project saved beside it.
    if (s.regrowing() || s.rebuildPending) {
        s.exportWhenGrown = true;
        s.transient.message = "the export starts once the field has grown";
        return;
    }
    s.exportWhenGrown = false;
    core::ExportOptions options;
    options.format = core::ExportFormat(s.transient.exportFormat);
    options.lod = options.format != core::ExportFormat::Raw ? s.transient.exportLod : 0;
    std::filesystem::path dir(s.transient.exportDir);
    if (dir.is_relative() && !s.doc.loaded.folder.empty())
        dir = s.doc.loaded.folder / dir;
    options.outDir = dir;
    // An export reads what already lies in its folder (the clean-up of files no longer named):
    // whatever happens there, unsaved work is in the autosave first.
    if (s.doc.dirty)
        if (auto kept = writeAutosave(s); !kept) {
            s.transient.message = "not exported: the unsaved work could not be autosaved first: " +
                        kept.error().str();
            return;
        }
    s.exportJob = std::make_shared<ExportJob>(s.doc.loaded, *s.scene, options, s.wakeFrame);
    s.transient.message = "exporting to " + dir.string();
}

void exportWindow(ui::Context& ctx, EditorState& s) {
    // The status line says the end as it comes, the window open or not (it said "exporting to
    // …" until the window was closed).
    if (s.exportJob)
        if (std::optional<std::string> notice = s.exportJob->takeEndNotice())
            s.transient.message = std::move(*notice);
    if (s.exportJob && s.exportJob->done() && !s.transient.exportDialog)
        s.exportJob.reset();
    if (!s.transient.exportDialog)
        return;
    const ui::Rect screen = ctx.screenRect();
    bool open = true;
    ui::window(
        ctx, "Export", &open,
        [&](ui::Ui& ui) {
            if (s.exportJob) {
                ui.wrappedLabel(s.exportJob->done() ? s.exportJob->summary() : s.exportJob->stage());
                ui.progressBar(s.exportJob->fraction());
                if (!s.exportJob->done() && !s.exportJob->stopping() &&
                    ui.button("Stop")
                        .onHoverText("Stop exporting: the folder stays as it was")
                        .clicked())
                    s.exportJob->stop();
                if (!s.exportJob->done() && s.exportJob->stopping())
                    ui.label("stopping…");
                if (s.exportJob->done() &&
                    ui.button("Close").onHoverText("Close this window").clicked()) {
                    s.transient.message = s.exportJob->summary();
                    s.exportJob.reset();
                    s.transient.exportDialog = false;
                }
                return;
            }
            ui.label("Folder (a relative path is inside the project folder):");
            ui::textEdit(ui, "##exportdir", s.transient.exportDir, ui.availableWidth() - 8.0f)
                .onHoverText("The folder to export into; a relative path is inside the project "
                             "folder");
            // In core::ExportFormat's order.
            static constexpr std::array<const char*, 4> FORMATS{
                "glTF per layer (EXT_mesh_gpu_instancing)", "raw GPU buffers",
                "one .glb, every layer", "one .glb, blades merged (any viewer)"};
            ui.comboBox("format", s.transient.exportFormat, FORMATS)
                .onHoverText("What to write: glTF files per layer, raw GPU buffers or one .glb");
            if (s.transient.exportFormat != int(core::ExportFormat::Raw))
                ui.slider("LOD (keep 1 in 2^N)", s.transient.exportLod, 0, core::MAX_EXPORT_LOD)
                    .onHoverText("Keep 1 blade in 2^N (N from 0 to 8); 0 keeps every blade");
            ui.horizontal([&](ui::Ui& row) {
                if (row.button("Export")
                        .onHoverText("Write the scene to the folder in the chosen format")
                        .clicked() &&
                    !s.transient.exportDir.empty())
                    startExport(s);
                if (row.button("Cancel")
                        .onHoverText("Close this window without exporting")
                        .clicked())
                    s.transient.exportDialog = false;
            });
        },
        ui::Rect::fromMinSize({screen.centre().x - 230.0f, screen.centre().y - 80.0f},
                              {460.0f, 160.0f}));
    // Closing the window while a job runs only hides it; the status bar reports the end.
    if (!open)
        s.transient.exportDialog = false;
}

}  // namespace grass::editor
