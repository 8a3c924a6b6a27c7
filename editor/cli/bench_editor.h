// grass bench's editor case (issue 24): the real editor — grass-editor next to grass, its window,
// its UI, its live physics — on a copy of the case's project, replaying an orbit, a paint stroke
// and playback at wall-clock time (`--script … --wall-clock`), under the display or, with none,
// xvfb-run. The figures are the session's own summary (editor/app/session_stats.h).
#pragma once

#include <filesystem>
#include <string>

#include "cli/bench_report.h"
#include "util/result.h"

namespace grass::cli {

// The session's script for a window of width × height: the phases orbit, paint and play, with
// settle phases between them (input stopped: the full picture comes back).
std::string editorBenchScript(int width, int height);

// Reads the summary lines the editor printed; the error says which figure is missing.
Result<EditorFigures> parseEditorSummary(const std::string& output);

// Runs the session on a copy of `project` (the stroke paints, the copy is removed after).
Result<EditorFigures> measureEditor(const std::filesystem::path& project, bool glDebug);

}  // namespace grass::cli
