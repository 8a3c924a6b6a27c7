// Reading JSON documents that people write by hand: a parse that reports syntax errors as
// file:line:column and refuses duplicate keys, and a typed field reader that tracks the JSON
// pointer (RFC 6901, "/layers/0/density") of what it reads and keeps the first error, so a
// loader reads every field in one straight pass and reports one readable line. Internal to
// core/project/; nlohmann-json never throws out of it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "util/nearest_name.h"  // closestMatch, for the unknown keys' "did you mean"

#include "util/result.h"

namespace grass::core::json {

// Ordered, so keys are checked (and written) in document order.
using Json = nlohmann::ordered_json;

// Parses `text`. Errors: "<sourceName>:<line>:<column>: JSON syntax error: ..." and duplicate
// keys ("<sourceName>: /cameras/0/name: duplicate key"), which nlohmann would silently merge.
Result<Json> parseDocument(std::string_view text, const std::string& sourceName);

// 1-based line and column (in bytes) of the byte at `offset`.
struct TextPosition {
    std::size_t line = 1;
    std::size_t column = 1;
};
TextPosition textPosition(std::string_view text, std::size_t offset);

// "/a" + "b" → "/a/b", escaping '~' and '/' in the key as RFC 6901 asks, and control
// characters as \uXXXX so a pointer always prints on one line.
std::string childPointer(const std::string& pointer, std::string_view key);
std::string childPointer(const std::string& pointer, std::size_t index);

// An allowed interval for a number; open or closed at each end; infinite ends are unbounded.
inline constexpr double UNBOUNDED = std::numeric_limits<double>::infinity();
struct NumberRule {
    double min = -UNBOUNDED;
    double max = UNBOUNDED;
    bool minOpen = false;
    bool maxOpen = false;
};
inline constexpr NumberRule ANY_NUMBER{};
inline constexpr NumberRule NON_NEGATIVE{0.0};
inline constexpr NumberRule POSITIVE{0.0, UNBOUNDED, true};
inline constexpr NumberRule UNIT_INTERVAL{0.0, 1.0};

// Reads typed values out of a parsed document. Every read names the JSON pointer of its value;
// the first failure is kept and later reads leave their outputs untouched, so a caller reads
// everything and checks ok() once.
class Reader {
public:
    explicit Reader(std::string sourceName) : mSourceName(std::move(sourceName)) {}

    bool ok() const { return !mError.has_value(); }
    // "<sourceName>" as path, "<pointer>: <problem>" as message.
    const Error& error() const { return *mError; }
    void fail(const std::string& pointer, const std::string& problem);

    // `node` must be an object whose keys are all in `keys`; unknown keys fail with a hint.
    bool checkObject(const Json& node, const std::string& pointer,
                     std::span<const std::string_view> keys);

    bool readFloat(const Json& node, const std::string& pointer, NumberRule rule, float& out);
    bool readInt(const Json& node, const std::string& pointer, std::int64_t min, std::int64_t max,
                 std::int64_t& out);
    bool readUint64(const Json& node, const std::string& pointer, std::uint64_t& out);
    bool readString(const Json& node, const std::string& pointer, bool allowEmpty,
                    std::string& out);
    // [x, y, z], each component obeying `rule`; `what` names the components in messages.
    bool readVec3(const Json& node, const std::string& pointer, NumberRule rule,
                  std::string_view what, glm::vec3& out);
    // [min, max] with min <= max, both obeying `rule`.
    bool readRange(const Json& node, const std::string& pointer, NumberRule rule, float& min,
                   float& max);
    // [a, b, ...] with exactly out.size() numbers, each obeying `rule`; `what` names them in
    // messages ("[gy0, gy1, gy2]"). All or nothing: out is untouched on failure.
    bool readFloats(const Json& node, const std::string& pointer, NumberRule rule,
                    std::string_view what, std::span<float> out);
    bool readBool(const Json& node, const std::string& pointer, bool& out);
    // A string that must be one of `names`; returns its index.
    bool readEnum(const Json& node, const std::string& pointer,
                  std::span<const std::string_view> names, std::size_t& out);

private:
    std::string mSourceName;
    std::optional<Error> mError;
};

// One object of the document: checks its type and keys on construction, then reads members
// that are present (absent ones keep the caller's defaults). If the object itself is bad, the
// reader has failed and every read is a no-op.
class Object {
public:
    Object(Reader& reader, const Json& node, std::string pointer,
           std::span<const std::string_view> keys);

    bool valid() const { return mNode != nullptr; }
    const std::string& pointer() const { return mPointer; }
    std::string pointerTo(std::string_view key) const { return childPointer(mPointer, key); }
    // The member or null when absent (or when this object is invalid).
    const Json* find(std::string_view key) const;

    void readFloat(std::string_view key, NumberRule rule, float& out);
    void readInt(std::string_view key, std::int64_t min, std::int64_t max, int& out);
    void readUint64(std::string_view key, std::uint64_t& out);
    void readString(std::string_view key, bool allowEmpty, std::string& out);
    void readVec3(std::string_view key, NumberRule rule, std::string_view what, glm::vec3& out);
    void readRange(std::string_view key, NumberRule rule, float& min, float& max);
    void readFloats(std::string_view key, NumberRule rule, std::string_view what,
                    std::span<float> out);
    void readBool(std::string_view key, bool& out);

private:
    Reader& mReader;
    const Json* mNode = nullptr;
    std::string mPointer;
};

// `text` as a JSON string literal: quoted, control characters escaped, invalid UTF-8 replaced,
// so user text never breaks a one-line message.
std::string quote(std::string_view text);

// "\"a\", \"b\", \"c\"": the valid names an error lists.
std::string quotedList(std::span<const std::string_view> names);

// Describes a JSON value for "(got ...)" in messages: `-3`, `inf`, `string "abc"`, `array`.
std::string describeValue(const Json& node);

// Writing: the double whose shortest text reads back as exactly `value` ("0.1", not
// "0.10000000149011612"), so saved floats survive load → save → load bit for bit.
double jsonFloat(float value);
Json jsonVec3(glm::vec3 v);
Json jsonRange(float min, float max);
Json jsonFloats(std::span<const float> values);

// Names must be unique within a list: the UI and the CLI select layers and cameras by name.
// Sorted, not compared pairwise: 64k layers took 45 s pairwise. Reports the first item (in list
// order) whose name an earlier item already has, and the first item that has it.
template <class T>
void checkUniqueNames(json::Reader& reader, const std::vector<T>& items, const std::string& list,
                      std::string_view what) {
    std::vector<std::size_t> order(items.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return items[a].name != items[b].name ? items[a].name < items[b].name : a < b;
    });
    std::size_t duplicate = items.size(), first = 0;
    for (std::size_t k = 1; k < order.size(); ++k)
        if (items[order[k]].name == items[order[k - 1]].name && order[k] < duplicate &&
            (k < 2 || items[order[k - 2]].name != items[order[k]].name)) {
            duplicate = order[k];
            first = order[k - 1];
        }
    if (duplicate < items.size())
        reader.fail(list + "/" + std::to_string(duplicate) + "/name",
                    "duplicate " + std::string(what) + " name " +
                        json::quote(items[duplicate].name) + " (also " + list + "/" +
                        std::to_string(first) + "/name)");
}

// A list of at most `maxItems` named objects (layers, cameras, wind sources, colliders): every
// frame and every physics step goes over each of them, so the bound is what can still run.
template <class T, class ReadItem>
void readList(json::Reader& reader, const Json& node, const std::string& pointer,
              std::string_view what, std::size_t maxItems, std::vector<T>& out, ReadItem readItem) {
    if (!node.is_array()) {
        reader.fail(pointer, "must be an array of " + std::string(what) + " objects (got " +
                                 json::describeValue(node) + ")");
        return;
    }
    if (node.size() > maxItems) {
        reader.fail(pointer, "holds " + std::to_string(node.size()) + " " + std::string(what) +
                                 " objects; at most " + std::to_string(maxItems) + " are allowed");
        return;
    }
    std::vector<T> items(node.size());
    for (std::size_t i = 0; i < node.size() && reader.ok(); ++i)
        readItem(reader, node[i], json::childPointer(pointer, i), items[i]);
    checkUniqueNames(reader, items, pointer, what);
    if (reader.ok())
        out = std::move(items);
}

}  // namespace grass::core::json
