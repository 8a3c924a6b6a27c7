#include "app/setting_widget.h"

#include <algorithm>
#include <cmath>

#include "ui/color_edit.h"
#include "ui/text_edit.h"

namespace grass::editor::setting_widget {

namespace {

using core::json::NumberRule;

bool within(const NumberRule& rule, float value) {
    const double v = value;
    return std::isfinite(v) && (rule.minOpen ? v > rule.min : v >= rule.min) &&
           (rule.maxOpen ? v < rule.max : v <= rule.max);
}

// The widget's track: the hint's when it gives one, else the rule's finite ends.
struct Track {
    float min;
    float max;
};
Track trackFor(const NumberRule& rule, const UiHint& hint) {
    if (hint.min != hint.max)
        return {hint.min, hint.max};
    const auto end = [](double bound, float fallback) {
        return std::isfinite(bound) ? static_cast<float>(bound) : fallback;
    };
    return {end(rule.min, -std::numeric_limits<float>::infinity()),
            end(rule.max, std::numeric_limits<float>::infinity())};
}

// A value outside what the loader accepts (an open end reached) goes back to what it was.
ui::Response keepWithin(const NumberRule& rule, float before, float& value, ui::Response r) {
    if (!within(rule, value))
        value = before;
    return r;
}

ui::Response mergeChanged(ui::Response into, const ui::Response& other) {
    return other.changed() ? into.markChanged() : into;
}

}  // namespace

std::string labelFor(std::string_view key, std::string_view label, std::string_view unit) {
    std::string text(label.empty() ? key : label);
    if (label.empty())
        std::replace(text.begin(), text.end(), '_', ' ');
    if (!unit.empty())
        text += " " + std::string(unit);
    return text;
}

ui::Response number(ui::Ui& ui, std::string_view label, float& value, const NumberRule& rule,
                    const UiHint& hint) {
    const float before = value;
    const Track track = trackFor(rule, hint);
    const bool slider = hint.slider && std::isfinite(track.min) && std::isfinite(track.max);
    const ui::Response r =
        slider ? ui::sliderWithEntry(ui, label, value, track.min, track.max,
                                     {.logarithmic = hint.logarithmic, .decimals = hint.decimals})
               : ui::dragValueWithEntry(ui, label, value, hint.speed, track.min, track.max,
                                        hint.decimals);
    return keepWithin(rule, before, value, r);
}

ui::Response integer(ui::Ui& ui, std::string_view label, int& value, std::int64_t min,
                     std::int64_t max) {
    const int lo = static_cast<int>(std::max<std::int64_t>(min, std::numeric_limits<int>::min()));
    const int hi = static_cast<int>(std::min<std::int64_t>(max, std::numeric_limits<int>::max()));
    // A short range is a slider; a long one (blades per clump, 0..10000) a drag box.
    constexpr std::int64_t SLIDER_STEPS = 64;
    return max - min <= SLIDER_STEPS ? ui.slider(label, value, lo, hi)
                                     : ui.dragValue(label, value, 1.0f, lo, hi);
}

ui::Response flag(ui::Ui& ui, std::string_view label, bool& value) {
    return ui.checkbox(value, label);
}

ui::Response vector(ui::Ui& ui, std::string_view label, glm::vec3& value, const NumberRule& rule,
                    const UiHint& hint) {
    const Track track = trackFor(rule, hint);
    ui::Response merged;
    ui.withId(label, [&](ui::Ui& inner) {
        inner.horizontal([&](ui::Ui& row) {
            for (int c = 0; c < 3; ++c) {
                row.pushId(std::uint64_t(c));
                const float before = value[c];
                const ui::Response r = row.dragValue(c == 2 ? label : "", value[c], hint.speed,
                                                     track.min, track.max, hint.decimals);
                merged = mergeChanged(c == 0 ? r : merged, keepWithin(rule, before, value[c], r));
                row.popId();
            }
        });
    });
    return merged;
}

ui::Response colour(ui::Ui& ui, std::string_view label, glm::vec3& value) {
    return ui::colorEdit(ui, label, value, true);
}

ui::Response range(ui::Ui& ui, std::string_view label, float& min, float& max,
                   const NumberRule& rule, const UiHint& hint) {
    const Track track = trackFor(rule, hint);
    ui::Response merged;
    ui.withId(label, [&](ui::Ui& inner) {
        inner.horizontal([&](ui::Ui& row) {
            row.pushId("min");
            const float minBefore = min;
            merged = keepWithin(rule, minBefore, min,
                                row.dragValue("", min, hint.speed, track.min, max, hint.decimals));
            row.popId();
            const float maxBefore = max;
            merged = mergeChanged(
                merged, keepWithin(rule, maxBefore, max,
                                   row.dragValue(label, max, hint.speed, min, track.max,
                                                 hint.decimals)));
        });
    });
    return merged;
}

ui::Response choice(ui::Ui& ui, std::string_view label, std::size_t& index,
                    std::span<const std::string_view> names) {
    int selected = static_cast<int>(index);
    const ui::Response r = ui.comboBox(label, selected, names);
    if (r.changed())
        index = static_cast<std::size_t>(selected);
    return r;
}

}  // namespace grass::editor::setting_widget
