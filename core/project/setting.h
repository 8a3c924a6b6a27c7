// One description per project.json setting: its key, the member it fills, its type, its
// allowed range, its unit, the names of its enum values and a line of help. The same table
// drives the reader (setting_io.h), the writer, the refusal messages, docs/project-format.md's
// tables (setting_docs.h, checked by a test) and the editor's widgets (editor/app/setting_widget.h).
// Adding a setting means adding one row to its section's table (project/settings.h).
//
// A row names its member by a chain of member pointers (`field<&Layer::scatter,
// &ScatterParams::density>`), so the table holds plain data and two function pointers, no copies.
// Settings that do not fit one member of one JSON type (gravity, paths, msaa) are `custom`: the
// row carries their reader and writer and still gives key, doc text and order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "project/json_reader.h"

namespace grass::core::settings {

// What a setting is in the file, and which widget the editor gives it.
enum class Kind {
    Auto,       // deduced from the member's type by field<>
    Number,     // float
    Integer,    // int or std::uint32_t (intMin .. intMax), std::uint64_t (any)
    Flag,       // bool
    Vector,     // glm::vec3, [x, y, z]
    Colour,     // glm::vec3, [r, g, b]
    Range,      // glm::vec2 or two floats, [min, max] with min <= max
    Choice,     // an enum class written as one of `names`
    Text,       // std::string, not empty unless `allowEmpty`
    AssetPath,  // std::string, a relative asset path (or "" when `allowEmpty`)
    Custom,     // its own reader and writer
};

// How the editor draws a number: the slider's track (defaults to the allowed range when both
// ends are finite), decimals, drag speed, logarithmic track. UI only; the file ignores it.
struct UiHint {
    float min = 0.0f;
    float max = 0.0f;  // min == max: use the allowed range
    int decimals = 2;
    float speed = 0.01f;
    bool logarithmic = false;
    bool slider = false;  // a slider track rather than a drag box
};

template <class S, class T>
struct Ref {
    T& (*get)(S&) = nullptr;
    const T& (*view)(const S&) = nullptr;
};

// An enum class member as an index into `names`.
template <class S>
struct ChoiceRef {
    std::size_t (*get)(const S&) = nullptr;
    void (*set)(S&, std::size_t) = nullptr;
};

// A [min, max] kept as two float members.
template <class S>
struct RangePair {
    Ref<S, float> min;
    Ref<S, float> max;
};

// Reads its key (the row's, given) from the object, which has checked the keys, and writes its
// JSON value; a writer returning null leaves the key out of the file.
template <class S>
struct CustomIo {
    void (*read)(json::Reader&, json::Object&, std::string_view key, S&) = nullptr;
    json::Json (*write)(const S&) = nullptr;
};

template <class S>
using Access =
    std::variant<std::monostate, Ref<S, float>, Ref<S, int>, Ref<S, std::uint32_t>,
                 Ref<S, std::uint64_t>, Ref<S, bool>, Ref<S, glm::vec3>, Ref<S, glm::vec2>,
                 Ref<S, std::string>, RangePair<S>, ChoiceRef<S>, CustomIo<S>>;

template <class S>
struct Setting {
    std::string_view key{};
    Kind kind = Kind::Auto;
    json::NumberRule rule{};               // Number, Vector, Colour, Range: each component
    std::int64_t intMin = 0;               // Integer
    std::int64_t intMax = 0;               // Integer (intMin == intMax: any std::uint64_t)
    std::span<const std::string_view> names{};  // Choice
    bool allowEmpty = false;               // Text, AssetPath
    std::string_view unit{};               // "m", "s", "Hz", "m/s": shown in docs and labels
    std::string_view help{};               // one line for the doc table and the tooltip
    std::string_view label{};              // the editor's label; empty: the key with spaces
    std::string_view typeText{};           // Custom: the doc's type column
    std::string_view allowedText{};        // the doc's allowed column, when the rule can't say it
    std::string_view defaultText{};        // the doc's default column, when the writer can't say it
    // A setting that only some objects have (a mesh collider's file): when false the key is
    // refused with `onlyText` and not written.
    bool (*applies)(const S&) = nullptr;
    std::string_view onlyText{};
    UiHint ui{};
    Access<S> access{};
};

namespace detail {

// `row` with `access`, built whole: clang cannot switch a variant's alternative by assignment in
// a constant expression, so the member is initialised, never assigned.
template <class S>
constexpr Setting<S> withAccess(const Setting<S>& row, Kind kind, Access<S> access) {
    return Setting<S>{row.key,       kind,           row.rule,        row.intMin,
                      row.intMax,    row.names,      row.allowEmpty,  row.unit,
                      row.help,      row.label,      row.typeText,    row.allowedText,
                      row.defaultText, row.applies,  row.onlyText,    row.ui,
                      access};
}

template <class M>
struct MemberTraits;
template <class C, class T>
struct MemberTraits<T C::*> {
    using Class = C;
};

// The class the first member pointer of a chain belongs to (a struct: an alias template may not
// take a pack into a non-pack parameter).
template <auto First, auto... Rest>
struct FirstOwner {
    using Type = typename MemberTraits<decltype(First)>::Class;
};
template <auto... Members>
using Owner = typename FirstOwner<Members...>::Type;

template <auto... Members>
using Value = std::remove_cvref_t<decltype((std::declval<Owner<Members...>&>() .* ... .* Members))>;

template <class T>
constexpr Kind kindOf() {
    if constexpr (std::is_same_v<T, float>)
        return Kind::Number;
    else if constexpr (std::is_same_v<T, bool>)
        return Kind::Flag;
    else if constexpr (std::is_integral_v<T>)
        return Kind::Integer;
    else if constexpr (std::is_same_v<T, glm::vec3>)
        return Kind::Vector;
    else if constexpr (std::is_same_v<T, glm::vec2>)
        return Kind::Range;
    else if constexpr (std::is_enum_v<T>)
        return Kind::Choice;
    else
        return Kind::Text;
}

template <auto... Members>
constexpr auto ref() {
    using S = Owner<Members...>;
    using T = Value<Members...>;
    return Ref<S, T>{[](S& s) -> T& { return (s .* ... .* Members); },
                     [](const S& s) -> const T& { return (s .* ... .* Members); }};
}

}  // namespace detail

// The setting stored in the member the chain reaches; its kind follows the member's type unless
// the row says (Colour for a glm::vec3, AssetPath for a string).
template <auto... Members>
constexpr Setting<detail::Owner<Members...>> field(Setting<detail::Owner<Members...>> row) {
    using S = detail::Owner<Members...>;
    using T = detail::Value<Members...>;
    const Kind kind = row.kind == Kind::Auto ? detail::kindOf<T>() : row.kind;
    if constexpr (std::is_enum_v<T>) {
        return detail::withAccess<S>(
            row, kind,
            ChoiceRef<S>{
                [](const S& s) { return static_cast<std::size_t>((s .* ... .* Members)); },
                [](S& s, std::size_t index) { (s .* ... .* Members) = static_cast<T>(index); }});
    } else {
        return detail::withAccess<S>(row, kind, detail::ref<Members...>());
    }
}

// A [min, max] setting stored as two float members of the same object.
template <auto Min, auto Max>
constexpr Setting<detail::Owner<Min>> rangeOf(Setting<detail::Owner<Min>> row) {
    return detail::withAccess<detail::Owner<Min>>(
        row, Kind::Range,
        RangePair<detail::Owner<Min>>{detail::ref<Min>(), detail::ref<Max>()});
}

template <class S>
constexpr Setting<S> custom(Setting<S> row,
                            void (*read)(json::Reader&, json::Object&, std::string_view, S&),
                            json::Json (*write)(const S&)) {
    return detail::withAccess<S>(row, Kind::Custom, CustomIo<S>{read, write});
}

// The keys of a table in order, for json::Object's key check.
template <class S>
std::vector<std::string_view> keysOf(std::span<const Setting<S>> table) {
    std::vector<std::string_view> keys;
    keys.reserve(table.size());
    for (const Setting<S>& row : table)
        keys.push_back(row.key);
    return keys;
}

// The row of `key`, or null when the table has none.
template <class S>
const Setting<S>* findSetting(std::span<const Setting<S>> table, std::string_view key) {
    for (const Setting<S>& row : table)
        if (row.key == key)
            return &row;
    return nullptr;
}

}  // namespace grass::core::settings
