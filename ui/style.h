// The look of the UI: sizes in points and colours of a dark, egui-like theme. A plain value
// type owned by the Context (Context::style()); widgets read it every frame, so changing a field
// takes effect on the next frame.
#pragma once

#include "shape.h"
#include "types.h"

namespace grass::ui {

// How an interactive widget is drawn in one of its states (inactive, hovered, active).
struct WidgetVisuals {
    Color32 bgFill;
    Stroke bgStroke;
    Color32 text;
};

struct Style {
    // 14 pt DejaVu Sans reads well at 1 pixel per point and keeps a side panel compact.
    float textSizePt = 14.0f;
    // Gap between consecutive items: x in horizontal layouts and grids, y in vertical ones.
    Vec2 itemSpacing{8.0f, 4.0f};
    // Inside buttons, combo boxes and drag values, around the text.
    Vec2 buttonPadding{6.0f, 2.0f};
    // Minimum height of interactive widgets; rows of a horizontal layout or grid centre smaller
    // items (labels) in it so their text lines up with the text in buttons.
    float interactHeight = 22.0f;
    float indent = 18.0f;
    float rounding = 3.0f;
    // Width of a slider's track; the handle centre travels sliderWidth − 2·sliderHandleRadius.
    float sliderWidth = 140.0f;
    float sliderHandleRadius = 7.0f;
    float sliderRailHeight = 4.0f;
    float comboWidth = 120.0f;
    float dragValueMinWidth = 50.0f;
    // Check box and radio button size.
    float iconSize = 14.0f;
    float iconSpacing = 5.0f;
    float scrollBarWidth = 8.0f;
    float scrollBarMinHandle = 16.0f;
    float popupPadding = 4.0f;
    float separatorSpace = 6.0f;
    Vec2 tooltipOffset{14.0f, 18.0f};
    // A tooltip wider than this (or than the screen) wraps into lines: a setting's help with its
    // allowed values and JSON key runs to 200 characters, cut off at the window's edge before.
    float tooltipMaxWidth = 560.0f;
    // Two clicks on one widget within this time are a double click.
    float doubleClickTimeS = 0.3f;
    // A press that moves further than this before its release is a drag, not a click, on
    // widgets that sense both.
    float clickMaxDistance = 6.0f;

    Color32 panelFill = Color32::rgb(27, 27, 27);
    Color32 popupFill = Color32::rgb(32, 32, 32);
    Color32 extremeBg = Color32::rgb(10, 10, 10);
    Stroke popupStroke{1.0f, Color32::rgb(60, 60, 60)};
    Color32 text = Color32::rgb(190, 190, 190);
    Color32 textWeak = Color32::rgb(120, 120, 120);
    Color32 textStrong = Color32::rgb(255, 255, 255);
    Color32 separator = Color32::rgb(60, 60, 60);
    // Selected items, slider fill, progress bar, checked boxes' marks.
    Color32 selectionFill = Color32::rgb(0, 92, 128);
    Color32 accent = Color32::rgb(90, 170, 255);
    // A refused entry: its box's outline and the reason under it.
    Color32 refused = Color32::rgb(255, 110, 80);
    Color32 scrollBarTrack = Color32::rgb(40, 40, 40);

    WidgetVisuals nonInteractive{
        Color32::rgb(27, 27, 27), {1.0f, Color32::rgb(60, 60, 60)}, Color32::rgb(190, 190, 190)};
    WidgetVisuals inactive{
        Color32::rgb(60, 60, 60), {0.0f, Color32::transparent()}, Color32::rgb(200, 200, 200)};
    WidgetVisuals hovered{
        Color32::rgb(70, 70, 70), {1.0f, Color32::rgb(150, 150, 150)}, Color32::rgb(240, 240, 240)};
    WidgetVisuals active{
        Color32::rgb(55, 55, 55), {1.0f, Color32::rgb(255, 255, 255)}, Color32::rgb(255, 255, 255)};
};

}  // namespace grass::ui
