// The Surface section (issue 26 item 2): what the grass grows on. A glTF file shows its path,
// its unit (mm, cm, m, in, ft, or metres per unit typed), its up axis (+Y, +Z) and whether it
// is drawn in its own material or the ground colour; a procedural
// shape its shape and sizes. "Import mesh…" replaces it (mesh_import.h). A change re-grows the
// field, and a new unit or up axis frames the view on the surface again: at a thousand times
// the size, the old view would be inside it.
#include <cmath>
#include <string>
#include <vector>

#include "app/panels.h"
#include "app/setting_widget.h"
#include "mesh/mesh_frame.h"
#include "mesh/procedural.h"
#include "project/settings.h"
#include "ui/text_edit.h"

namespace grass::editor {

namespace {

// The unit combo's items: the named units, then "other" (a typed factor).
int unitIndex(float metresPerUnit) {
    for (std::size_t i = 0; i < std::size(core::MESH_UNITS); ++i)
        if (core::MESH_UNITS[i].metres == metresPerUnit)
            return static_cast<int>(i);
    return static_cast<int>(std::size(core::MESH_UNITS));
}

void fileRows(ui::Ui& ui, EditorState& s, core::MeshSource& mesh) {
    ui.label("file: " + mesh.file);
    std::vector<std::string> names;
    for (const core::MeshUnit& unit : core::MESH_UNITS)
        names.emplace_back(unit.name);
    names.emplace_back("other");
    int index = unitIndex(mesh.metresPerUnit);
    const float before = mesh.metresPerUnit;
    if (ui.comboBox("unit", index, names)
            .onHoverText("What one unit of the file measures; the mesh is scaled to metres on "
                         "load (project.json \"unit\")")
            .changed() &&
        index < static_cast<int>(std::size(core::MESH_UNITS)))
        mesh.metresPerUnit = core::MESH_UNITS[static_cast<std::size_t>(index)].metres;
    ui::dragValueWithEntry(ui, "metres per unit", mesh.metresPerUnit, 0.001f,
                           core::MIN_METRES_PER_UNIT, core::MAX_METRES_PER_UNIT, 6)
        .onHoverText(ui::withTypingHint("Metres one unit of the file measures, 1e-6 to 1e6"));
    ui.horizontal([&](ui::Ui& row) {
        row.label("up");
        row.radioValue(mesh.up, core::UpAxis::Y, "+Y")
            .onHoverText("The file's up axis is +Y (glTF's own convention)");
        row.radioValue(mesh.up, core::UpAxis::Z, "+Z")
            .onHoverText("The file's up axis is +Z (CAD tools): turned to +Y on load");
    });
    if (mesh.metresPerUnit != before || mesh.up != s.doc.project().mesh.up)
        s.view.frameSurfacePending = true;
    ui.checkbox(mesh.fileMaterial, "the file's material")
        .onHoverText(
            "Draw and export the surface in the file's own base colour and texture; "
            "off: in the ground colour (Light), as a procedural surface "
            "(project.json \"file_material\")");
}

void proceduralRows(ui::Ui& ui, core::MeshSource& mesh) {
    const std::vector<std::string_view> names = core::proceduralShapeNames();
    int shape = static_cast<int>(mesh.procedural.shape);
    if (ui.comboBox("shape##surface", shape, names)
            .onHoverText("The procedural surface (project.json \"procedural\")")
            .changed())
        mesh.procedural.shape = static_cast<core::ProceduralShape>(shape);
    const auto rows = core::settings::mesh();
    for (const std::string_view key :
         {"size", "minor_size", "hill_height", "hill_scale", "resolution"}) {
        const core::settings::Setting<core::MeshSource>* row = core::settings::findSetting(rows, key);
        if (row && (!row->applies || row->applies(mesh)))
            settingWidget(ui, *row, mesh);
    }
}

}  // namespace

void surfaceSection(ui::Ui& ui, EditorState& s) {
    core::MeshSource& mesh = s.transient.draft.project.mesh;
    ui.collapsingHeader("Surface", [&](ui::Ui& section) {
        const core::MeshSource before = mesh;
        if (mesh.isFile)
            fileRows(section, s, mesh);
        else
            proceduralRows(section, mesh);
        if (mesh != before)
            s.transient.draft.regrow = true;
        if (section.button("Import mesh…")
                .onHoverText("Grow on a .gltf/.glb of your own instead (also: drop it on the "
                             "window)")
                .clicked())
            openBrowser(s, BrowsePurpose::ImportMesh);
    });
}

}  // namespace grass::editor
