// The editor's widget for one project setting, drawn from its row (core/project/setting.h): the
// label, unit, range, enum names and widget kind come from the row, so a panel names the keys it
// shows and holds no copies of ranges or names. A widget never leaves a value the loader would
// refuse: a drag outside the row's range is undone, a typed value outside it refused in its box
// with the row's range and unit.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include <glm/glm.hpp>

#include "project/setting.h"
#include "project/setting_text.h"
#include "util/assert.h"
#include "ui/text_edit.h"
#include "ui/ui.h"

namespace grass::editor {

namespace setting_widget {

using core::settings::UiHint;

// "max amount m": the row's label (or its key with spaces) and its unit.
std::string labelFor(std::string_view key, std::string_view label, std::string_view unit);

// `unit` names the unit in a refused entry's reason.
// `limit`, when given, refuses values the format allows but the scene cannot take (a density
// that would grow more blades than a scene may hold): a typed one in its box, a dragged one by
// undoing the drag's step, as a step outside the row's range is, with `limit`'s reason in
// `refused` (when given) for the panel to say.
ui::Response number(ui::Ui& ui, std::string_view label, float& value,
                    const core::json::NumberRule& rule, const UiHint& hint,
                    std::string_view unit = {}, const ui::NumberCheck& limit = {},
                    std::string* refused = nullptr);
ui::Response integer(ui::Ui& ui, std::string_view label, int& value, std::int64_t min,
                     std::int64_t max);
ui::Response flag(ui::Ui& ui, std::string_view label, bool& value);
ui::Response vector(ui::Ui& ui, std::string_view label, glm::vec3& value,
                    const core::json::NumberRule& rule, const UiHint& hint,
                    std::string_view unit = {});
ui::Response colour(ui::Ui& ui, std::string_view label, glm::vec3& value);
ui::Response range(ui::Ui& ui, std::string_view label, float& min, float& max,
                   const core::json::NumberRule& rule, const UiHint& hint,
                   std::string_view unit = {});
ui::Response choice(ui::Ui& ui, std::string_view label, std::size_t& index,
                    std::span<const std::string_view> names);

}  // namespace setting_widget

// The widget of `row` editing `value`; `hint` replaces the row's (a range bounded by another
// setting, as snow amount by max amount); `limit` and `refused` as for setting_widget::number.
// Custom rows and text have no generic widget: the panel draws those itself (this returns an
// unchanged Response).
template <class S>
ui::Response settingWidget(ui::Ui& ui, const core::settings::Setting<S>& row, S& value,
                           const core::settings::UiHint* hint = nullptr,
                           const ui::NumberCheck& limit = {}, std::string* refused = nullptr) {
    namespace w = setting_widget;
    namespace s = core::settings;
    const std::string label = w::labelFor(row.key, row.label, row.unit);
    const s::UiHint& uiHint = hint ? *hint : row.ui;
    ui::Response response = std::visit(
        [&](const auto& access) -> ui::Response {
            using A = std::remove_cvref_t<decltype(access)>;
            if constexpr (std::is_same_v<A, s::Ref<S, float>>) {
                return w::number(ui, label, access.get(value), row.rule, uiHint, row.unit, limit,
                                 refused);
            } else if constexpr (std::is_same_v<A, s::Ref<S, int>>) {
                return w::integer(ui, label, access.get(value), row.intMin, row.intMax);
            } else if constexpr (std::is_same_v<A, s::Ref<S, std::uint32_t>>) {
                std::uint32_t& stored = access.get(value);
                ui::Response r;
                if (row.kind == s::Kind::Flag) {
                    bool on = stored != 0u;
                    r = w::flag(ui, label, on);
                    stored = on ? 1u : 0u;
                } else {
                    int n = static_cast<int>(stored);
                    r = w::integer(ui, label, n, row.intMin, row.intMax);
                    stored = static_cast<std::uint32_t>(n);
                }
                return r;
            } else if constexpr (std::is_same_v<A, s::Ref<S, bool>>) {
                return w::flag(ui, label, access.get(value));
            } else if constexpr (std::is_same_v<A, s::Ref<S, glm::vec3>>) {
                return row.kind == s::Kind::Colour
                           ? w::colour(ui, label, access.get(value))
                           : w::vector(ui, label, access.get(value), row.rule, uiHint, row.unit);
            } else if constexpr (std::is_same_v<A, s::Ref<S, glm::vec2>>) {
                glm::vec2& v = access.get(value);
                return w::range(ui, label, v.x, v.y, row.rule, uiHint, row.unit);
            } else if constexpr (std::is_same_v<A, s::RangePair<S>>) {
                return w::range(ui, label, access.min.get(value), access.max.get(value), row.rule,
                                uiHint, row.unit);
            } else if constexpr (std::is_same_v<A, s::ChoiceRef<S>>) {
                std::size_t index = access.get(value);
                const ui::Response r = w::choice(ui, label, index, row.names);
                if (r.changed())
                    access.set(value, index);
                return r;
            } else {
                return ui::Response();
            }
        },
        row.access);
    // What it is, its unit and range, where it is saved (issue 26 item 4): the row's own words,
    // as docs/project-format.md has them.
    response.onHoverText(s::settingTooltip(row));
    return response;
}

// The widget of the row named `key` (a key the table lacks is a programming error).
template <class S>
ui::Response settingWidget(ui::Ui& ui, std::span<const core::settings::Setting<S>> table,
                           std::string_view key, S& value,
                           const core::settings::UiHint* hint = nullptr,
                           const ui::NumberCheck& limit = {}, std::string* refused = nullptr) {
    const core::settings::Setting<S>* row = core::settings::findSetting(table, key);
    GRASS_ASSERT(row != nullptr);
    return settingWidget(ui, *row, value, hint, limit, refused);
}

}  // namespace grass::editor
