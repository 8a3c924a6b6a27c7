// The editor's widget for a project setting, drawn from the setting's row: it shows the row's
// label and unit, its range is the loader's, and it never leaves a value the loader refuses.
#include "app/setting_widget.h"

#include <gtest/gtest.h>

#include <array>

#include "project/settings.h"
#include "ui/ui_harness.h"

namespace grass::editor {
namespace {

using core::settings::field;
using ui::test::findText;
using ui::test::UiHarness;

struct Sample {
    float radius = 0.5f;   // (0, ∞): an open lower end the drag box reaches
    float weight = 0.25f;  // [0, 1]
};

constexpr std::array SAMPLE_ROWS{
    field<&Sample::radius>({.key = "radius", .rule = core::json::POSITIVE, .unit = "m"}),
    field<&Sample::weight>({.key = "blend_weight", .rule = core::json::UNIT_INTERVAL}),
};

struct Fixture {
    UiHarness h;
    Sample sample;
    ui::Response last;
    const ui::Output& frame() {
        return h.frame([&](ui::Ui& ui) {
            for (const auto& row : SAMPLE_ROWS)
                last = settingWidget(ui, row, sample);
        });
    }
    // Presses on `text` and drags `dx` points right over four frames.
    void drag(std::string_view text, float dx) {
        const auto box = findText(frame(), text);
        ASSERT_TRUE(box.has_value()) << "nothing reads \"" << text << "\"";
        h.moveTo(box->centre());
        frame();
        h.press();
        frame();
        for (int i = 0; i < 4; ++i) {
            h.input.pointerPos.x += 0.25f * dx;
            frame();
        }
        h.release();
        frame();
    }
};

TEST(SettingWidget, LabelsComeFromTheRowWithTheirUnit) {
    Fixture f;
    const ui::Output& out = f.frame();
    EXPECT_TRUE(findText(out, "radius m").has_value());
    EXPECT_TRUE(findText(out, "blend weight").has_value()) << "the key with spaces";
}

TEST(SettingWidget, AnOpenEndIsNeverReached) {
    Fixture f;
    f.drag("0.50", -5000.0f);  // far left: the box stops at 0, which (0, ∞) refuses
    EXPECT_GT(f.sample.radius, 0.0f);
    f.drag("0.25", 5000.0f);  // far right: [0, 1] stops at 1
    EXPECT_EQ(f.sample.weight, 1.0f);
}

TEST(SettingWidget, EveryNumberOfTheSnowSectionStaysLoadable) {
    // Each snow number dragged to both ends of its widget: the project still loads.
    for (const auto& row : core::settings::snow()) {
        for (const float dx : {-1e5f, 1e5f}) {
            UiHarness h;
            core::Project project;
            core::SnowParams& snow = project.snow;
            const auto build = [&](ui::Ui& ui) { settingWidget(ui, row, snow); };
            const ui::Output& out = h.frame(build);
            // The first value box of the row: the text right of the track or in the box.
            std::optional<ui::Rect> box;
            for (const ui::ClippedShape& shape : out.shapes)
                if (const auto* t = std::get_if<ui::TextShape>(&shape.shape);
                    t && !t->text.empty() && (std::isdigit(static_cast<unsigned char>(t->text[0])) ||
                                              t->text[0] == '-'))
                    box = box ? box : findText(out, t->text);
            if (!box)
                continue;  // a checkbox, a colour, the combo box
            h.moveTo(box->centre());
            h.frame(build);
            h.press();
            h.frame(build);
            h.input.pointerPos.x += dx;
            h.frame(build);
            h.release();
            h.frame(build);
            if (snow.amountM > snow.maxAmountM)
                snow.amountM = snow.maxAmountM;  // the panel bounds these two by each other
            const auto reread = core::parseProject(core::serializeProject(project), "p.json");
            EXPECT_TRUE(reread.ok()) << row.key << " dragged by " << dx << ": "
                                     << (reread ? "" : reread.error().message);
        }
    }
}

}  // namespace
}  // namespace grass::editor
