#include "cli/bench_editor.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>
#include <unistd.h>

#include "project/project.h"

namespace grass::cli {

namespace {

namespace fs = std::filesystem;

// The viewport's middle: the side panel takes the left 330 points, the menu and status bars
// 26 points each.
struct ViewArea {
    int x0, y0, x1, y1;
    int cx() const { return (x0 + x1) / 2; }
    int cy() const { return (y0 + y1) / 2; }
};

constexpr int DRAG_FRAMES = 40;

Result<fs::path> editorExecutable() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    const fs::path editor = self.parent_path() / "grass-editor";
    if (ec || !fs::exists(editor))
        return makeError("editor-meadow",
                         "grass-editor not found next to grass (" + editor.string() +
                             "): build it, or leave the case out of --cases");
    return editor;
}

// The last lines of a log, for an error message.
std::string tail(const fs::path& log) {
    std::ifstream in(log);
    std::string line, last;
    std::vector<std::string> lines;
    while (std::getline(in, line))
        lines.push_back(line);
    for (std::size_t i = lines.size() > 4 ? lines.size() - 4 : 0; i < lines.size(); ++i)
        last += "\n  " + lines[i];
    return last;
}

}  // namespace

std::string editorBenchScript(int width, int height) {
    const ViewArea view{330, 26, width, height - 26};
    std::ostringstream s;
    // The editor opens playing; playback keeps the picture reduced (issue 24), so the orbit and
    // the stroke happen paused, and playback has a phase of its own, paused again after it.
    s << "# grass bench editor case: orbit, paint, play at wall-clock time\n"
      << "wait 2\nkey space\nphase open\nwait-s 2\n";
    const auto drag = [&](int fromX, int y) {
        s << "move " << fromX << ' ' << y << "\npress\n";
        for (int i = 1; i <= DRAG_FRAMES; ++i)
            s << "move " << fromX + i * (view.x1 - view.x0) / (3 * DRAG_FRAMES) << ' '
              << y + (i % 5) << '\n';
        s << "release\n";
    };
    s << "phase orbit\n";
    drag(view.cx() - (view.x1 - view.x0) / 6, view.cy());
    // The stroke subtracts (Ctrl inverts the brush's add): an add on the meadow's full density
    // map changes nothing, and since the viewport draws only what changed (app/view_redraw.h) its
    // frames drew nothing and timed only the panels.
    s << "phase settle\nwait-s 2\nkey b\nhold ctrl\nphase paint\n";
    drag(view.cx() - (view.x1 - view.x0) / 6, view.cy() + (view.y1 - view.y0) / 6);
    s << "hold none\nkey c\nphase settle\nwait-s 2\nkey space\nphase play\nwait-s 5\nkey space\n"
      << "phase settle\nwait-s 2\n";
    return s.str();
}

Result<EditorFigures> parseEditorSummary(const std::string& output) {
    EditorFigures figures;
    bool orbit = false, paint = false, play = false, full = false;
    std::istringstream in(output);
    std::string line;
    while (std::getline(in, line)) {
        char phase[64] = "";
        EditorPhaseFigures f;
        double slowest = 0.0, realTime = 0.0, fullS = 0.0;
        std::size_t of = 0;
        if (std::sscanf(line.c_str(),
                        "frames %63[^:]: %d, median %lf ms, 95th percentile %lf ms, slowest %lf ms, "
                        "real time %lf",
                        phase, &f.frames, &f.medianMs, &f.p95Ms, &slowest, &realTime) == 6) {
            const std::string name = phase;
            if (name == "orbit")
                figures.orbit = f, orbit = true;
            else if (name == "paint")
                figures.paint = f, paint = true;
            else if (name == "play") {
                figures.play = f, play = true;
                figures.realtimeFactor = realTime;
            }
        } else if (std::sscanf(line.c_str(), "full quality after input stops: %lf s (slowest of %zu)",
                               &fullS, &of) == 2) {
            figures.fullQualityS = fullS;
            full = true;
        }
    }
    if (!orbit || !paint || !play)
        return makeError("editor-meadow", "the editor's session printed no frame times for " +
                                              std::string(!orbit ? "orbit" : !paint ? "paint" : "play"));
    if (!full)
        return makeError("editor-meadow",
                         "the editor's session never returned to the full picture after input");
    return figures;
}

Result<EditorFigures> measureEditor(const fs::path& project, bool glDebug) {
    auto editor = editorExecutable();
    if (!editor)
        return editor.error();
    auto loaded = core::loadProject(project);
    if (!loaded)
        return loaded.error();
    std::error_code ec;
    const fs::path scratch =
        fs::temp_directory_path(ec) / ("grass-bench-editor-" + std::to_string(::getpid()));
    fs::remove_all(scratch, ec);
    fs::create_directories(scratch, ec);
    fs::copy(loaded->folder, scratch / "project", fs::copy_options::recursive, ec);
    if (ec)
        return makeError(scratch.string(), "cannot copy the project there: " + ec.message());
    {
        std::ofstream script(scratch / "session.txt");
        script << editorBenchScript(loaded->project.render.width, loaded->project.render.height);
    }
    const fs::path log = scratch / "editor.log";
    const char* display = std::getenv("DISPLAY");
    const std::string prefix = display && *display ? "" : "xvfb-run -a -s '-screen 0 1920x1200x24' ";
    // The session opens a copy that is deleted afterwards: its own configuration folder keeps
    // it out of the user's File > Open Recent.
    const std::string command = "XDG_CONFIG_HOME='" + (scratch / "config").string() +
                                "' XDG_STATE_HOME='" + (scratch / "state").string() + "' " +
                                prefix + "'" + editor->string() + "' '" +
                                (scratch / "project").string() + "' --script '" +
                                (scratch / "session.txt").string() + "' --wall-clock" +
                                (glDebug ? " --gl-debug" : "") + " 2> '" + log.string() + "'";
    std::string output;
    if (FILE* pipe = ::popen(command.c_str(), "r")) {
        char buffer[512];
        while (std::fgets(buffer, sizeof buffer, pipe))
            output += buffer;
        const int status = ::pclose(pipe);
        if (status != 0) {
            const std::string why = tail(log);
            fs::remove_all(scratch, ec);
            return makeError("editor-meadow", "grass-editor failed (" + command + "):" + why);
        }
    } else {
        return makeError("editor-meadow", "cannot run grass-editor");
    }
    fs::remove_all(scratch, ec);
    return parseEditorSummary(output);
}

}  // namespace grass::cli
