// What the editor last saw of its files on disk (project_file_watch.h follows them): kept in
// the EditorState, so a Save can ask whether a map it is about to write over was changed by
// another program since (panels.h, saveTo).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>

namespace grass::editor {

// When a file was last written, as far as its time and size tell.
struct FileStamp {
    std::filesystem::file_time_type modified{};
    std::uintmax_t size = 0;
    bool operator==(const FileStamp&) const = default;
};

// The file's stamp now; none when it is gone (or being replaced).
std::optional<FileStamp> stampOf(const std::filesystem::path& file);

struct ProjectFileWatch {
    std::filesystem::path file;  // the file the stamp below is of
    FileStamp stamp;
    double nextLookS = 0.0;
    std::optional<std::uint64_t> saidDigest;  // the version last said (not taken)
    // The surface's glTF file, the layers' maps, the billboards' texture and the mesh colliders'
    // glTF files as last looked at, by path; a file first seen is only stamped. A map changed on
    // disk (painted in another program, written by `grass paint`) grows the field again from it,
    // unless the editor holds unsaved painting of that map (then it is said, and Save asks
    // before writing the painting over it: its stamp here stays the one before); a changed
    // surface is read again, a changed collider mesh made into its prop and packed again. None
    // is an undo step: the editor keeps no copy of the file as it was.
    std::map<std::filesystem::path, FileStamp> assets;
    std::map<std::filesystem::path, FileStamp> assetsSaid;  // said and not taken
};

}  // namespace grass::editor
