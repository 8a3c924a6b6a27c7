#include "app/project_file_watch.h"

#include <string>
#include <system_error>

#include "app/commands.h"
#include "util/atomic_file.h"
#include "util/content_digest.h"

namespace grass::editor {

namespace fs = std::filesystem;

bool followProjectFileOnDisk(EditorState& s, ProjectFileWatch& watch, double nowS,
                             bool editUnderWay) {
    Document& doc = s.doc;
    if (doc.loaded.file.empty() || !doc.loaded.fileDigest || editUnderWay || s.busy() ||
        s.transient.changedOnDisk || nowS < watch.nextLookS)
        return false;
    watch.nextLookS = nowS + PROJECT_FILE_LOOK_S;
    std::error_code timeError;
    std::error_code sizeError;
    const fs::file_time_type modified = fs::last_write_time(doc.loaded.file, timeError);
    const std::uintmax_t size = fs::file_size(doc.loaded.file, sizeError);
    if (timeError || sizeError)
        return false;  // gone or being replaced: a Save writes it again
    if (watch.file == doc.loaded.file && watch.modified == modified && watch.size == size)
        return false;
    watch.file = doc.loaded.file;
    watch.modified = modified;
    watch.size = size;
    // Read and parsed, not loaded (core::loadProject also clears stale temporaries of saves
    // from the project's folders: not a watcher's business while workers copy files there).
    const auto text = readFile(doc.loaded.file, MAX_JSON_FILE_BYTES);
    if (!text)
        return false;
    const std::optional<std::uint64_t> digest = contentDigest(*text);
    if (digest == doc.loaded.fileDigest)
        return false;  // the editor's own save, or a touch
    const std::string name = doc.loaded.file.filename().string();
    // Each version of the file is said once, however often it is looked at.
    const auto say = [&](const std::string& message) {
        if (digest == watch.saidDigest)
            return;
        s.transient.message = message;
        s.transient.loggedMessage.clear();
        watch.saidDigest = digest;
    };
    if (doc.dirty || doc.editChanged) {
        say(name +
            " was changed on disk: the unsaved changes here are kept (Save asks before "
            "replacing the file)");
        watch.file.clear();  // looked at again: once nothing is unsaved here, it is taken
        return false;
    }
    auto project = core::parseProject(*text, doc.loaded.file.string());
    if (!project) {
        say(name + " was changed on disk but does not load: " + project.error().str());
        return false;
    }
    doc.loaded.fileDigest = digest;
    watch.saidDigest.reset();
    if (*project == doc.project())
        return false;  // the same project written another way (spaces, key order)
    apply(s, EditProject{.after = std::move(*project),
                         .effect = EditEffect::Regrow,
                         .label = "changes made on disk"});
    // The document is the file again.
    doc.dirty = false;
    doc.history.markSaved();
    s.transient.message = "took the changes made to " + name + " on disk (Ctrl+Z undoes them)";
    s.transient.loggedMessage.clear();
    return true;
}

}  // namespace grass::editor
