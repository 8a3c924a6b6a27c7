#include "app/commands.h"

#include "quality/quality_presets.h"

namespace grass::editor {

namespace {

// A short name for a project step: the part of the project that changed.
std::string projectEditLabel(const core::Project& before, const core::Project& after) {
    if (const auto preset = core::matchingPreset(after); preset && preset != core::matchingPreset(before))
        return "quality " + std::string(core::qualityPresetName(*preset));
    if (before.wind != after.wind)
        return "wind";
    if (before.colliders != after.colliders)
        return "colliders";
    if (before.layers != after.layers)
        return "layers";
    if (before.render != after.render || before.lighting != after.lighting)
        return "render settings";
    if (before.snow != after.snow)
        return "snow";
    if (before.name != after.name)
        return "project name";
    return "project";
}

struct Applier {
    EditorState& s;

    bool operator()(EditProject& c) {
        Document& doc = s.doc;
        const bool changed = c.after != doc.project();
        if (changed) {
            doc.loaded.project = std::move(c.after);
            doc.dirty = true;
            doc.editChanged = true;
        }
        const bool ended = !c.ongoing && !s.view.toolDragActive;
        const bool stepDue = ended && doc.project() != doc.committed;
        if (c.effect != EditEffect::Live && (changed || stepDue))
            doc.editRegrows = true;
        if (c.effect == EditEffect::Regrow && (changed || stepDue))
            s.rebuildPending = true;
        if (ended && !stepDue && doc.editChanged) {
            // The edit ended where it began (a drag brought back, a value typed again): no step,
            // and nothing unsaved when nothing was before it (the title's * goes).
            doc.dirty = !doc.history.atSavePoint();
            doc.editChanged = doc.editRegrows = false;
        }
        if (!stepDue)
            return changed;
        core::ProjectEdit step{doc.committed, doc.project(), doc.editRegrows};
        doc.editChanged = doc.editRegrows = false;
        std::string label = c.label.empty() ? projectEditLabel(step.before, step.after) : c.label;
        doc.committed = doc.project();
        doc.history.push(core::Edit{std::move(label), std::move(step)});
        doc.dirty = true;
        return true;
    }

    bool operator()(RecordStroke& c) {
        s.doc.paintedMaps.insert({c.edit.layer, c.edit.map});
        s.doc.dirty = true;
        std::string label = !c.label.empty()
                                ? c.label
                                : std::string("paint ") + std::string(core::layerMapName(c.edit.map));
        s.doc.history.push(core::Edit{std::move(label), std::move(c.edit)});
        return true;
    }

    bool operator()(Undo) { return step(true); }
    bool operator()(Redo) { return step(false); }

    bool step(bool undoing) {
        if (s.view.toolDragActive || s.busy())
            return false;
        const core::Edit* edit = undoing ? s.doc.history.undo() : s.doc.history.redo();
        if (!edit)
            return false;
        s.transient.message = std::string(undoing ? "undid " : "redid ") + edit->label;
        s.transient.loggedMessage.clear();  // another undo of a stroke says so again
        bool done = true;
        if (const auto* project = std::get_if<core::ProjectEdit>(&edit->change)) {
            s.doc.loaded.project = undoing ? project->before : project->after;
            s.doc.committed = s.doc.project();
            s.doc.editChanged = s.doc.editRegrows = false;
            // A step the field was not grown from (render settings, light, colours, names) is
            // shown as it is; the rest grows the field again (or moves what moves it:
            // Editor::followMotionEdits).
            if (project->regrows)
                s.rebuildPending = true;
            else if (s.scene)
                core::takeLayerLooks(*s.scene, s.doc.project());
        } else {
            done = replayPaint(std::get<core::PaintEdit>(edit->change), undoing);
        }
        // Back at what the file holds: nothing is unsaved (the title's * goes, quitting asks
        // nothing).
        s.doc.dirty = !done || !s.doc.history.atSavePoint();
        return done;
    }

    // Writes a stroke's texels back (or again) and re-grows the patches they reach.
    bool replayPaint(const core::PaintEdit& edit, bool undoing) {
        if (!s.tools)
            return false;
        auto report = s.tools->painter.apply(edit, undoing);
        if (!report) {
            s.transient.message = "cannot " + std::string(undoing ? "undo" : "redo") + ": " +
                                  report.error().message;
            return false;
        }
        if (s.regrown)
            s.regrown(edit.layer, *report);
        s.doc.paintedMaps.insert({edit.layer, edit.map});
        s.doc.dirty = true;
        return true;
    }
};

}  // namespace

bool apply(EditorState& state, Command command) {
    return std::visit(Applier{state}, command);
}

void recordProjectEdit(EditorState& state, bool widgetActive) {
    apply(state, EditProject{.after = state.doc.project(), .ongoing = widgetActive});
}

bool undo(EditorState& state) {
    return apply(state, Undo{});
}

bool redo(EditorState& state) {
    return apply(state, Redo{});
}

}  // namespace grass::editor
