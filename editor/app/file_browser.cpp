#include "app/file_browser.h"

#include <algorithm>
#include <cstdlib>
#include <system_error>

#include "util/file_extension.h"

namespace grass::editor {

namespace fs = std::filesystem;

namespace {

bool hasExtension(const fs::path& path, const std::vector<std::string>& extensions) {
    const std::string extension = lowerExtension(path);
    return std::find(extensions.begin(), extensions.end(), extension) != extensions.end();
}

bool isFolder(const fs::path& path) {
    std::error_code ec;
    return fs::is_directory(path, ec);
}

bool isFile(const fs::path& path) {
    std::error_code ec;
    return fs::is_regular_file(path, ec);
}

bool holdsProject(const fs::path& folder) {
    return isFile(folder / "project.json");
}

}  // namespace

fs::path projectFileFor(const fs::path& path) {
    return path.extension() == ".json" ? path : path / "project.json";
}

std::string_view browseTitle(BrowsePurpose purpose) {
    switch (purpose) {
        case BrowsePurpose::OpenProject: return "Open project";
        case BrowsePurpose::SaveProject: return "Save project as";
        case BrowsePurpose::NewFromMesh: return "New project from mesh";
        case BrowsePurpose::ImportMesh: return "Import mesh";
        case BrowsePurpose::ImportMap: return "Import map image";
        case BrowsePurpose::ExportMap: return "Export map image";
        case BrowsePurpose::AddCollider:
            return "Add mesh collider";
    }
    return "";
}

std::string_view browseButton(BrowsePurpose purpose) {
    switch (purpose) {
        case BrowsePurpose::OpenProject: return "Open";
        case BrowsePurpose::SaveProject: return "Save";
        case BrowsePurpose::NewFromMesh: return "Create";
        case BrowsePurpose::ImportMesh:
        case BrowsePurpose::ImportMap: return "Import";
        case BrowsePurpose::ExportMap: return "Export";
        case BrowsePurpose::AddCollider:
            return "Add";
    }
    return "";
}

const std::vector<std::string>& browseExtensions(BrowsePurpose purpose) {
    static const std::vector<std::string> project{".json"};
    static const std::vector<std::string> mesh{".gltf", ".glb"};
    // What a map is read from (core/util/image_open.h).
    static const std::vector<std::string>& image = readableImageExtensions();
    // What a map is written to without loss (16-bit PNG and TIFF, float EXR: saveMapImage).
    static const std::vector<std::string> exported{".png", ".exr", ".tif", ".tiff"};
    switch (purpose) {
        case BrowsePurpose::OpenProject:
        case BrowsePurpose::SaveProject: return project;
        case BrowsePurpose::NewFromMesh:
        case BrowsePurpose::ImportMesh:
        case BrowsePurpose::AddCollider:
            return mesh;
        case BrowsePurpose::ImportMap: return image;
        case BrowsePurpose::ExportMap: return exported;
    }
    return project;
}

bool browseAccepts(BrowsePurpose purpose, const fs::path& path) {
    return hasExtension(path, browseExtensions(purpose));
}

std::string browseFilterText(BrowsePurpose purpose) {
    std::string kind =
        purpose == BrowsePurpose::ImportMap || purpose == BrowsePurpose::ExportMap ? "images"
        : purpose == BrowsePurpose::NewFromMesh || purpose == BrowsePurpose::ImportMesh ||
                purpose == BrowsePurpose::AddCollider
            ? "glTF"
            : "projects";
    std::string text = kind + " (";
    for (const std::string& extension : browseExtensions(purpose))
        text += (text.back() == '(' ? "" : " ") + extension;
    return text + ")";
}

FolderListing listFolder(const fs::path& folder, const std::vector<std::string>& extensions) {
    FolderListing listing;
    std::error_code ec;
    fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
    if (ec) {
        listing.error = "cannot read " + folder.string() + ": " + ec.message();
        return listing;
    }
    for (; it != fs::directory_iterator(); it.increment(ec)) {
        if (ec)
            break;  // a folder that changes while listed: show what was read
        const fs::path& path = it->path();
        const std::string name = path.filename().string();
        if (name.empty() || name.front() == '.')
            continue;
        std::error_code statError;
        const bool folderEntry = it->is_directory(statError);
        if (!folderEntry && !(it->is_regular_file(statError) && hasExtension(path, extensions)))
            continue;
        if (listing.entries.size() >= MAX_BROWSER_ENTRIES) {
            ++listing.hidden;
            continue;
        }
        BrowserEntry entry{name, folderEntry, folderEntry && holdsProject(path), 0};
        if (!folderEntry)
            entry.bytes = it->file_size(statError);
        listing.entries.push_back(std::move(entry));
    }
    std::sort(listing.entries.begin(), listing.entries.end(),
              [](const BrowserEntry& a, const BrowserEntry& b) {
                  if (a.isFolder != b.isFolder)
                      return a.isFolder;
                  const std::string la = asciiLowerCase(a.name), lb = asciiLowerCase(b.name);
                  return la != lb ? la < lb : a.name < b.name;
              });
    return listing;
}

fs::path resolveTypedPath(const fs::path& folder, const std::string& typed) {
    if (typed == "~" || typed.rfind("~/", 0) == 0) {
        const char* home = std::getenv("HOME");
        if (home && *home)
            return (fs::path(home) / typed.substr(std::min<std::size_t>(2, typed.size())))
                .lexically_normal();
    }
    const fs::path path(typed);
    return (path.is_absolute() ? path : folder / path).lexically_normal();
}

FileBrowser::FileBrowser(BrowsePurpose purpose, const fs::path& start, std::string typedName)
    : mPurpose(purpose), mTyped(std::move(typedName)) {
    // The start folder, or the nearest folder above it that exists (a moved project).
    fs::path folder = start.empty() ? fs::current_path() : fs::absolute(start).lexically_normal();
    while (!isFolder(folder) && folder.has_parent_path() && folder.parent_path() != folder)
        folder = folder.parent_path();
    enter(folder);
}

void FileBrowser::enter(const fs::path& folder) {
    mFolder = folder.lexically_normal();
    // "/a/b/" normalises to "/a/b/": drop the empty last part so up() and labels work.
    if (!mFolder.has_filename() && mFolder.has_parent_path() && mFolder != mFolder.root_path())
        mFolder = mFolder.parent_path();
    mSelected.reset();
    mFocusPath = true;  // the next thing typed is a name in the new folder
    refresh();
}

void FileBrowser::up() {
    if (mFolder.has_parent_path() && mFolder.parent_path() != mFolder)
        enter(mFolder.parent_path());
}

void FileBrowser::refresh() {
    mListing = listFolder(mFolder, browseExtensions(mPurpose));
}

void FileBrowser::select(std::size_t index) {
    if (index >= mListing.entries.size())
        return;
    mSelected = index;
    mMessage.clear();
    const BrowserEntry& entry = mListing.entries[index];
    if (!entry.isFolder || (entry.isProject && mPurpose == BrowsePurpose::OpenProject))
        mTyped = entry.name;
}

std::optional<fs::path> FileBrowser::activate(std::size_t index) {
    if (index >= mListing.entries.size())
        return std::nullopt;
    const BrowserEntry& entry = mListing.entries[index];
    const fs::path path = mFolder / entry.name;
    mMessage.clear();
    // A project is a folder: opening one is choosing it, not browsing its maps.
    if (entry.isFolder && !(entry.isProject && mPurpose == BrowsePurpose::OpenProject)) {
        enter(path);
        return std::nullopt;
    }
    return choose(path);
}

std::optional<fs::path> FileBrowser::activateTyped() {
    mMessage.clear();
    const bool projects =
        mPurpose == BrowsePurpose::OpenProject || mPurpose == BrowsePurpose::SaveProject;
    mFocusPath = true;  // what follows a refusal or a move is more typing
    if (mTyped.empty()) {
        // A project folder being shown is what Open and Save mean with nothing typed.
        if (mPurpose == BrowsePurpose::SaveProject)
            return choose(mFolder);  // asks before replacing another project
        if (projects && holdsProject(mFolder))
            return mFolder;
        mMessage = mPurpose == BrowsePurpose::OpenProject
                       ? "this folder holds no project.json: pick a project folder"
                       : "type a file name or pick a file";
        return std::nullopt;
    }
    const fs::path path = resolveTypedPath(mFolder, mTyped);
    if (isFolder(path) && !(projects && (mPurpose == BrowsePurpose::SaveProject || holdsProject(path)))) {
        enter(path);
        mTyped.clear();
        return std::nullopt;
    }
    return choose(path);
}

bool FileBrowser::askReplace(const fs::path& file, std::string_view what) {
    if (mReplaceAsked == file)
        return false;  // the same choice twice in a row: replace it
    mReplaceAsked = file;
    mMessage = file.string() + " " + std::string(what) + ": choose it again (" +
               std::string(browseButton(mPurpose)) + ") to replace it, or type a new name";
    return true;
}

std::optional<fs::path> FileBrowser::choose(const fs::path& path) {
    switch (mPurpose) {
        case BrowsePurpose::SaveProject: {
            // A new name is a new project folder (or .json file). Another project's file would
            // be overwritten, and its folder's files mixed with this project's (those already
            // there are kept): asked first, confirmed by choosing it again.
            const fs::path file = projectFileFor(path);
            std::error_code ec;
            const bool own = !mOwnProject.empty() && fs::equivalent(file, mOwnProject, ec);
            if (isFile(file) && !own && askReplace(file, "is another project"))
                return std::nullopt;
            return path;
        }
        case BrowsePurpose::ExportMap:
            if (isFolder(path)) {
                mMessage = path.string() + " is a folder";
                return std::nullopt;
            }
            if (!browseAccepts(mPurpose, path)) {
                mMessage = path.filename().string() + " is not one of " + browseFilterText(mPurpose);
                return std::nullopt;
            }
            // A picture already there (the artist's own texture, perhaps) is replaced only
            // when chosen twice.
            if (isFile(path) && askReplace(path, "already exists"))
                return std::nullopt;
            return path;
        case BrowsePurpose::OpenProject:
            if (isFolder(path) || isFile(path))
                return path;
            mMessage = path.string() + " does not exist";
            return std::nullopt;
        default:
            break;
    }
    if (!isFile(path)) {
        mMessage = path.string() + (isFolder(path) ? " is a folder" : " does not exist");
        return std::nullopt;
    }
    if (!browseAccepts(mPurpose, path)) {
        mMessage = path.filename().string() + " is not one of " + browseFilterText(mPurpose);
        return std::nullopt;
    }
    return path;
}

}  // namespace grass::editor
