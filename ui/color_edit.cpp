// Colour edit widget and HSV conversion (color_edit.h).
#include "ui/color_edit.h"

#include <algorithm>
#include <cmath>

namespace grass::ui {

namespace {

// Cells per side of the SV square and segments of the hue bar: shapes carry one fill colour, so
// gradients are drawn as small flat cells; 16 cells keep steps invisible at 160 pt.
constexpr int SV_CELLS = 16;
constexpr int HUE_SEGMENTS = 24;
constexpr float SWATCH_WIDTH = 40.0f;

struct PickerState {
    glm::vec3 hsv{0.0f};
    // The colour hsv was last synchronised with; a different incoming colour (edited by the app
    // or the RGB drag values) re-derives hsv.
    glm::vec3 rgb{-1.0f};
};

float srgbEncode(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

Color32 toColor32(glm::vec3 rgb, bool linear) {
    const auto channel = [linear](float v) {
        const float d = linear ? srgbEncode(v) : std::clamp(v, 0.0f, 1.0f);
        return std::uint8_t(std::lround(d * 255.0f));
    };
    return Color32::rgb(channel(rgb.r), channel(rgb.g), channel(rgb.b));
}

}  // namespace

glm::vec3 rgbToHsv(glm::vec3 rgb) {
    const float maxC = std::max({rgb.r, rgb.g, rgb.b});
    const float minC = std::min({rgb.r, rgb.g, rgb.b});
    const float chroma = maxC - minC;
    float h = 0.0f;
    if (chroma > 0.0f) {
        // Which sextant of the hue circle: the largest channel picks the centre (red 0, green
        // 2, blue 4) and the other two the offset from it.
        if (maxC == rgb.r) {
            h = (rgb.g - rgb.b) / chroma;
        } else if (maxC == rgb.g) {
            h = 2.0f + (rgb.b - rgb.r) / chroma;
        } else {
            h = 4.0f + (rgb.r - rgb.g) / chroma;
        }
        h /= 6.0f;
        if (h < 0.0f) {
            h += 1.0f;
        }
    }
    const float s = maxC > 0.0f ? chroma / maxC : 0.0f;
    return {h >= 1.0f ? 0.0f : h, s, maxC};
}

glm::vec3 hsvToRgb(glm::vec3 hsv) {
    const float h = hsv.x - std::floor(hsv.x);
    const float s = std::clamp(hsv.y, 0.0f, 1.0f);
    const float v = std::clamp(hsv.z, 0.0f, 1.0f);
    // Each channel is v minus chroma times how far the hue is from that channel's sextant, the
    // closed form of the piecewise linear hue ramps.
    const auto channel = [&](float n) {
        const float k = std::fmod(n + 6.0f * h, 6.0f);
        return v - v * s * std::clamp(std::min(k, 4.0f - k), 0.0f, 1.0f);
    };
    return {channel(5.0f), channel(3.0f), channel(1.0f)};
}

Response colorPicker(Ui& ui, std::string_view idSalt, glm::vec3& rgb, bool linear) {
    const Id id = ui.makeId(idSalt);
    Context& ctx = ui.context();
    PickerState& st = ctx.state<PickerState>(id.with("picker"));
    if (rgb != st.rgb) {
        const glm::vec3 hsv = rgbToHsv(rgb);
        // Hue is meaningless for greys and saturation for black: keep the remembered ones so a
        // drag through the bottom or left edge of the square comes back to the same colour.
        st.hsv.x = hsv.y > 0.0f ? hsv.x : st.hsv.x;
        st.hsv.y = hsv.z > 0.0f ? hsv.y : st.hsv.y;
        st.hsv.z = hsv.z;
        st.rgb = rgb;
    }
    glm::vec3& hsv = st.hsv;
    const glm::vec3 before = hsv;
    const Style& s = ui.style();
    Response result;

    const Vec2 origin = ui.nextItemPos();
    const Rect square = Rect::fromMinSize(origin, Vec2(COLOR_PICKER_SIZE));
    const Rect hueBar = Rect::fromMinSize({square.max.x + s.itemSpacing.x, origin.y},
                                          {COLOR_HUE_BAR_WIDTH, COLOR_PICKER_SIZE});
    ui.allocate({hueBar.max.x - origin.x, COLOR_PICKER_SIZE});
    const Response sv = ui.interact(square, id.with("sv"), Sense::dragOnly());
    if (sv.dragged()) {
        const Vec2 t = glm::clamp((sv.pointerPos() - square.min) / square.size(), 0.0f, 1.0f);
        hsv.y = t.x;
        hsv.z = 1.0f - t.y;
    }
    const Response hue = ui.interact(hueBar, id.with("hue"), Sense::dragOnly());
    if (hue.dragged()) {
        // Top is hue 0 and the bottom just short of a full turn, so the bar's ends stay apart.
        hsv.x = std::clamp((hue.pointerPos().y - hueBar.min.y) / hueBar.height(), 0.0f, 0.9999f);
    }
    result = sv;
    result.unite(hue);

    Painter& p = ui.painter();
    const Vec2 cell = square.size() / float(SV_CELLS);
    for (int y = 0; y < SV_CELLS; ++y) {
        for (int x = 0; x < SV_CELLS; ++x) {
            const glm::vec3 c = hsvToRgb(
                {hsv.x, (float(x) + 0.5f) / SV_CELLS, 1.0f - (float(y) + 0.5f) / SV_CELLS});
            const Vec2 min = square.min + cell * Vec2(float(x), float(y));
            // Encoded like the swatch, so the colour under the marker is the swatch's.
            p.rect({min, min + cell}, 0.0f, toColor32(c, linear));
        }
    }
    const float segment = hueBar.height() / HUE_SEGMENTS;
    for (int i = 0; i < HUE_SEGMENTS; ++i) {
        const float y = hueBar.min.y + segment * float(i);
        p.rect({{hueBar.min.x, y}, {hueBar.max.x, y + segment}}, 0.0f,
               toColor32(hsvToRgb({(float(i) + 0.5f) / HUE_SEGMENTS, 1.0f, 1.0f}), linear));
    }
    const Vec2 marker{square.min.x + hsv.y * square.width(),
                      square.min.y + (1.0f - hsv.z) * square.height()};
    const Color32 ring = hsv.z > 0.5f ? Color32::rgb(0, 0, 0) : Color32::rgb(255, 255, 255);
    p.circle(marker, 5.0f, Color32::transparent(), {1.5f, ring});
    const float hueY = hueBar.min.y + hsv.x * hueBar.height();
    p.rect({{hueBar.min.x - 2.0f, hueY - 2.0f}, {hueBar.max.x + 2.0f, hueY + 2.0f}}, 1.0f,
           Color32::transparent(), {1.5f, s.textStrong});

    bool rgbEdited = false;
    ui.pushId(id.value);
    ui.horizontal([&](Ui& row) {
        glm::vec3 edited = glm::clamp(rgb, 0.0f, 1.0f);
        const char* names[] = {"R", "G", "B"};
        for (int c = 0; c < 3; ++c) {
            rgbEdited |= row.dragValue(names[c], edited[c], 0.005f, 0.0f, 1.0f).changed();
        }
        if (rgbEdited) {
            rgb = edited;
        }
    });
    ui.horizontal([&](Ui& row) {
        row.dragValue("H", hsv.x, 0.002f, 0.0f, 0.9999f);
        row.dragValue("S", hsv.y, 0.005f, 0.0f, 1.0f);
        row.dragValue("V", hsv.z, 0.005f, 0.0f, 1.0f);
    });
    ui.popId();

    if (rgbEdited) {
        result.markChanged();
    } else if (hsv != before) {
        rgb = hsvToRgb(hsv);
        st.rgb = rgb;
        result.markChanged();
    }
    return result;
}

Response colorEdit(Ui& ui, std::string_view label, glm::vec3& rgb, bool linear) {
    const Style& s = ui.style();
    Context& ctx = ui.context();
    const Id id = ui.makeId(label);
    const std::string_view shown = shownLabel(label);
    const Vec2 labelSize = ctx.fonts().textSize(shown, s.textSizePt);
    const Rect total = ui.allocate(
        {SWATCH_WIDTH + (shown.empty() ? 0.0f : s.itemSpacing.x + labelSize.x), s.interactHeight});
    const Rect swatch = Rect::fromMinSize(total.min, {SWATCH_WIDTH, s.interactHeight});
    Response r = ui.interact(swatch, id, Sense::clickOnly());
    const Id popupId = id.with("popup");
    if (r.clicked()) {
        if (ctx.isPopupOpen(popupId)) {
            ctx.closePopup();
        } else {
            ctx.openPopup(popupId);
        }
    }
    const WidgetVisuals& v = ui.visuals(r);
    Painter& p = ui.painter();
    p.rect(swatch, s.rounding, toColor32(rgb, linear),
           v.bgStroke.width > 0.0f ? v.bgStroke : Stroke{1.0f, s.separator});
    p.text({swatch.max.x + s.itemSpacing.x, swatch.centre().y}, shown, s.textSizePt, s.text,
           {0.0f, 0.5f});
    bool changed = false;
    ui.popupBelow(
        popupId, swatch,
        [&](Ui& popup) { changed = colorPicker(popup, "picker", rgb, linear).changed(); }, false);
    return changed ? r.markChanged() : r;
}

}  // namespace grass::ui
