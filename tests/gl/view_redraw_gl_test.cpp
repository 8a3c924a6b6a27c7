// The viewport's picture is drawn only when something it shows changed (editor/app/view_redraw.h):
// a paused window at rest shows its last picture again instead of drawing the scene each frame
// (the meadow's frame at rest: 169 ms → 12 ms on llvmpipe), and a change of the camera, the
// technique, the lighting, an undo, a re-grow or a brush stroke draws it again. The pictures are
// the ones drawing every frame gives, pixel for pixel.
#include <gtest/gtest.h>

#include <cstdio>
#include <regex>
#include <string>
#include <vector>

#include "editor_runs.h"
#include "support/image_compare.h"
#include "support/test_paths.h"
#include "util/image_file.h"

namespace grass::test {
namespace {

// "viewport drawn in N of M frames": {N, M}, or {-1, -1} when the log has no such line.
std::pair<int, int> viewportDrawn(const std::string& log) {
    std::smatch match;
    if (!std::regex_search(log, match, std::regex("viewport drawn in ([0-9]+) of ([0-9]+) frames")))
        return {-1, -1};
    return {std::stoi(match[1]), std::stoi(match[2])};
}

// What each step does; a screenshot after each (the pointer then rests on the side panel's empty
// bottom, away from every widget).
struct Step {
    const char* name;
    const char* script;
    bool changesThePicture;
};
const std::vector<Step> STEPS = {
    {"paused", "key space\nwait 2\n", true},
    {"orbited", "drag 600 300 680 320 4\nwait 2\n", true},
    {"billboards", "key t\nwait 2\n", true},
    {"lighting", "key l\nwait 2\n", true},
    {"undone", "key ctrl+z\nwait 2\n", true},
    {"duplicated", "click 80 208\nwait 2\n", true},
    {"painted", "key b\nhold ctrl\ndrag 585 245 655 250 6\nhold none\nwait 2\n", true},
    {"rest", "wait 6\n", false},
};

std::string sessionScript() {
    std::string script;
    for (const Step& step : STEPS)
        script +=
            std::string(step.script) + "move 100 540\nwait 1\nscreenshot " + step.name + ".png\n";
    return script;
}

// The viewport of a step's screenshot (the 900 × 560 window less the side panel, the menu bar,
// the timeline and the status bar, whose title and timings differ from run to run).
Rgba8Pixels viewportShot(const std::filesystem::path& dir, const Step& step) {
    constexpr int LEFT = 340, TOP = 30, RIGHT = 890, BOTTOM = 470;
    auto image = readRgba8Image(dir / (std::string(step.name) + ".png"));
    EXPECT_TRUE(image.ok()) << (image.ok() ? "" : image.error().str());
    if (!image.ok() || image->width < RIGHT || image->height < BOTTOM)
        return {};
    Rgba8Pixels view{RIGHT - LEFT, BOTTOM - TOP, {}};
    for (int y = TOP; y < BOTTOM; ++y) {
        const auto row = image->pixels.begin() + 4 * (std::ptrdiff_t(y) * image->width + LEFT);
        view.pixels.insert(view.pixels.end(), row, row + 4 * view.width);
    }
    return view;
}

TEST(ViewRedraw, EachChangeDrawsThePictureAndAtRestTheLastOneShowsAgainAsDrawn) {
    const auto reused = scratchDir("view_redraw_reused");
    const auto drawn = scratchDir("view_redraw_every_frame");
    for (const auto& dir : {reused, drawn})
        writeTinyProject(dir, "tiny", 900, 560);
    const std::string reusedLog = runEditor(reused, sessionScript(), "", false);
    const std::string drawnLog = runEditor(drawn, sessionScript(), "--redraw-every-frame", false);

    const auto [reusedDraws, reusedFrames] = viewportDrawn(reusedLog);
    const auto [everyDraws, everyFrames] = viewportDrawn(drawnLog);
    ASSERT_GT(reusedFrames, 30) << reusedLog;
    EXPECT_EQ(everyDraws, everyFrames) << drawnLog;
    // Drawn at the start, in the steps' changes and their follow-up frames; not in the waits.
    EXPECT_LT(reusedDraws, reusedFrames / 2) << reusedLog;

    Rgba8Pixels previous;
    for (const Step& step : STEPS) {
        const Rgba8Pixels a = viewportShot(reused, step), b = viewportShot(drawn, step);
        ASSERT_FALSE(a.pixels.empty()) << step.name;
        ASSERT_EQ(a.width, b.width) << step.name;
        EXPECT_EQ(compareImages(a.pixels, b.pixels, 0).maxChannel, 0)
            << step.name << ": the picture shown again is not the one drawing it gives";
        if (!previous.pixels.empty()) {
            const int changed = compareImages(previous.pixels, a.pixels, 0).maxChannel;
            if (step.changesThePicture)
                EXPECT_GT(changed, 0) << step.name << " did not change the picture";
            else
                EXPECT_EQ(changed, 0) << step.name;
        }
        previous = a;
    }
}

}  // namespace
}  // namespace grass::test
