#include "cli/bench_options.h"

#include "cli/parse_arguments.h"
#include "util/arg_parser.h"

namespace grass::cli {

namespace {

void describeOptions(ArgParser& parser, BenchArgs& args) {
    parser.text("--cases", "LIST",
                "comma-separated cases: nature-100k, nature-100k-all (every blade drawn at full "
                "detail without MSAA: what a drawn blade costs), helicopter-100k, winter-100k "
                "(snow on), "
                "nature-1m, helicopter-1m, nature-1m-all (a million blades drawn in full), "
                "nature-1m-hybrid (nature-1m as the hybrid technique: billboards beyond the "
                "cross-fade), "
                "nature-10m, editor-meadow (the editor window orbiting, painting "
                "and playing the meadow at wall-clock time; needs a display or xvfb-run), tiny "
                "and tiny-hybrid (tests/data/projects/tiny, for tests); default: every case "
                "but tiny, tiny-hybrid, nature-1m-all, nature-1m-hybrid and nature-10m",
                &args.cases);
    parser.flag("--quick", "only the cases of 100k blades or fewer", &args.quick);
    parser.integer("--frames", "timed frames per case, after the warm-up", &args.frames, 1, 1000);
    parser.integer("--frames-1m", "timed frames of the 1M-blade cases", &args.framesLarge, 1, 1000);
    parser.integer("--warmup", "untimed frames first; the last gives the cull counts", &args.warmup,
                   1, 100);
    parser.integer("--steps", "timed physics steps per case", &args.steps, 1, 10000);
    parser.integer("--steps-1m", "timed physics steps of the 1M-blade cases", &args.stepsLarge, 1,
                   10000);
    parser.integer("--width", "image width in pixels", &args.width, 1, 16384);
    parser.integer("--height", "image height in pixels", &args.height, 1, 16384);
    parser.choice("--msaa", {"0", "1", "2", "4", "8"},
                  "multisample anti-aliasing samples per pixel", &args.msaa);
    parser.choice("--geometry", {"auto", "tess", "strips"},
                  "blade geometry path for every case; auto = strips on software GL, "
                  "tessellation on a GPU",
                  &args.geometry);
    parser.text("--root", "DIR",
                "folder holding projects/ and tests/data/ (default: the source tree)", &args.root);
    parser.text("--out", "FILE.json", "write the results as JSON (atomically)", &args.out);
    parser.text("--compare", "OLD.json",
                "also print each figure as this run / OLD (a file from --out) as ratios",
                &args.compare);
    parser.text("--results", "FILE.json",
                "print a saved run (from --out) instead of measuring; with --compare, compare "
                "two saved runs",
                &args.results);
    parser.flag("--gl-debug", "print GL debug output (errors and warnings from the driver)",
                &args.glDebug);
}

}  // namespace

std::optional<int> parseBenchArgs(const std::vector<std::string>& argv, BenchArgs& args) {
    ArgParser parser(
        "grass bench [--quick] [--cases LIST] [--frames N] [--out FILE.json] [--compare "
        "OLD.json]",
        "Runs the standard benchmark set: the paper scenes projects/nature and "
        "projects/helicopter at about 100k and 1M blades, and projects/winter at 100k with its "
        "snow, at 1280x720 from each project's first camera. A case scales every layer's density "
        "by target / (estimated blades of the project) and divides clump spacing by the square "
        "root of that factor. Prints one table: blades in and drawn, culled share, frame wall "
        "ms and per-stage GPU ms (cull, opaque, grass, snow depth pass) as medians over the "
        "timed frames, physics ms per step and blade-steps per second (compute shader), and UI "
        "ms (one frame of the editor's panels: build, layout, tessellation), under the GL "
        "renderer string. Progress goes to stderr. The full set takes a few minutes on a 2-core "
        "software rasterizer; --quick under a minute. Ctrl+C ends the run after the case under "
        "way, printing and saving the cases measured (exit 130); a second Ctrl+C ends it at "
        "once. GRASS_COMPUTE_GROUP=N (32 to 256, a multiple of 32; 32 when unset) sizes the "
        "work groups of the physics and cull compute passes, and the table says which.");
    describeOptions(parser, args);
    if (const auto exitCode = parseArguments(parser, argv, "bench"))
        return exitCode;
    for (const char* option :
         {"--cases", "--quick", "--out", "--frames", "--frames-1m", "--warmup", "--steps",
          "--steps-1m", "--width", "--height", "--msaa", "--geometry", "--root"})
        if (parser.given(option)) {
            args.measuringOption = option;
            break;
        }
    return std::nullopt;
}

}  // namespace grass::cli
