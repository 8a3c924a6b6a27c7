// Widgets that edit numbers and choices: sliders, drag values and combo boxes.
#include <cmath>
#include <cstdio>
#include <string>

#include "ui/number_text.h"
#include "ui/ui.h"

namespace grass::ui {

namespace {

// Enough digits to see a 1% step of the range: 0..500 shows integers, 0..1 two decimals.
int autoDecimals(double min, double max) {
    const double range = std::abs(max - min);
    if (!(range > 0.0) || !std::isfinite(range)) {
        return 3;
    }
    return std::clamp(int(std::ceil(-std::log10(range / 100.0))), 0, 6);
}

// The slider's value <-> track position t in 0..1 (beyond when not clamped).
struct SliderMapping {
    double min = 0.0;
    double max = 1.0;
    bool logarithmic = false;

    double toT(double v) const {
        if (logarithmic) {
            return std::log(std::max(v, min * 1e-6) / min) / std::log(max / min);
        }
        return max == min ? 0.0 : (v - min) / (max - min);
    }
    double fromT(double t) const {
        return logarithmic ? min * std::pow(max / min, t) : min + t * (max - min);
    }
};

// Shared by the float and int sliders: edits `value` in double precision and reports whether
// it changed. `integer` rounds to whole numbers.
Response sliderImpl(Ui& ui, std::string_view label, double& value, double min, double max,
                    const SliderOptions& options, bool integer) {
    const std::string_view shown = shownLabel(label);
    const Style& s = ui.style();
    const FontAtlas& fonts = ui.context().fonts();
    const SliderMapping map{min, max, options.logarithmic && min > 0.0 && max > min};
    const int rangeDigits =
        integer ? 0 : (options.decimals >= 0 ? options.decimals : autoDecimals(min, max));
    // A logarithmic track spans orders of magnitude: its value keeps its significant digits.
    const int decimals =
        map.logarithmic && !integer ? significantDecimals(value, rangeDigits) : rangeDigits;
    const std::string valueText = options.showValue ? numberText(value, decimals) : std::string();
    const Vec2 valueSize = fonts.textSize(valueText, s.textSizePt);
    const Vec2 labelSize = fonts.textSize(shown, s.textSizePt);
    const float height = std::max(s.interactHeight, valueSize.y);
    const float valueWidth = options.showValue ? s.itemSpacing.x + valueSize.x : 0.0f;
    const float trackWidth = options.trackWidth > 0.0f ? options.trackWidth : s.sliderWidth;
    const float width =
        trackWidth + valueWidth + (shown.empty() ? 0.0f : s.itemSpacing.x + labelSize.x);
    const Rect total = ui.allocate({width, height});
    const Rect track = Rect::fromMinSize(total.min, {trackWidth, height});
    Response r = ui.interact(track, ui.makeId(label), Sense::clickAndDrag());

    // The handle centre travels between the track ends inset by its radius, so the handle
    // never sticks out of the widget: value per point = range / (width − 2·radius).
    const float x0 = track.min.x + s.sliderHandleRadius;
    const float x1 = track.max.x - s.sliderHandleRadius;
    if (r.dragged() && x1 > x0) {
        double t = double(r.pointerPos().x - x0) / double(x1 - x0);
        if (options.clamp) {
            t = std::clamp(t, 0.0, 1.0);
        }
        double v = map.fromT(t);
        if (integer) {
            v = std::round(v);
        }
        if (options.clamp) {
            v = std::clamp(v, std::min(min, max), std::max(min, max));
        }
        if (v != value) {
            value = v;
            r.markChanged();
        }
    }

    Painter& p = ui.painter();
    const WidgetVisuals& vis = ui.visuals(r);
    const float cy = track.centre().y;
    const float handleX =
        x0 + float(std::clamp(map.toT(value), 0.0, 1.0)) * std::max(x1 - x0, 0.0f);
    const float rail = 0.5f * s.sliderRailHeight;
    p.rect({{x0, cy - rail}, {x1, cy + rail}}, rail, s.extremeBg);
    p.rect({{x0, cy - rail}, {handleX, cy + rail}}, rail, s.selectionFill);
    p.circle({handleX, cy}, s.sliderHandleRadius, vis.bgFill, {1.0f, vis.text});
    const float textX = track.max.x + s.itemSpacing.x;
    if (options.showValue) {
        p.text({textX, cy}, valueText, s.textSizePt, s.text, {0.0f, 0.5f});
    }
    p.text({track.max.x + valueWidth + s.itemSpacing.x, cy}, shown, s.textSizePt, s.text,
           {0.0f, 0.5f});
    return r;
}

// The value box of a drag value; returns the response of the box.
Response dragBox(Ui& ui, std::string_view label, const std::string& text) {
    const std::string_view shown = shownLabel(label);
    const Style& s = ui.style();
    const FontAtlas& fonts = ui.context().fonts();
    const Vec2 textSize = fonts.textSize(text, s.textSizePt);
    const Vec2 labelSize = fonts.textSize(shown, s.textSizePt);
    const Vec2 box{std::max(s.dragValueMinWidth, textSize.x + 2.0f * s.buttonPadding.x),
                   std::max(s.interactHeight, textSize.y + 2.0f * s.buttonPadding.y)};
    const Rect total =
        ui.allocate({box.x + (shown.empty() ? 0.0f : s.itemSpacing.x + labelSize.x), box.y});
    const Rect rect = Rect::fromMinSize(total.min, box);
    const Response r = ui.interact(rect, ui.makeId(label), Sense::clickAndDrag());
    if (r.hovered() || r.dragged()) {
        ui.context().output().cursor = CursorIcon::ResizeHorizontal;
    }
    const WidgetVisuals& v = ui.visuals(r);
    Painter& p = ui.painter();
    p.rect(rect, s.rounding, v.bgFill, v.bgStroke);
    p.text(rect.centre(), text, s.textSizePt, v.text, {0.5f, 0.5f});
    p.text({rect.max.x + s.itemSpacing.x, rect.centre().y}, shown, s.textSizePt, s.text,
           {0.0f, 0.5f});
    return r;
}

}  // namespace

Response Ui::slider(std::string_view label, float& value, float min, float max,
                    const SliderOptions& options) {
    double v = value;
    Response r = sliderImpl(*this, label, v, min, max, options, false);
    if (r.changed()) {
        value = float(v);
    }
    return r;
}

Response Ui::slider(std::string_view label, int& value, int min, int max,
                    const SliderOptions& options) {
    double v = value;
    Response r = sliderImpl(*this, label, v, min, max, options, true);
    if (r.changed()) {
        value = int(v);
    }
    return r;
}

Response Ui::dragValue(std::string_view label, float& value, float speed, float min, float max,
                       int decimals) {
    Response r = dragBox(*this, label, numberText(value, std::max(decimals, 0)));
    if (r.dragged() && r.dragDelta().x != 0.0f) {
        const float v = std::clamp(value + r.dragDelta().x * speed, min, max);
        if (v != value) {
            value = v;
            r.markChanged();
        }
    }
    return r;
}

Response Ui::dragValue(std::string_view label, int& value, float speed, int min, int max) {
    Response r = dragBox(*this, label, numberText(value, 0));
    // Sub-integer movement accumulates across frames in a per-widget float, so slow drags
    // still change the value.
    double& exact = mCtx->state<double>(r.id().with("exact"));
    if (r.dragStarted()) {
        exact = value;
    }
    if (r.dragged() && r.dragDelta().x != 0.0f) {
        exact = std::clamp(exact + double(r.dragDelta().x * speed), double(min), double(max));
        const int v = int(std::round(exact));
        if (v != value) {
            value = v;
            r.markChanged();
        }
    }
    return r;
}

Response Ui::comboBox(std::string_view label, std::string_view selectedText, const UiFn& fn) {
    const Style& s = style();
    const Id id = makeId(label);
    const Vec2 textSize = mCtx->fonts().textSize(selectedText, s.textSizePt);
    const std::string_view shown = shownLabel(label);
    const Vec2 labelSize = mCtx->fonts().textSize(shown, s.textSizePt);
    // As wide as its selected text and arrow where there is room (never under comboWidth): the
    // export window's "glTF per layer (EXT_mesh_gpu_instancing)" showed as "glTF per laye".
    const float arrow = 0.5f * s.iconSize;
    const float wanted = textSize.x + 2.0f * s.buttonPadding.x + 2.0f * arrow + s.buttonPadding.x;
    const float room = availableWidth() - (shown.empty() ? 0.0f : s.itemSpacing.x + labelSize.x);
    const Vec2 box{std::max(s.comboWidth, std::min(wanted, room)),
                   std::max(s.interactHeight, textSize.y + 2.0f * s.buttonPadding.y)};
    const Rect total =
        allocate({box.x + (shown.empty() ? 0.0f : s.itemSpacing.x + labelSize.x), box.y});
    const Rect rect = Rect::fromMinSize(total.min, box);
    const Response r = interact(rect, id, Sense::clickOnly());
    const Id popupId = id.with("popup");
    if (r.clicked()) {
        if (mCtx->isPopupOpen(popupId)) {
            mCtx->closePopup();
        } else {
            mCtx->openPopup(popupId);
        }
    }
    const WidgetVisuals& v = visuals(r);
    mPainter.rect(rect, s.rounding, v.bgFill, v.bgStroke);
    // The selected text is clipped short of the arrow.
    mPainter.pushClip({rect.min, {rect.max.x - 2.0f * arrow - s.buttonPadding.x, rect.max.y}});
    mPainter.text({rect.min.x + s.buttonPadding.x, rect.centre().y}, selectedText, s.textSizePt,
                  v.text, {0.0f, 0.5f});
    mPainter.popClip();
    const Vec2 c{rect.max.x - s.buttonPadding.x - arrow, rect.centre().y};
    mPainter.path({{c.x - arrow, c.y - 0.4f * arrow},
                   {c.x + arrow, c.y - 0.4f * arrow},
                   {c.x, c.y + 0.5f * arrow}},
                  true, v.text, {});
    mPainter.text({rect.max.x + s.itemSpacing.x, rect.centre().y}, shown, s.textSizePt, s.text,
                  {0.0f, 0.5f});
    popupBelow(popupId, rect, fn);
    return r;
}

}  // namespace grass::ui
