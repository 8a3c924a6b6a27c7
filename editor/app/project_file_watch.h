// The project's file edited by another program while the editor has it open (a text editor: the
// project format is documented for hand-editing, docs/project-format.md): the editor takes the
// change as one undoable edit, so the field follows the file as it is saved there, the view and
// the timeline staying where they are. A document with unsaved changes of its own is left as it
// is (said once; its Save then asks before replacing the file: panels.h, saveTo); a file that
// does not load is said with its error, once per version, and taken as soon as it loads.
// GL-free: the Editor calls it every frame.
#pragma once

#include <filesystem>
#include <vector>

#include "app/editor_state.h"

namespace grass::editor {

// How often the file's time and size are looked at; it is read only when they changed.
inline constexpr double PROJECT_FILE_LOOK_S = 1.0;

// At most every PROJECT_FILE_LOOK_S of `nowS`, and not while `editUnderWay` (a drag, a text
// entry) or a job replaces or reads the document: when the project's file holds another
// project than the one last read or written here, takes it as an edit labelled "changes made
// on disk" (the field re-grows as after any edit; Ctrl+Z goes back) and the document counts as
// saved; else, when a map or the surface changed on disk, asks for the field to grow again
// from them (regrowFromDisk, surfaceChangedOnDisk). Returns whether it took a change.
bool followProjectFileOnDisk(EditorState& state, double nowS, bool editUnderWay);

// The project's file as it is on disk taken over the document ("Take the file's" in the
// Changed on disk window): one undoable edit, "changes made on disk", so the unsaved changes made
// here stay one Ctrl+Z away; the document then counts as saved unless maps painted here are
// not. A file that cannot be read or does not load is said (in warning orange) and taken not.
bool takeProjectFileFromDisk(EditorState& state);

// The files of the maps painted here that another program changed since the watch last took
// them (time or size other than its stamp): a Save asks before writing the painting over them.
// Asked of the files themselves, so a map saved elsewhere in the second before a Save, or while
// a job held the watch off, counts too.
std::vector<std::filesystem::path> paintedMapsChangedOnDisk(const EditorState& state);

}  // namespace grass::editor
