#include "app/project_file_watch.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "app/commands.h"
#include "app/edit_actions.h"
#include "scene/layer_growth.h"
#include "util/atomic_file.h"
#include "util/content_digest.h"

namespace grass::editor {

namespace fs = std::filesystem;

std::optional<FileStamp> stampOf(const fs::path& file) {
    std::error_code timeError;
    std::error_code sizeError;
    FileStamp stamp{fs::last_write_time(file, timeError), fs::file_size(file, sizeError)};
    if (timeError || sizeError)
        return std::nullopt;  // gone, or being replaced
    return stamp;
}

namespace {

// Said in the status line and on the terminal: a refused file's error is long, and the status
// line cuts it (Help › Messages has it whole too).
void tell(EditorState& s, std::string message) {
    std::fprintf(stderr, "grass-editor: %s\n", message.c_str());
    s.transient.message = std::move(message);
    s.transient.loggedMessage.clear();
}

// A file the field is grown from: the surface's glTF, a layer's map, the billboards' texture, a
// mesh collider's glTF.
struct WatchedAsset {
    fs::path path = {};
    std::string name = {};                                           // as the project names it
    std::optional<std::pair<std::size_t, core::LayerMap>> map = {};  // a layer's map
    bool surface = false;
    bool collider = false;  // a mesh collider's
};

std::vector<WatchedAsset> watchedAssets(const core::LoadedProject& loaded) {
    std::vector<WatchedAsset> assets;
    const auto add = [&](const std::string& relative, WatchedAsset asset) {
        if (relative.empty())
            return;
        if (auto path = core::resolveAssetPath(loaded.folder, relative, "watch")) {
            asset.path = *path;
            asset.name = relative;
            assets.push_back(std::move(asset));
        }
    };
    if (loaded.project.mesh.isFile)
        add(loaded.project.mesh.file, {.surface = true});
    for (std::size_t i = 0; i < loaded.project.layers.size(); ++i)
        for (const core::LayerMap map : core::ALL_LAYER_MAPS)
            add(core::layerMapFile(loaded.project.layers[i], map), {.map = std::pair(i, map)});
    add(loaded.project.billboards.texture, {});
    // Packed again (the packing cache is keyed by the file's bytes: core/collider/
    // packing_cache.h) and its prop read again.
    for (const core::ColliderDesc& collider : loaded.project.colliders)
        if (collider.shape == core::ColliderShape::Mesh)
            add(collider.file, {.collider = true});
    return assets;
}

// The maps and the surface as they are now: what a re-grow about to start reads.
void stampAssets(const core::LoadedProject& loaded, ProjectFileWatch& watch) {
    for (const WatchedAsset& asset : watchedAssets(loaded))
        if (const std::optional<FileStamp> stamp = stampOf(asset.path))
            watch.assets[asset.path] = *stamp;
}

// The maps and the surface changed on disk since they were last looked at. Returns whether the
// field is to grow again from them.
bool followAssetsOnDisk(EditorState& s, ProjectFileWatch& watch) {
    if (std::exchange(s.assetsWrittenHere, false))
        watch.assets.clear();  // a Save wrote the painted maps: stamped afresh below
    std::vector<std::string> taken;
    std::vector<std::string> kept;
    std::set<std::string> colliderFiles;
    bool surface = false;
    for (const WatchedAsset& asset : watchedAssets(s.doc.loaded)) {
        const std::optional<FileStamp> stamp = stampOf(asset.path);
        if (!stamp)
            continue;
        const auto [known, firstSeen] = watch.assets.try_emplace(asset.path, *stamp);
        if (firstSeen || known->second == *stamp)
            continue;
        // Painting here not saved yet: the field keeps it, and a Save asks before writing it
        // over the file.
        if (asset.map && s.doc.paintedMaps.count(*asset.map)) {
            if (watch.assetsSaid[asset.path] != *stamp)
                kept.push_back(asset.name);
            watch.assetsSaid[asset.path] = *stamp;
            continue;
        }
        known->second = *stamp;
        watch.assetsSaid.erase(asset.path);
        taken.push_back(asset.name);
        surface = surface || asset.surface;
        if (asset.collider)
            colliderFiles.insert(asset.name);
    }
    if (!kept.empty()) {
        tell(s,
             kept.front() + (kept.size() > 1 ? " and others" : "") +
                 " changed on disk: the painting here is kept (Save asks before writing it over)");
    }
    if (taken.empty())
        return false;
    // Only colliders' meshes: packed again while the field keeps its blades and their motion,
    // and where a layer clears the ground under them, grown again around them alone (Editor::
    // followMotionEdits). A file is taken once, as what watches it first: one that is the
    // surface or a map as well as a collider's grows the field again.
    if (colliderFiles.size() == taken.size()) {
        s.colliderFilesChangedOnDisk.insert(colliderFiles.begin(), colliderFiles.end());
        tell(s, taken.front() + (taken.size() > 1 ? " and others" : "") +
                    " changed on disk: packing the collider again (the field keeps its blades)");
        return true;
    }
    s.regrowFromDisk = true;
    s.surfaceChangedOnDisk = s.surfaceChangedOnDisk || surface;
    tell(s, "growing the field again from " + taken.front() +
                (taken.size() > 1 ? " and " + std::to_string(taken.size() - 1) + " more" : "") +
                ", changed on disk");
    return true;
}

// `project`, read from the project's file (whose bytes have `digest`), becomes the document as
// one edit, "changes made on disk", which Ctrl+Z takes back. The document is the file then,
// unless maps painted here are still unsaved.
bool takeProject(EditorState& s, core::Project project, std::optional<std::uint64_t> digest) {
    Document& doc = s.doc;
    doc.loaded.fileDigest = digest;
    if (project == doc.project()) {
        // The same project written another way (spaces, key order).
        if (doc.paintedMaps.empty()) {
            doc.dirty = false;
            doc.history.markSaved();
        }
        return false;
    }
    apply(s, EditProject{.after = std::move(project),
                         .effect = EditEffect::Regrow,
                         .label = "changes made on disk"});
    // The maps it names are read by the re-grow as they are now: a map changed after this
    // look is a change of its own (first seen a second later, it would pass unnoticed).
    stampAssets(doc.loaded, s.fileWatch);
    // The document is the file again.
    doc.dirty = !doc.paintedMaps.empty();
    if (!doc.dirty)
        doc.history.markSaved();
    return true;
}

}  // namespace

std::vector<fs::path> paintedMapsChangedOnDisk(const EditorState& s) {
    const ProjectFileWatch& watch = s.fileWatch;
    std::vector<fs::path> changed;
    // A Save wrote them just now: the watch takes their new stamps at its next look.
    if (s.assetsWrittenHere)
        return changed;
    for (const WatchedAsset& asset : watchedAssets(s.doc.loaded)) {
        // A file two maps read is not written over: the painting goes to a file of its own.
        if (!asset.map || !s.doc.paintedMaps.count(*asset.map) ||
            mapFileShared(s.doc.project(), asset.name))
            continue;
        // Never looked at yet: nothing known to lose.
        const auto known = watch.assets.find(asset.path);
        const std::optional<FileStamp> now = stampOf(asset.path);
        if (known != watch.assets.end() && now && *now != known->second &&
            std::find(changed.begin(), changed.end(), asset.path) == changed.end())
            changed.push_back(asset.path);
    }
    return changed;
}

bool followProjectFileOnDisk(EditorState& s, double nowS, bool editUnderWay) {
    Document& doc = s.doc;
    ProjectFileWatch& watch = s.fileWatch;
    if (doc.loaded.file.empty() || !doc.loaded.fileDigest || editUnderWay || s.busy() ||
        s.transient.changedOnDisk || nowS < watch.nextLookS)
        return false;
    watch.nextLookS = nowS + PROJECT_FILE_LOOK_S;
    const std::optional<FileStamp> stamp = stampOf(doc.loaded.file);
    if (!stamp)
        return false;  // gone or being replaced: a Save writes it again
    if (watch.file == doc.loaded.file && watch.stamp == *stamp)
        return followAssetsOnDisk(s, watch);
    watch.file = doc.loaded.file;
    watch.stamp = *stamp;
    // Read and parsed, not loaded (core::loadProject also clears stale temporaries of saves
    // from the project's folders: not a watcher's business while workers copy files there).
    const auto text = readFile(doc.loaded.file, MAX_JSON_FILE_BYTES);
    if (!text)
        return false;
    const std::optional<std::uint64_t> digest = contentDigest(*text);
    if (digest == doc.loaded.fileDigest)
        return followAssetsOnDisk(s, watch);  // the editor's own save, or a touch
    const std::string name = doc.loaded.file.filename().string();
    // Each version of the file is said once, however often it is looked at.
    const auto say = [&](const std::string& message) {
        if (digest == watch.saidDigest)
            return;
        tell(s, message);
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
        const std::string said =
            name + " was changed on disk but does not load: " + project.error().str();
        say(said);
        s.transient.warningMessage = said;  // to be fixed there: said in orange while shown
        return false;
    }
    watch.saidDigest.reset();
    if (!takeProject(s, std::move(*project), digest))
        return false;
    tell(s, "took the changes made to " + name + " on disk (Ctrl+Z undoes them)");
    return true;
}

bool takeProjectFileFromDisk(EditorState& s) {
    const std::string name = s.doc.loaded.file.filename().string();
    const auto text = readFile(s.doc.loaded.file, MAX_JSON_FILE_BYTES);
    if (!text) {
        tell(s, "could not take " + name + " from disk: " + text.error().str());
        s.transient.warningMessage = s.transient.message;
        return false;
    }
    auto project = core::parseProject(*text, s.doc.loaded.file.string());
    if (!project) {
        tell(s, name + " on disk does not load: " + project.error().str());
        s.transient.warningMessage = s.transient.message;
        return false;
    }
    if (takeProject(s, std::move(*project), contentDigest(*text)))
        tell(s, "took " + name + " as it is on disk (Ctrl+Z brings back the changes made here)");
    return true;
}

}  // namespace grass::editor
