// Basic value types of the UI library (grass::ui): positions and sizes in points (logical
// pixels, y down, origin at the top-left of the window), colours as 8-bit sRGB with straight
// alpha. Screen pixels = points × Context::pixelsPerPoint() (HiDPI).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string_view>

#include <glm/glm.hpp>

namespace grass::ui {

using Vec2 = glm::vec2;

struct Rect {
    Vec2 min{0.0f};
    Vec2 max{0.0f};

    static Rect fromMinSize(Vec2 min, Vec2 size) { return {min, min + size}; }
    Vec2 size() const { return max - min; }
    float width() const { return max.x - min.x; }
    float height() const { return max.y - min.y; }
    Vec2 centre() const { return 0.5f * (min + max); }
    bool contains(Vec2 p) const {
        return p.x >= min.x && p.y >= min.y && p.x < max.x && p.y < max.y;
    }
    bool empty() const { return !(max.x > min.x && max.y > min.y); }
    Rect intersect(const Rect& o) const {
        return {glm::max(min, o.min), glm::min(max, o.max)};
    }
    Rect expand(float by) const { return {min - Vec2(by), max + Vec2(by)}; }
    bool operator==(const Rect&) const = default;
};

struct Color32 {
    std::uint8_t r = 0, g = 0, b = 0, a = 255;

    static constexpr Color32 rgb(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
        return {r, g, b, 255};
    }
    static constexpr Color32 transparent() { return {0, 0, 0, 0}; }
    bool operator==(const Color32&) const = default;
};

// "Text##key": the part a widget shows (all of the label without "##"); the whole label is its
// id, so two rows showing the same text keep their own state.
inline std::string_view shownLabel(std::string_view label) {
    return label.substr(0, std::min(label.find("##"), label.size()));
}

// A widget's identity across frames: a hash of its parent's id and a salt (ui::Id::with).
struct Id {
    std::uint64_t value = 0;

    static Id fromString(std::string_view text);
    Id with(std::string_view salt) const;
    Id with(std::uint64_t salt) const;
    bool operator==(const Id&) const = default;
};

}  // namespace grass::ui
