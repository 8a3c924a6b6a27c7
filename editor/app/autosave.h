// Autosave and crash recovery (issue 8). Every few minutes, while there are unsaved changes, the
// editor writes the project to a side file next to it, <stem>.autosave.json, and each map painted
// since the last save to its own side file, <map>.autosave.png (a new map: maps/<layer>-<map>
// .autosave.png), which that side project names. project.json and the real maps are never
// touched, so a crash loses at most one interval and never the last saved state. A save, or
// quitting without keeping the changes, removes the side files; at the next start they mean the
// editor did not close cleanly, and it offers the autosaved work back.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "app/panels.h"
#include "util/result.h"

namespace grass::editor {

// <folder>/<stem>.autosave.json for the project file; empty for a project never saved.
std::filesystem::path autosavePath(const core::LoadedProject& loaded);

// "maps/grass-soil.png" ↔ "maps/grass-soil.autosave.png".
std::string autosaveMapName(const std::string& relative);
std::optional<std::string> mapNameOfAutosave(const std::string& relative);

// Writes the side project and the painted maps' side files (atomic, each). Nothing when the
// project has no file yet.
Result<void> writeAutosave(const EditorState& state);
// writeAutosave, with what happened in the status bar: a failure always, "autosaved to …" only
// when it does not replace a failed save's message (that stays until a save succeeds). A
// project never saved (File › New, New from mesh) autosaves into its slot of the user's
// unsaved folder instead (below); where there is none, the status bar says it is not
// autosaved, in the failed save's colour. A saved project whose folder refuses the side files
// (read-only, full) is autosaved into such a slot as well, and the status bar says where.
void autosaveNow(EditorState& state);
// Removes the side project and every side map it names.
void removeAutosave(const core::LoadedProject& loaded);

// A project never saved has no folder of its own to autosave next to. Its autosave goes to
// <root>/<pid>-<n>/, root being $XDG_STATE_HOME/grass/unsaved (~/.local/state/grass/unsaved
// when unset; empty when neither that nor HOME is set): a project of its own there, the files
// it names copied along as Save As copies them, then the side project and side maps as above.
std::filesystem::path unsavedAutosaveRoot();
// Writes the never-saved document's autosave into its slot (chosen on the first call).
Result<void> writeUnsavedAutosave(EditorState& state);
// The newest autosave of a never-saved project whose editor is gone (its process ended without
// a clean close): a never-saved document (file empty) whose folder is the slot, so the files
// it names resolve there.
// `except`: a slot not to offer (the open document's own).
std::optional<core::LoadedProject> findUnsavedAutosave(const std::filesystem::path& except = {});
// A saved project whose folder cannot be written autosaves into a slot too (autosaveNow); the
// slot records the project file it came from, which the recovery offer names.
Result<void> writeUnsavedOrigin(const std::filesystem::path& slot, const std::filesystem::path& projectFile);
// That project file; empty for a never-saved project's slot.
std::filesystem::path unsavedAutosaveOrigin(const std::filesystem::path& slot);
// Whether `folder` is a slot of the unsaved folder (where a recovered project lives until saved).
bool isUnsavedSlot(const std::filesystem::path& folder);
// Removes a slot of the unsaved folder (nothing outside it) and forgets it.
void removeUnsavedSlot(std::filesystem::path& slot);

// The autosaved project, if one is left from a session that did not close cleanly: the project
// as the user had it, its map fields naming the side maps (and its file the real project's).
std::optional<core::LoadedProject> findAutosave(const core::LoadedProject& loaded);
// Once the scene is grown from the recovered project (so it holds the side maps' texels): the
// map fields get their real names back and those maps count as painted, so the next save
// writes them where they belong; the project counts as unsaved.
void markRecoveredMaps(EditorState& state);

// How long ago `seconds` is, as the recovery offer says it: "just now", "5 minutes ago",
// "3 hours ago", "2 days ago".
std::string timeAgo(double seconds);

// The "Recover unsaved work?" window while state.recoveryOffer is set: which work (the
// project's name, or its file) and how long ago it was autosaved.
void recoveryWindow(ui::Context& ctx, EditorState& state);

}  // namespace grass::editor
