// The timeline strip (issue 26 item 4): a wide bar under the viewport, as in Blender and every
// animation tool. Its first row plays, pauses, steps and loops, with the time and speed boxes
// (drag, or click to type); its track spans the timeline's range with a
// tick for every key of every wind and collider path (the selected object's brighter) and the
// playhead: a click or drag on the track scrubs, a click on a tick selects the object that key
// moves and jumps to the key's time.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/panels.h"
#include "ui/text_edit.h"

namespace grass::editor {

namespace {

// Pointer distance (points) within which a click on the track takes the key under it.
constexpr float KEY_PICK_POINTS = 5.0f;

float timeAt(const core::Timeline& t, const ui::Rect& track, float x) {
    const double f = std::clamp((x - track.min.x) / std::max(track.width(), 1.0f), 0.0f, 1.0f);
    return static_cast<float>(t.startS() + f * (t.endS() - t.startS()));
}

float xAt(const core::Timeline& t, const ui::Rect& track, double timeS) {
    const double span = std::max(t.endS() - t.startS(), 1e-9);
    return track.min.x + static_cast<float>((timeS - t.startS()) / span) * track.width();
}

void transportRow(ui::Ui& row, EditorState& s) {
    core::Timeline& t = s.view.timeline;
    if (row.button("|<").onHoverText("Back to the start of the timeline").clicked())
        s.view.timeJump = t.scrub(t.startS());
    if (row.button("<").onHoverText("One physics step back").clicked())
        s.view.timeJump = t.stepBack();
    if (row.button(t.playing() ? "pause" : "play").onHoverText("Play or pause (Space)").clicked())
        s.view.timeJump = t.toggle();
    if (row.button(">").onHoverText("One physics step forward").clicked())
        s.view.timeJump = t.stepForward();
    bool loop = t.looping();
    if (row.checkbox(loop, "loop").onHoverText("Start again at the end of the range").changed())
        t.setLoop(loop);
    float timeS = static_cast<float>(t.timeS());
    if (ui::dragValueWithEntry(row, "s##time", timeS, 0.01f, static_cast<float>(t.startS()),
                               static_cast<float>(t.endS()), 2)
            .onHoverText(ui::withTypingHint("Scene time in seconds: drag it"))
            .changed())
        s.view.timeJump = t.scrub(timeS);
    float speed = static_cast<float>(t.speed());
    if (ui::dragValueWithEntry(row, "× speed", speed, 0.01f,
                               static_cast<float>(core::TIMELINE_MIN_SPEED),
                               static_cast<float>(core::TIMELINE_MAX_SPEED), 2)
            .onHoverText("Playback speed (scene seconds per second)")
            .changed())
        t.setSpeed(speed);
}

void drawTrack(ui::Ui& ui, EditorState& s, const std::vector<core::OwnedKey>& keys) {
    core::Timeline& t = s.view.timeline;
    const ui::Style& style = ui.style();
    const ui::Rect track = ui.allocate({ui.availableWidth(), 18.0f});
    ui::Response r = ui.interact(track, ui.makeId("track"), ui::Sense::clickAndDrag());
    const std::optional<PlacedObject>& selected = s.view.place.selected;
    const auto isSelected = [&](const core::OwnedKey& key) {
        return selected && (selected->kind == PlacedKind::Wind) == key.wind &&
               selected->index == key.index;
    };
    // A press on a tick takes its key; anywhere else (and any drag) scrubs.
    if (r.dragStarted() || r.clicked() || r.dragged()) {
        const float pointerTime = timeAt(t, track, r.pointerPos().x);
        const float tolerance =
            KEY_PICK_POINTS * static_cast<float>(t.endS() - t.startS()) / std::max(track.width(), 1.0f);
        const auto key = r.clicked() ? core::nearestOwnedKey(keys, pointerTime, tolerance)
                                     : std::nullopt;
        if (key) {
            s.view.place.selected = PlacedObject{key->wind ? PlacedKind::Wind : PlacedKind::Collider,
                                                 key->index};
            s.view.timeJump = t.scrub(key->timeS);
        } else if (std::abs(pointerTime - t.timeS()) > 1e-6) {
            s.view.timeJump = t.scrub(pointerTime);
        }
    }
    r.onHoverText("Click or drag to scrub; click a key's tick to select what it moves and go to it");
    ui::Painter& p = ui.painter();
    p.rect(track, style.rounding, style.extremeBg, {1.0f, style.separator});
    // Whole seconds, as a ruler (every 5 s, 10 s... on a long range).
    const double span = t.endS() - t.startS();
    const double every = span <= 20.0 ? 1.0 : span <= 100.0 ? 5.0 : std::pow(10.0, std::ceil(std::log10(span / 20.0)));
    for (double second = std::ceil(t.startS() / every) * every; second <= t.endS(); second += every) {
        const float x = xAt(t, track, second);
        p.line({x, track.max.y - 4.0f}, {x, track.max.y}, {1.0f, style.textWeak});
    }
    for (const core::OwnedKey& key : keys) {
        const float x = xAt(t, track, key.timeS);
        const ui::Color32 colour = isSelected(key) ? style.accent : style.text;
        p.rect({{x - 1.5f, track.min.y + 3.0f}, {x + 1.5f, track.max.y - 3.0f}}, 0.0f, colour);
    }
    const float head = xAt(t, track, t.timeS());
    p.line({head, track.min.y}, {head, track.max.y}, {2.0f, style.refused});
}

}  // namespace

void timelineStrip(ui::Context& ctx, ui::Rect rect, EditorState& s) {
    const ui::Style& style = ctx.style();
    paintBar(ctx, rect);
    ui::Ui ui(ctx, {rect.min + ui::Vec2(8.0f, 4.0f), rect.max - ui::Vec2(8.0f, 2.0f)},
              ui::Layer::Panels);
    ui.pushId("timeline strip");
    const std::vector<core::OwnedKey> keys = core::ownedKeys(s.doc.project());
    ui.horizontal([&](ui::Ui& row) {
        transportRow(row, s);
        // The range and the key count as the room left allows: cut at a narrow window's edge,
        // the line read "0.0" (at 800 points).
        char range[64];
        std::snprintf(range, sizeof range, "   %.2f – %.2f s, %zu keys", s.view.timeline.startS(),
                      s.view.timeline.endS(), keys.size());
        const auto fits = [&](const char* text) {
            return ctx.fonts().textSize(text, style.textSizePt).x <= row.availableWidth();
        };
        if (!fits(range))
            std::snprintf(range, sizeof range, "   %zu keys", keys.size());
        if (fits(range))
            row.coloredLabel(range, style.textWeak);
    });
    drawTrack(ui, s, keys);
    ui.popId();
}

}  // namespace grass::editor
