// The file browser of the editor's own UI (issue 26): what Open…, Save As…, New from mesh… and
// Import mesh… show instead of a bare path field (there is no native dialog: GLFW has none, and
// the editor draws every window itself). This is the part without drawing: the folder being
// shown, its entries through the purpose's extension filter, the typed path and where it leads,
// the places (home, the project's folder, recent folders). Drawn by panels_file_browser.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace grass::editor {

// What the browser picks a path for; each purpose has its own filter and button.
// AddCollider: Colliders › add mesh… (a mesh collider, mesh_import.h addMeshCollider).
enum class BrowsePurpose {
    OpenProject,
    SaveProject,
    NewFromMesh,
    ImportMesh,
    ImportMap,
    ExportMap,
    AddCollider
};

std::string_view browseTitle(BrowsePurpose purpose);
std::string_view browseButton(BrowsePurpose purpose);
// Lower-case extensions with the dot (".gltf"); a project's is ".json".
const std::vector<std::string>& browseExtensions(BrowsePurpose purpose);
// Whether `path`'s extension (any case) is one the purpose takes.
bool browseAccepts(BrowsePurpose purpose, const std::filesystem::path& path);
// "glTF (.gltf .glb)" and the like, for the filter line.
std::string browseFilterText(BrowsePurpose purpose);

struct BrowserEntry {
    std::string name;
    bool isFolder = false;
    bool isProject = false;  // a folder holding project.json
    std::uintmax_t bytes = 0;
};

// A folder lists at most this many entries (a folder of a million files stays responsive;
// the rest are counted in `hidden`).
inline constexpr std::size_t MAX_BROWSER_ENTRIES = 4000;

struct FolderListing {
    std::vector<BrowserEntry> entries;  // folders first, then files, each by name (any case)
    std::size_t hidden = 0;             // entries beyond MAX_BROWSER_ENTRIES
    std::string error;                  // the folder could not be read (empty: listed)
};

// The folder's sub-folders and the files whose extension is one of `extensions` (any case);
// hidden (dot) entries left out. Never throws: an unreadable folder gives `error`.
FolderListing listFolder(const std::filesystem::path& folder,
                         const std::vector<std::string>& extensions);

// A typed path: "~" and "~/x" are the home folder, a relative path is relative to `folder`.
std::filesystem::path resolveTypedPath(const std::filesystem::path& folder, const std::string& typed);

// A named place on the browser's left.
struct BrowserPlace {
    std::string label;
    std::filesystem::path folder;
};

class FileBrowser {
public:
    FileBrowser() = default;
    FileBrowser(BrowsePurpose purpose, const std::filesystem::path& start,
                std::string typedName = {});

    BrowsePurpose purpose() const { return mPurpose; }
    const std::filesystem::path& folder() const { return mFolder; }
    const FolderListing& listing() const { return mListing; }
    std::string& typed() { return mTyped; }
    const std::string& typed() const { return mTyped; }
    std::optional<std::size_t> selected() const { return mSelected; }
    // True once after the browser opened, moved to another folder or refused a typed path: the
    // path field takes the keyboard, so a path can be typed (or pasted) at once.
    bool takeFocusRequest() { return std::exchange(mFocusPath, false); }
    // Why the last activation chose nothing (a missing file, a wrong kind); empty otherwise.
    const std::string& message() const { return mMessage; }

    // Shows `folder` (an unreadable one shows its error and keeps the typed text).
    void enter(const std::filesystem::path& folder);
    void up();
    void refresh();
    // A click on an entry: selects it, and puts a file's name into the typed path.
    void select(std::size_t index);
    // A double-click on an entry, or Enter/the button with the typed path: a folder is entered
    // (for Open, a project folder is chosen instead); a file is chosen. Returns the chosen path,
    // or nothing when the browser only moved.
    std::optional<std::filesystem::path> activate(std::size_t index);
    std::optional<std::filesystem::path> activateTyped();
    // Save As: the open project's own file, which a save may replace without asking. Any other
    // project.json (a folder holding another project, an existing .json), and for a map export
    // any existing file, is chosen only when the same path is chosen twice in a row: the first
    // time says what would be replaced.
    void setOwnProject(const std::filesystem::path& projectFile) { mOwnProject = projectFile; }

private:
    std::optional<std::filesystem::path> choose(const std::filesystem::path& path);
    // Whether to hold back a choice that would replace `file`: true (with the question in
    // message()) unless the same file was asked about by the last choice.
    bool askReplace(const std::filesystem::path& file, std::string_view what);

    BrowsePurpose mPurpose = BrowsePurpose::OpenProject;
    std::filesystem::path mFolder;
    FolderListing mListing;
    std::string mTyped;
    std::optional<std::size_t> mSelected;
    std::string mMessage;
    bool mFocusPath = true;
    std::filesystem::path mOwnProject;
    std::filesystem::path mReplaceAsked;  // the other project a Save As asked about last
};

// The project file a chosen project path means: a folder, or a path not ending in .json, is
// <path>/project.json (projects are folders).
std::filesystem::path projectFileFor(const std::filesystem::path& path);

}  // namespace grass::editor
