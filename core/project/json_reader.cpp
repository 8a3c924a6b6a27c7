#include "project/json_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include "util/json_text.h"

namespace grass::core::json {

namespace {

// A SAX pass before the real parse: nlohmann's DOM parser keeps the last of duplicate keys
// without a word, and reports syntax errors only by exception; this pass reports both.
class SyntaxChecker final : public nlohmann::json_sax<Json> {
public:
    SyntaxChecker(std::string_view text, const std::string& sourceName)
        : mText(text), mSourceName(sourceName) {}

    std::optional<Error> error;

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t, const string_t&) override { return value(); }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override {
        value();
        mStack.push_back(Frame{true, {}, {}, 0});
        return true;
    }
    bool key(string_t& name) override {
        Frame& frame = mStack.back();
        frame.key = name;
        if (!frame.keys.insert(name).second) {
            error = Error{mSourceName, pointer() + ": duplicate key (each key may appear once)"};
            return false;
        }
        return true;
    }
    bool end_object() override {
        mStack.pop_back();
        return true;
    }
    bool start_array(std::size_t) override {
        value();
        mStack.push_back(Frame{false, {}, {}, 0});
        return true;
    }
    bool end_array() override {
        mStack.pop_back();
        return true;
    }
    bool parse_error(std::size_t position, const std::string& lastToken,
                     const nlohmann::detail::exception& ex) override {
        // nlohmann refuses numbers that overflow a double (1e999) as a parse error (406); it
        // is a bad value, so name its field like any other.
        if (ex.id == NUMBER_OVERFLOW) {
            const std::string where = pendingPointer();
            error = Error{mSourceName, (where.empty() ? "" : where + ": ") +
                                           "must be a finite number (got " + lastToken +
                                           ", beyond double precision)"};
            return false;
        }
        // what() is "[json.exception.parse_error.101] parse error at line 3, column 5: <why>";
        // keep <why> and say where in the usual file:line:column form.
        std::string why = ex.what();
        if (const auto at = why.find("column "); at != std::string::npos) {
            if (const auto colon = why.find(": ", at); colon != std::string::npos)
                why = why.substr(colon + 2);
        } else if (const auto bracket = why.find("] "); bracket != std::string::npos) {
            why = why.substr(bracket + 2);
        }
        // nlohmann counts the offending byte as read: `position` is one past it.
        const TextPosition where = textPosition(mText, position > 0 ? position - 1 : 0);
        error = Error{
            mSourceName + ":" + std::to_string(where.line) + ":" + std::to_string(where.column),
            "JSON syntax error: " + why};
        return false;
    }

private:
    struct Frame {
        bool isObject;
        std::set<std::string> keys;
        std::string key;
        std::size_t count;
    };

    static constexpr int NUMBER_OVERFLOW = 406;

    bool value() {
        if (!mStack.empty() && !mStack.back().isObject)
            ++mStack.back().count;
        return true;
    }
    // The pointer of the value just read (`count` already includes it), or of the value about to
    // be read (`pending`: the next array element).
    std::string pointer(bool pending = false) const {
        std::string result;
        for (std::size_t i = 0; i < mStack.size(); ++i) {
            const Frame& frame = mStack[i];
            const bool next = pending && i + 1 == mStack.size();
            result = frame.isObject ? childPointer(result, frame.key)
                                    : childPointer(result, next ? frame.count : frame.count - 1);
        }
        return result;
    }
    std::string pendingPointer() const { return pointer(true); }

    std::string_view mText;
    const std::string& mSourceName;
    std::vector<Frame> mStack;
};

// Shortest decimal text of a bound in fixed notation ("100000", "0.5"), for messages.
std::string formatBound(double value) {
    char buffer[64];
    const auto [end, ec] =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
    if (ec != std::errc{})
        return std::to_string(value);
    return std::string(buffer, end);
}

// ">= 0", "> 0", "in [0, 1]", "in (0, 180)" or "" for an unbounded rule.
std::string ruleText(const NumberRule& rule) {
    const bool hasMin = std::isfinite(rule.min);
    const bool hasMax = std::isfinite(rule.max);
    if (hasMin && hasMax)
        return std::string("in ") + (rule.minOpen ? "(" : "[") + formatBound(rule.min) + ", " +
               formatBound(rule.max) + (rule.maxOpen ? ")" : "]");
    if (hasMin)
        return (rule.minOpen ? "> " : ">= ") + formatBound(rule.min);
    if (hasMax)
        return (rule.maxOpen ? "< " : "<= ") + formatBound(rule.max);
    return {};
}

bool obeys(const NumberRule& rule, double value) {
    if (rule.minOpen ? !(value > rule.min) : !(value >= rule.min))
        return false;
    if (rule.maxOpen ? !(value < rule.max) : !(value <= rule.max))
        return false;
    return true;
}

}  // namespace

Result<Json> parseDocument(std::string_view text, const std::string& sourceName) {
    if (jsonDepth(text) > MAX_JSON_DEPTH)
        return Error{sourceName, "JSON nested more than " + std::to_string(MAX_JSON_DEPTH) +
                                     " levels deep; a project nests about 5"};
    SyntaxChecker checker(text, sourceName);
    const bool accepted = Json::sax_parse(text.begin(), text.end(), &checker);
    if (!accepted || checker.error) {
        if (checker.error)
            return *checker.error;
        return Error{sourceName, "JSON syntax error"};
    }
    Json document = Json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
    if (document.is_discarded())
        return Error{sourceName, "JSON syntax error"};
    return document;
}

TextPosition textPosition(std::string_view text, std::size_t offset) {
    TextPosition position;
    const std::size_t end = std::min(offset, text.size());
    for (std::size_t i = 0; i < end; ++i) {
        if (text[i] == '\n') {
            ++position.line;
            position.column = 1;
        } else {
            ++position.column;
        }
    }
    return position;
}

std::string childPointer(const std::string& pointer, std::string_view key) {
    std::string result = pointer + "/";
    for (const char c : key) {
        if (c == '~')
            result += "~0";
        else if (c == '/')
            result += "~1";
        else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
            const std::string escaped = quote(std::string(1, c));
            result += escaped.substr(1, escaped.size() - 2);
        } else
            result += c;
    }
    return result;
}

std::string childPointer(const std::string& pointer, std::size_t index) {
    return pointer + "/" + std::to_string(index);
}

std::string quotedList(std::span<const std::string_view> names) {
    std::string list;
    for (const std::string_view name : names) {
        if (!list.empty())
            list += ", ";
        list += "\"" + std::string(name) + "\"";
    }
    return list;
}

std::string quote(std::string_view text) {
    return Json(std::string(text)).dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string describeValue(const Json& node) {
    switch (node.type()) {
        case Json::value_t::null:
            return "null";
        case Json::value_t::boolean:
            return node.get<bool>() ? "true" : "false";
        case Json::value_t::number_float: {
            const double value = node.get<double>();
            // dump() writes non-finite numbers as null; 1e999 parses to inf.
            if (std::isnan(value))
                return "nan";
            if (std::isinf(value))
                return value > 0 ? "inf" : "-inf";
            return node.dump();
        }
        case Json::value_t::number_integer:
        case Json::value_t::number_unsigned:
            return node.dump();
        case Json::value_t::string: {
            std::string text = node.get<std::string>();
            if (text.size() > 40)
                text = text.substr(0, 40) + "...";
            return "string " + quote(text);
        }
        case Json::value_t::array:
            if (node.empty())
                return "an empty array";
            return "an array of " + std::to_string(node.size()) +
                   (node.size() == 1 ? " element" : " elements");
        case Json::value_t::object:
            return "an object";
        default:
            return "binary data";
    }
}

void Reader::fail(const std::string& pointer, const std::string& problem) {
    if (mError)
        return;
    mError = Error{mSourceName, pointer.empty() ? problem : pointer + ": " + problem};
}

bool Reader::checkObject(const Json& node, const std::string& pointer,
                         std::span<const std::string_view> keys) {
    if (!ok())
        return false;
    if (!node.is_object()) {
        fail(pointer, "must be an object (got " + describeValue(node) + ")");
        return false;
    }
    for (const auto& item : node.items()) {
        const std::string& key = item.key();
        if (std::find(keys.begin(), keys.end(), key) != keys.end())
            continue;
        const auto suggestion = closestMatch(key, keys);
        fail(childPointer(pointer, key),
             suggestion ? "unknown key (did you mean \"" + std::string(*suggestion) + "\"?)"
                        : "unknown key (expected one of " + quotedList(keys) + ")");
        return false;
    }
    return true;
}

bool Reader::readFloat(const Json& node, const std::string& pointer, NumberRule rule, float& out) {
    if (!ok())
        return false;
    const std::string rangeText = ruleText(rule);
    const std::string expected =
        "must be a finite number" + (rangeText.empty() ? "" : " " + rangeText);
    if (!node.is_number()) {
        fail(pointer, expected + " (got " + describeValue(node) + ")");
        return false;
    }
    const double value = node.get<double>();
    if (!std::isfinite(value)) {
        fail(pointer, expected + " (got " + describeValue(node) + ")");
        return false;
    }
    if (std::abs(value) > static_cast<double>(std::numeric_limits<float>::max())) {
        fail(pointer, expected + " (got " + describeValue(node) + ", beyond single precision)");
        return false;
    }
    const float single = static_cast<float>(value);
    // The bounds as floats too, so that a value typed as the bound itself (1e-5, which no float
    // holds exactly) is inside it.
    NumberRule singleRule = rule;
    singleRule.min = static_cast<double>(static_cast<float>(rule.min));
    singleRule.max = static_cast<double>(static_cast<float>(rule.max));
    if (!obeys(singleRule, static_cast<double>(single))) {
        fail(pointer, expected + " (got " + describeValue(node) + ")");
        return false;
    }
    out = single;
    return true;
}

bool Reader::readInt(const Json& node, const std::string& pointer, std::int64_t min,
                     std::int64_t max, std::int64_t& out) {
    if (!ok())
        return false;
    const std::string expected =
        "must be an integer in " + std::to_string(min) + ".." + std::to_string(max);
    bool inRange = false;
    std::int64_t value = 0;
    if (node.is_number_unsigned()) {
        const std::uint64_t u = node.get<std::uint64_t>();
        inRange = max >= 0 && u <= static_cast<std::uint64_t>(max) &&
                  (min <= 0 || u >= static_cast<std::uint64_t>(min));
        value = static_cast<std::int64_t>(u);
    } else if (node.is_number_integer()) {
        value = node.get<std::int64_t>();
        inRange = value >= min && value <= max;
    }
    if (!inRange) {
        fail(pointer, expected + " (got " + describeValue(node) + ")");
        return false;
    }
    out = value;
    return true;
}

bool Reader::readUint64(const Json& node, const std::string& pointer, std::uint64_t& out) {
    if (!ok())
        return false;
    if (!node.is_number_unsigned()) {
        fail(pointer,
             "must be a non-negative integer of at most 64 bits (got " + describeValue(node) + ")");
        return false;
    }
    out = node.get<std::uint64_t>();
    return true;
}

bool Reader::readString(const Json& node, const std::string& pointer, bool allowEmpty,
                        std::string& out) {
    if (!ok())
        return false;
    if (!node.is_string()) {
        fail(pointer, "must be a string (got " + describeValue(node) + ")");
        return false;
    }
    const auto& text = node.get_ref<const std::string&>();
    if (!allowEmpty && text.empty()) {
        fail(pointer, "must not be empty");
        return false;
    }
    // Names and paths end up in file names, window titles and on the terminal, where a control
    // character (an escape sequence, a newline, NUL) would do what the file says, not show it.
    for (std::size_t i = 0; i < text.size(); ++i)
        if (const auto byte = static_cast<unsigned char>(text[i]); byte < 0x20 || byte == 0x7f) {
            char code[8];
            std::snprintf(code, sizeof code, "0x%02x", byte);
            fail(pointer, std::string("must not contain control characters (character ") +
                              std::to_string(i + 1) + " is " + code + ")");
            return false;
        }
    out = text;
    return true;
}

bool Reader::readVec3(const Json& node, const std::string& pointer, NumberRule rule,
                      std::string_view what, glm::vec3& out) {
    if (!ok())
        return false;
    if (!node.is_array() || node.size() != 3) {
        fail(pointer, "must be an array of 3 numbers " + std::string(what) + " (got " +
                          describeValue(node) + ")");
        return false;
    }
    glm::vec3 value;
    for (std::size_t i = 0; i < 3; ++i) {
        const auto component = static_cast<glm::vec3::length_type>(i);
        if (!readFloat(node[i], childPointer(pointer, i), rule, value[component]))
            return false;
    }
    out = value;
    return true;
}

bool Reader::readRange(const Json& node, const std::string& pointer, NumberRule rule, float& min,
                       float& max) {
    if (!ok())
        return false;
    if (!node.is_array() || node.size() != 2) {
        fail(pointer, "must be an array of 2 numbers [min, max] (got " + describeValue(node) + ")");
        return false;
    }
    float lo = 0.0f, hi = 0.0f;
    if (!readFloat(node[0], childPointer(pointer, 0), rule, lo))
        return false;
    if (!readFloat(node[1], childPointer(pointer, 1), rule, hi))
        return false;
    if (lo > hi) {
        fail(pointer, "min must be <= max (got [" + node[0].dump() + ", " + node[1].dump() + "])");
        return false;
    }
    min = lo;
    max = hi;
    return true;
}

bool Reader::readFloats(const Json& node, const std::string& pointer, NumberRule rule,
                        std::string_view what, std::span<float> out) {
    if (!ok())
        return false;
    if (!node.is_array() || node.size() != out.size()) {
        fail(pointer, "must be an array of " + std::to_string(out.size()) + " numbers " +
                          std::string(what) + " (got " + describeValue(node) + ")");
        return false;
    }
    std::vector<float> values(out.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        if (!readFloat(node[i], childPointer(pointer, i), rule, values[i]))
            return false;
    std::copy(values.begin(), values.end(), out.begin());
    return true;
}

bool Reader::readBool(const Json& node, const std::string& pointer, bool& out) {
    if (!ok())
        return false;
    if (!node.is_boolean()) {
        fail(pointer, "must be true or false (got " + describeValue(node) + ")");
        return false;
    }
    out = node.get<bool>();
    return true;
}

bool Reader::readEnum(const Json& node, const std::string& pointer,
                      std::span<const std::string_view> names, std::size_t& out) {
    if (!ok())
        return false;
    if (!node.is_string()) {
        fail(pointer, "must be one of " + quotedList(names) + " (got " + describeValue(node) + ")");
        return false;
    }
    const auto& text = node.get_ref<const std::string&>();
    const auto found = std::find(names.begin(), names.end(), text);
    if (found != names.end()) {
        out = static_cast<std::size_t>(found - names.begin());
        return true;
    }
    const auto suggestion = closestMatch(text, names);
    fail(pointer, "unknown value " + quote(text) +
                      (suggestion ? " (did you mean \"" + std::string(*suggestion) + "\"?)" : "") +
                      "; valid: " + quotedList(names));
    return false;
}

Object::Object(Reader& reader, const Json& node, std::string pointer,
               std::span<const std::string_view> keys)
    : mReader(reader), mPointer(std::move(pointer)) {
    if (reader.checkObject(node, mPointer, keys))
        mNode = &node;
}

const Json* Object::find(std::string_view key) const {
    if (!mNode || !mReader.ok())
        return nullptr;
    const auto it = mNode->find(std::string(key));
    return it == mNode->end() ? nullptr : &*it;
}

void Object::readFloat(std::string_view key, NumberRule rule, float& out) {
    if (const Json* node = find(key))
        mReader.readFloat(*node, pointerTo(key), rule, out);
}

void Object::readInt(std::string_view key, std::int64_t min, std::int64_t max, int& out) {
    std::int64_t value = 0;
    if (const Json* node = find(key);
        node && mReader.readInt(*node, pointerTo(key), min, max, value))
        out = static_cast<int>(value);
}

void Object::readUint64(std::string_view key, std::uint64_t& out) {
    if (const Json* node = find(key))
        mReader.readUint64(*node, pointerTo(key), out);
}

void Object::readString(std::string_view key, bool allowEmpty, std::string& out) {
    if (const Json* node = find(key))
        mReader.readString(*node, pointerTo(key), allowEmpty, out);
}

void Object::readVec3(std::string_view key, NumberRule rule, std::string_view what,
                      glm::vec3& out) {
    if (const Json* node = find(key))
        mReader.readVec3(*node, pointerTo(key), rule, what, out);
}

void Object::readRange(std::string_view key, NumberRule rule, float& min, float& max) {
    if (const Json* node = find(key))
        mReader.readRange(*node, pointerTo(key), rule, min, max);
}

void Object::readFloats(std::string_view key, NumberRule rule, std::string_view what,
                        std::span<float> out) {
    if (const Json* node = find(key))
        mReader.readFloats(*node, pointerTo(key), rule, what, out);
}

void Object::readBool(std::string_view key, bool& out) {
    if (const Json* node = find(key))
        mReader.readBool(*node, pointerTo(key), out);
}

double jsonFloat(float value) {
    char buffer[32];
    const auto printed = std::to_chars(buffer, buffer + sizeof buffer, value);
    double shortest = 0.0;
    const auto parsed = std::from_chars(buffer, printed.ptr, shortest);
    if (printed.ec == std::errc{} && parsed.ec == std::errc{} &&
        static_cast<float>(shortest) == value)
        return shortest;
    return static_cast<double>(value);
}

Json jsonFloats(std::span<const float> values) {
    Json out = Json::array();
    for (float value : values)
        out.push_back(jsonFloat(value));
    return out;
}

Json jsonVec3(glm::vec3 v) {
    return Json::array({jsonFloat(v.x), jsonFloat(v.y), jsonFloat(v.z)});
}
Json jsonRange(float min, float max) {
    return Json::array({jsonFloat(min), jsonFloat(max)});
}

}  // namespace grass::core::json
