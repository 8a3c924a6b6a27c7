// Contact sheets: many frames (a turntable's views) shrunk into one grid image, so a whole turn
// can be seen and shared as one file. Pixels are 8-bit RGBA, row 0 at the top (Rgba8Pixels of
// util/image_file.h); sizes in pixels.
#pragma once

#include <vector>

#include "util/image_file.h"

namespace grass {

struct ContactSheetLimits {
    // 8 columns keep a sheet of a full turn about as wide as a screen.
    int maxColumns = 8;
    // At most 64 cells: beyond that the cells get too small to read, so longer turns show an
    // evenly spaced selection of their frames instead of every one.
    int maxCells = 64;
    // Cells are at most this wide (the frame's aspect is kept); frames are never enlarged.
    int maxCellWidth = 256;
    // Dark border between and around cells, so neighbouring views read as separate pictures.
    int gapPx = 2;
};

struct ContactSheetLayout {
    int columns = 1;
    int rows = 1;
    int cellWidth = 1;
    int cellHeight = 1;
    int gapPx = 0;
    // The frame shown in each cell, in reading order (left to right, top to bottom).
    std::vector<int> frames;

    int width() const { return columns * cellWidth + (columns + 1) * gapPx; }
    int height() const { return rows * cellHeight + (rows + 1) * gapPx; }
    // The cell showing `frame`, or −1 when the frame is not on the sheet.
    int cellOf(int frame) const;
    bool operator==(const ContactSheetLayout&) const = default;
};

// The grid for frameCount frames of frameWidth × frameHeight. Precondition: all ≥ 1.
ContactSheetLayout contactSheetLayout(int frameCount, int frameWidth, int frameHeight,
                                      const ContactSheetLimits& limits = {});

// An empty sheet of the layout's size, filled with the border colour.
Rgba8Pixels blankContactSheet(const ContactSheetLayout& layout);

// Shrinks (never enlarges) `image` to width × height with a box filter: each output pixel is
// the mean of the source pixels its footprint covers. Precondition: 1 ≤ width ≤ image.width,
// 1 ≤ height ≤ image.height.
Rgba8Pixels boxDownscale(const Rgba8Pixels& image, int width, int height);

// Shrinks `frame` to a cell and copies it into cell `cell` of `sheet`.
// Precondition: sheet made by blankContactSheet(layout), 0 ≤ cell < layout.frames.size().
void placeInContactSheet(Rgba8Pixels& sheet, const ContactSheetLayout& layout, int cell,
                         const Rgba8Pixels& frame);

}  // namespace grass
