// grass-editor: the authoring window. A menu bar (File), a side panel with the project's layers,
// wind, colliders and render settings, a status bar with blade counts and pass times, and the
// 3D viewport in what is left: drag to orbit, wheel to zoom, middle- or shift-drag to pan, F to
// frame the scene; 1–4 switch the cull tests, T the technique, L the lighting. Quitting with
// unsaved changes asks first. The UI takes the pointer and keys when it wants them
// (ui::Output). --screenshot saves what the window shows after --frames frames and exits, so
// tests and users can see the editor without a person; --no-ui shows the viewport alone.
#include <cstdio>
#include <stop_token>
#include <string>
#include <vector>

#include "app/editor.h"
#include "gl/debug_output.h"
#include "util/arg_parser.h"
#include "util/image_file.h"
#include "util/interrupt_stop.h"
#include "util/version.h"

namespace {

using namespace grass;

int fail(const std::string& message, int code = 1) {
    std::fprintf(stderr, "grass-editor: %s\n", message.c_str());
    return code;
}

}  // namespace

int main(int argc, char** argv) {
    editor::EditorSettings settings;
    bool noAdaptive = false;
    std::string physicsDevice = "auto";
    settings.projectPath = std::string(GRASS_SOURCE_DIR) + "/projects/meadow";
    settings.glDebug = gl::GL_DEBUG_BY_DEFAULT;
    ArgParser parser("grass-editor [project-dir|project.json|mesh.glb] [--screenshot F.png --frames N]",
                     "Opens the grass editor on a project (default: projects/meadow), or on a "
                     "new unsaved project around a .gltf/.glb mesh (as File > New from mesh): a File "
                     "menu, a side panel with the layers, wind, colliders and render settings, "
                     "and the viewport. Drag to orbit, wheel to zoom, middle- or shift-drag to "
                     "pan, F to frame (Esc closes with --no-ui); keys 1-4 switch the "
                     "orientation, frustum, distance and occlusion culling, T cycles blades / "
                     "billboards / hybrid / growth (stem sets), L toggles the grass lighting.");
    parser.positional("project", "a project folder (with project.json), a .json file, or a .gltf/.glb mesh to grow a new project on",
                      &settings.projectPath, false);
    parser.text("--screenshot", "FILE",
                "save what the window shows after --frames frames, then exit",
                &settings.screenshot);
    parser.integer("--frames",
                   "frames to draw before the screenshot (with --screenshot: default 3)",
                   &settings.frames, 1, 100000);
    parser.text("--script", "FILE",
                "replay recorded input (pointer, keys, waits, screenshots; see "
                "editor/app/input_script.h), one step of physics per frame, then exit",
                &settings.scriptFile);
    parser.flag("--wall-clock",
                "with --script: time, physics and autosave follow the wall clock, as in a "
                "session, instead of one physics step per frame (for tests of time)",
                &settings.wallClock);
    parser.integer("--frame-delay-ms", "add N ms to every frame, as a slower machine would "
                   "(for tests of time)",
                   &settings.frameDelayMs, 0, 10000);
    parser.integer("--load-delay-ms",
                   "add N ms to every New, Open, import, recovery and re-grow after an edit "
                   "of the layers, the project the window opens on included, as a large file "
                   "would (for tests of time)",
                   &settings.loadDelayMs, 0, 60000);
    parser.flag("--no-adaptive",
                "draw every frame at full quality (by default the viewport lowers MSAA, blade "
                "count, segments and resolution while you orbit, paint, drag or play, to keep "
                "--frame-budget-ms, and draws the full picture 0.3 s after input stops)",
                &noAdaptive);
    parser.flag("--redraw-every-frame",
                "draw the viewport's picture in every frame (by default a frame whose camera, "
                "project, time and field are as in the last drawn picture shows that picture "
                "again, and a window at rest waits for input; for tests that compare the two)",
                &settings.redrawEveryFrame);
    parser.number("--frame-budget-ms", "MS",
                  "the frame time the viewport keeps while you interact", &settings.frameBudgetMs,
                  5.0, 10000.0, "80");
    parser.number("--autosave-s", "S",
                  "seconds between autosaves of unsaved changes to <project>.autosave.json (0: "
                  "never); a project never saved, or whose folder cannot be written, autosaves "
                  "into $XDG_STATE_HOME/grass/unsaved (~/.local/state when unset)",
                  &settings.autosaveS, 0.0, 86400.0, "180");
    parser.flag("--recover",
                "take back an autosave left by a session that did not close cleanly without "
                "asking (otherwise a window offers it)",
                &settings.recover);
    parser.flag("--gl-debug", "print GL debug output (driver errors and warnings) to stderr",
                &settings.glDebug);
    parser.flag("--no-physics",
                "show the field at rest (by default gravity, wind and colliders run live, on the "
                "device --physics-device picks, one physics step of the project's step_s per elapsed step, at most 4 per "
                "frame; time beyond that is skipped, and the status bar says so)",
                &settings.noPhysics);
    parser.choice("--physics-device", {"auto", "cpu", "gpu"},
                  "where the live physics runs: the SIMD execution on the CPU (one upload of the "
                  "blades a frame) or the compute shader; auto: the CPU on software GL, where it "
                  "is ~10x faster (docs/physics.md), the GPU elsewhere",
                  &physicsDevice);
    parser.flag("--no-ui",
                "show the viewport alone over the whole window (what `grass render` draws; "
                "tests compare the two)",
                &settings.noUi);
    bool versionRequested = false;
    parser.flag("--version", "print the version and exit", &versionRequested);
    if (auto parsed = parser.parse(std::vector<std::string>(argv + 1, argv + argc)); !parsed)
        return fail(parsed.error().str(), 2);
    if (parser.helpRequested()) {
        std::fputs(parser.help().c_str(), stdout);
        return 0;
    }
    if (versionRequested) {
        std::printf("grass-editor %s\n", std::string(core::versionText()).c_str());
        return 0;
    }
    settings.adaptive = !noAdaptive;
    settings.physicsDevice = physicsDevice == "cpu"   ? editor::PhysicsDevice::Cpu
                             : physicsDevice == "gpu" ? editor::PhysicsDevice::Gpu
                                                      : editor::PhysicsDevice::Auto;
    if (!settings.screenshot.empty() && settings.frames == 0)
        settings.frames = 3;
    if (!settings.screenshot.empty())
        if (auto writable = checkImageWritable(settings.screenshot); !writable)
            return fail(writable.error().str(), 2);

    auto editor = editor::Editor::open(std::move(settings));
    if (!editor)
        return fail(editor.error().str(), editor.error().path == "--script" ? 2 : 1);
    if (!*editor)
        return 0;  // the window was closed while the first field grew: nothing to save
    // Ctrl+C in the terminal, or SIGTERM (a logout, a shutdown): the unsaved changes go into the
    // autosave and the editor ends (util/interrupt_stop.h); a second signal ends it at once. The
    // signal wakes a window waiting for input.
    const core::InterruptStop interrupt;
    const std::stop_callback wake(interrupt.token(), [] { editor::Window::wake(); });
    while (true) {
        if (interrupt.signal() != 0) {
            (*editor)->endInterrupted(interrupt.signal());
            return interrupt.exitCode();
        }
        const Result<bool> more = (*editor)->frame();
        if (!more)
            return fail(more.error().str());
        if (!*more)
            return 0;
    }
}
