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

// A typed value the loader would refuse is refused in the box, with the row's own range and
// unit ("must be in (0, 5000] m"), as docs/project-format.md states it.
ui::NumberCheck checkFor(const NumberRule& rule, std::string_view unit) {
    return [rule, unit = std::string(unit)](double typed) -> std::string {
        if (within(rule, static_cast<float>(typed)))
            return {};
        const std::string range = core::settings::ruleText(rule);
        const bool interval = range.front() == '[' || range.front() == '(';
        return core::settings::withUnit("must be " + std::string(interval ? "in " : "") + range, unit);
    };
}

// One response for a row of boxes: hovered (its tooltip) or changed when any box is.
ui::Response mergeChanged(ui::Response into, const ui::Response& other) {
    return into.unite(other);
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
                    const UiHint& hint, std::string_view unit, const ui::NumberCheck& limit,
                    std::string* refused) {
    const float before = value;
    const Track track = trackFor(rule, hint);
    const bool slider = hint.slider && std::isfinite(track.min) && std::isfinite(track.max);
    // The track bounds dragging; a typed value may go anywhere the rule allows.
    const ui::NumberCheck inRule = checkFor(rule, unit);
    const ui::NumberCheck check = [&](double typed) {
        std::string reason = inRule(typed);
        return reason.empty() && limit ? limit(typed) : reason;
    };
    const ui::Response r =
        slider ? ui::sliderWithEntry(ui, label, value, track.min, track.max,
                                     {.logarithmic = hint.logarithmic, .decimals = hint.decimals},
                                     check)
               : ui::dragValueWithEntry(ui, label, value, hint.speed, track.min, track.max,
                                        hint.decimals, check);
    keepWithin(rule, before, value, r);
    // A drag bypasses the box's check: a step `limit` refuses is undone (a typed value it
    // refused never reached `value`). On a 60 km sphere the density slider's lowest step, 1 /m²,
    // asked for 1e10 blades: the field could not grow, and the project kept the value.
    if (limit && value != before) {
        if (std::string reason = limit(value); !reason.empty()) {
            value = before;
            if (refused)
                *refused = std::move(reason);
        }
    }
    return r;
}

ui::Response integer(ui::Ui& ui, std::string_view label, int& value, std::int64_t min,
                     std::int64_t max) {
    const int lo = static_cast<int>(std::max<std::int64_t>(min, std::numeric_limits<int>::min()));
    const int hi = static_cast<int>(std::min<std::int64_t>(max, std::numeric_limits<int>::max()));
    // A short range is a slider whose box can be typed into; a long one (blades per clump,
    // 0..10000) a drag box that can.
    constexpr std::int64_t SLIDER_STEPS = 64;
    if (max - min > SLIDER_STEPS)
        return ui::dragValueWithEntry(ui, label, value, 1.0f, lo, hi);
    float proxy = static_cast<float>(value);
    const ui::Response r = ui::sliderWithEntry(
        ui, label, proxy, static_cast<float>(lo), static_cast<float>(hi), {.decimals = 0},
        [lo, hi](double typed) -> std::string {
            if (typed != std::floor(typed))
                return "must be a whole number";
            if (typed < lo || typed > hi)
                return "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
            return {};
        });
    value = static_cast<int>(std::lround(proxy));
    return r;
}

ui::Response flag(ui::Ui& ui, std::string_view label, bool& value) {
    return ui.checkbox(value, label);
}

ui::Response vector(ui::Ui& ui, std::string_view label, glm::vec3& value, const NumberRule& rule,
                    const UiHint& hint, std::string_view unit) {
    const Track track = trackFor(rule, hint);
    const ui::NumberCheck check = checkFor(rule, unit);
    ui::Response merged;
    ui.withId(label, [&](ui::Ui& inner) {
        inner.horizontal([&](ui::Ui& row) {
            for (int c = 0; c < 3; ++c) {
                row.pushId(std::uint64_t(c));
                const float before = value[c];
                const ui::Response r =
                    ui::dragValueWithEntry(row, c == 2 ? label : "", value[c], hint.speed,
                                           track.min, track.max, hint.decimals, check);
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
                   const NumberRule& rule, const UiHint& hint, std::string_view unit) {
    const Track track = trackFor(rule, hint);
    const ui::NumberCheck check = checkFor(rule, unit);
    // A typed end may not pass the other: the range would be empty.
    const auto atMost = [&](float bound) {
        return [check, bound](double typed) -> std::string {
            std::string reason = check(typed);
            return !reason.empty() || typed <= bound ? reason : "must not be above the maximum";
        };
    };
    const auto atLeast = [&](float bound) {
        return [check, bound](double typed) -> std::string {
            std::string reason = check(typed);
            return !reason.empty() || typed >= bound ? reason : "must not be below the minimum";
        };
    };
    ui::Response merged;
    ui.withId(label, [&](ui::Ui& inner) {
        inner.horizontal([&](ui::Ui& row) {
            row.pushId("min");
            const float minBefore = min;
            merged = keepWithin(rule, minBefore, min,
                                ui::dragValueWithEntry(row, "", min, hint.speed, track.min, max,
                                                       hint.decimals, atMost(max)));
            row.popId();
            const float maxBefore = max;
            merged = mergeChanged(
                merged, keepWithin(rule, maxBefore, max,
                                   ui::dragValueWithEntry(row, label, max, hint.speed, min,
                                                          track.max, hint.decimals, atLeast(min))));
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
