// The project's file edited by another program while the editor has it open (a text editor: the
// project format is documented for hand-editing, docs/project-format.md): the editor takes the
// change as one undoable edit, so the field follows the file as it is saved there, the view and
// the timeline staying where they are. A document with unsaved changes of its own is left as it
// is (said once; its Save then asks before replacing the file: panels.h, saveTo); a file that
// does not load is said with its error, once per version, and taken as soon as it loads.
// GL-free: the Editor calls it every frame.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>

#include "app/editor_state.h"

namespace grass::editor {

// When a file was last written, as far as its time and size tell.
struct FileStamp {
    std::filesystem::file_time_type modified{};
    std::uintmax_t size = 0;
    bool operator==(const FileStamp&) const = default;
};

struct ProjectFileWatch {
    std::filesystem::path file;  // the file the stamp below is of
    FileStamp stamp;
    double nextLookS = 0.0;
    std::optional<std::uint64_t> saidDigest;  // the version last said (not taken)
    // The surface's glTF file, the layers' maps, the billboards' texture and the mesh colliders'
    // glTF files as last looked at, by path; a file first seen is only stamped. A map changed on
    // disk (painted in another program, written by `grass paint`) grows the field again from it,
    // unless the editor holds unsaved painting of that map (then it is said, and Save asks
    // before writing the painting over it); a changed surface is read again, a changed collider
    // mesh made into its prop and packed again. None is an undo step: the editor keeps no copy
    // of the file as it was.
    std::map<std::filesystem::path, FileStamp> assets;
    std::map<std::filesystem::path, FileStamp> assetsSaid;  // said and not taken
};

// How often the file's time and size are looked at; it is read only when they changed.
inline constexpr double PROJECT_FILE_LOOK_S = 1.0;

// At most every PROJECT_FILE_LOOK_S of `nowS`, and not while `editUnderWay` (a drag, a text
// entry) or a job replaces or reads the document: when the project's file holds another
// project than the one last read or written here, takes it as an edit labelled "changes made
// on disk" (the field re-grows as after any edit; Ctrl+Z goes back) and the document counts as
// saved; else, when a map or the surface changed on disk, asks for the field to grow again
// from them (regrowFromDisk, surfaceChangedOnDisk). Returns whether it took a change.
bool followProjectFileOnDisk(EditorState& state, ProjectFileWatch& watch, double nowS,
                             bool editUnderWay);

}  // namespace grass::editor
