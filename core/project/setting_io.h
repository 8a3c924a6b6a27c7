// Reading and writing a section of project.json from its table of settings (setting.h): every
// row is read with the json::Reader call its kind asks for, so the refusal messages are the
// reader's ("/snow/amount: must be in [0, 10] (got 15)"), and written in table order, which is
// the order docs/project-format.md lists. Internal to core/project/.
#pragma once

#include <string>
#include <type_traits>
#include <variant>

#include "project/json_reader.h"
#include "project/setting.h"

namespace grass::core::json {

// Fails `pointer` when `path` is not a well-formed relative asset path (resolveAssetPath's rules).
void checkAssetPath(Reader& reader, const std::string& pointer, const std::string& path);

}  // namespace grass::core::json

namespace grass::core::settings {

namespace detail {

inline std::string_view componentNames(Kind kind) {
    return kind == Kind::Colour ? "[r, g, b]" : "[x, y, z]";
}

template <class S>
void readValue(json::Reader& reader, json::Object& object, const Setting<S>& row, S& out) {
    const std::string_view key = row.key;
    std::visit(
        [&](const auto& access) {
            using A = std::remove_cvref_t<decltype(access)>;
            if constexpr (std::is_same_v<A, CustomIo<S>>) {
                access.read(reader, object, key, out);
            } else if constexpr (std::is_same_v<A, Ref<S, float>>) {
                object.readFloat(key, row.rule, access.get(out));
            } else if constexpr (std::is_same_v<A, Ref<S, int>>) {
                object.readInt(key, row.intMin, row.intMax, access.get(out));
            } else if constexpr (std::is_same_v<A, Ref<S, std::uint32_t>>) {
                if (row.kind == Kind::Flag) {  // a GPU struct's 0/1 (std430 has no bool)
                    bool on = access.get(out) != 0u;
                    object.readBool(key, on);
                    access.get(out) = on ? 1u : 0u;
                    return;
                }
                int value = static_cast<int>(access.get(out));
                object.readInt(key, row.intMin, row.intMax, value);
                access.get(out) = static_cast<std::uint32_t>(value);
            } else if constexpr (std::is_same_v<A, Ref<S, std::uint64_t>>) {
                object.readUint64(key, access.get(out));
            } else if constexpr (std::is_same_v<A, Ref<S, bool>>) {
                object.readBool(key, access.get(out));
            } else if constexpr (std::is_same_v<A, Ref<S, glm::vec3>>) {
                object.readVec3(key, row.rule, componentNames(row.kind), access.get(out));
            } else if constexpr (std::is_same_v<A, Ref<S, glm::vec2>>) {
                glm::vec2& range = access.get(out);
                object.readRange(key, row.rule, range.x, range.y);
            } else if constexpr (std::is_same_v<A, RangePair<S>>) {
                object.readRange(key, row.rule, access.min.get(out), access.max.get(out));
            } else if constexpr (std::is_same_v<A, Ref<S, std::string>>) {
                std::string& text = access.get(out);
                object.readString(key, row.allowEmpty, text);
                if (row.kind == Kind::AssetPath && !text.empty() && object.find(key))
                    json::checkAssetPath(reader, object.pointerTo(key), text);
            } else if constexpr (std::is_same_v<A, ChoiceRef<S>>) {
                std::size_t index = 0;
                if (const json::Json* node = object.find(key);
                    node && reader.readEnum(*node, object.pointerTo(key), row.names, index))
                    access.set(out, index);
            }
        },
        row.access);
}

inline json::Json jsonChoice(std::span<const std::string_view> names, std::size_t index) {
    return index < names.size() ? json::Json(std::string(names[index])) : json::Json();
}

}  // namespace detail

// The JSON value `row` writes for `value`; null when the row leaves its key out.
template <class S>
json::Json settingJson(const Setting<S>& row, const S& value) {
    if (row.applies && !row.applies(value))
        return json::Json();
    return std::visit(
        [&](const auto& access) -> json::Json {
            using A = std::remove_cvref_t<decltype(access)>;
            if constexpr (std::is_same_v<A, std::monostate>)
                return json::Json();
            else if constexpr (std::is_same_v<A, CustomIo<S>>)
                return access.write(value);
            else if constexpr (std::is_same_v<A, Ref<S, float>>)
                return json::jsonFloat(access.view(value));
            else if constexpr (std::is_same_v<A, Ref<S, glm::vec3>>)
                return json::jsonVec3(access.view(value));
            else if constexpr (std::is_same_v<A, Ref<S, glm::vec2>>)
                return json::jsonRange(access.view(value).x, access.view(value).y);
            else if constexpr (std::is_same_v<A, RangePair<S>>)
                return json::jsonRange(access.min.view(value), access.max.view(value));
            else if constexpr (std::is_same_v<A, ChoiceRef<S>>)
                return detail::jsonChoice(row.names, access.get(value));
            else if constexpr (std::is_same_v<A, Ref<S, std::uint32_t>>)
                return row.kind == Kind::Flag ? json::Json(access.view(value) != 0u)
                                              : json::Json(access.view(value));
            else
                return json::Json(access.view(value));
        },
        row.access);
}

// Reads every row of `table` that `object` holds into `out` (absent keys keep their values);
// a row that does not apply to `out` refuses its key.
template <class S>
void readSettings(json::Reader& reader, json::Object& object, std::span<const Setting<S>> table,
                  S& out) {
    for (const Setting<S>& row : table) {
        if (!reader.ok())
            return;
        if (row.applies && !row.applies(out)) {
            if (object.find(row.key))
                reader.fail(object.pointerTo(row.key), std::string(row.onlyText));
            continue;
        }
        detail::readValue(reader, object, row, out);
    }
}

// The object `node` at `pointer`, with the keys of `table`, read into `out`.
template <class S>
json::Object readSection(json::Reader& reader, const json::Json& node, std::string pointer,
                         std::span<const Setting<S>> table, S& out) {
    const std::vector<std::string_view> keys = keysOf(table);
    json::Object object(reader, node, std::move(pointer), keys);
    if (object.valid())
        readSettings(reader, object, table, out);
    return object;
}

// Checks across the keys of an object once they are read (amount <= max_amount); null: none.
template <class T>
using CheckFn = void (*)(json::Reader&, const json::Object&, const T&);

// `node` at `pointer` read by `table` into `out`, then checked.
template <class T>
void readObject(json::Reader& reader, const json::Json& node, std::string pointer,
                std::span<const Setting<T>> table, CheckFn<T> check, T& out) {
    json::Object object = readSection(reader, node, std::move(pointer), table, out);
    if (reader.ok() && check)
        check(reader, object, out);
}

// Every row of `table` in order; rows whose value is null are left out.
template <class S>
json::Json sectionJson(std::span<const Setting<S>> table, const S& value) {
    json::Json out = json::Json::object();
    for (const Setting<S>& row : table)
        if (json::Json item = settingJson(row, value); !item.is_null())
            out[std::string(row.key)] = std::move(item);
    return out;
}

// A setting whose value is an object of its own (a layer's "blade", the project's "snow"), read
// by the table `Table()` and checked by `Check` (nullptr: no check).
template <auto Table, auto Check, auto... Members>
constexpr Setting<detail::Owner<Members...>> object(Setting<detail::Owner<Members...>> row) {
    using S = detail::Owner<Members...>;
    using T = detail::Value<Members...>;
    if (row.typeText.empty())
        row.typeText = "object";
    return custom<S>(
        row,
        [](json::Reader& reader, json::Object& parent, std::string_view key, S& value) {
            if (const json::Json* node = parent.find(key))
                readObject<T>(reader, *node, parent.pointerTo(key), Table(), Check,
                              (value .* ... .* Members));
        },
        [](const S& value) -> json::Json { return sectionJson(Table(), (value .* ... .* Members)); });
}

}  // namespace grass::core::settings
