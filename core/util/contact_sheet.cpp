#include "util/contact_sheet.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "util/assert.h"

namespace grass {

namespace {

// A dark grey, not black: a black frame (an empty sky at night) stays visible against it.
constexpr std::uint8_t BORDER_RGBA[4] = {24, 24, 24, 255};

std::size_t pixelIndex(int x, int y, int width) {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
            static_cast<std::size_t>(x)) *
           4;
}

}  // namespace

int ContactSheetLayout::cellOf(int frame) const {
    const auto found = std::find(frames.begin(), frames.end(), frame);
    return found == frames.end() ? -1 : static_cast<int>(found - frames.begin());
}

ContactSheetLayout contactSheetLayout(int frameCount, int frameWidth, int frameHeight,
                                      const ContactSheetLimits& limits) {
    GRASS_ASSERT(frameCount >= 1 && frameWidth >= 1 && frameHeight >= 1);
    GRASS_ASSERT(limits.maxColumns >= 1 && limits.maxCells >= 1 && limits.maxCellWidth >= 1);
    ContactSheetLayout layout;
    const int cells = std::min(frameCount, limits.maxCells);
    // Evenly spaced over the turn, frame 0 first; with cells == frameCount, every frame.
    for (int cell = 0; cell < cells; ++cell)
        layout.frames.push_back(
            static_cast<int>(static_cast<long long>(cell) * frameCount / cells));
    layout.columns = std::min(cells, limits.maxColumns);
    layout.rows = (cells + layout.columns - 1) / layout.columns;
    layout.cellWidth = std::min(frameWidth, limits.maxCellWidth);
    // Rounded to the nearest pixel, at least one, never taller than the frame.
    const long long scaledHeight =
        (2LL * frameHeight * layout.cellWidth + frameWidth) / (2LL * frameWidth);
    layout.cellHeight = static_cast<int>(std::clamp<long long>(scaledHeight, 1, frameHeight));
    layout.gapPx = std::max(limits.gapPx, 0);
    return layout;
}

Rgba8Pixels blankContactSheet(const ContactSheetLayout& layout) {
    Rgba8Pixels sheet;
    sheet.width = layout.width();
    sheet.height = layout.height();
    sheet.pixels.resize(static_cast<std::size_t>(sheet.width) *
                        static_cast<std::size_t>(sheet.height) * 4);
    for (std::size_t i = 0; i < sheet.pixels.size(); ++i)
        sheet.pixels[i] = BORDER_RGBA[i % 4];
    return sheet;
}

Rgba8Pixels boxDownscale(const Rgba8Pixels& image, int width, int height) {
    GRASS_ASSERT(width >= 1 && width <= image.width && height >= 1 && height <= image.height);
    GRASS_ASSERT(image.pixels.size() == static_cast<std::size_t>(image.width) *
                                            static_cast<std::size_t>(image.height) * 4);
    Rgba8Pixels out;
    out.width = width;
    out.height = height;
    out.pixels.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    for (int y = 0; y < height; ++y) {
        // Integer footprints tile the source exactly (no pixel counted twice or skipped); with a
        // non-integer ratio they differ by one pixel, which a thumbnail does not show.
        const int y0 = static_cast<int>(static_cast<long long>(y) * image.height / height);
        const int y1 = static_cast<int>(static_cast<long long>(y + 1) * image.height / height);
        for (int x = 0; x < width; ++x) {
            const int x0 = static_cast<int>(static_cast<long long>(x) * image.width / width);
            const int x1 = static_cast<int>(static_cast<long long>(x + 1) * image.width / width);
            std::uint64_t sum[4] = {0, 0, 0, 0};
            for (int sy = y0; sy < y1; ++sy)
                for (int sx = x0; sx < x1; ++sx)
                    for (int c = 0; c < 4; ++c)
                        sum[c] += image.pixels[pixelIndex(sx, sy, image.width) + std::size_t(c)];
            const std::uint64_t count =
                static_cast<std::uint64_t>(x1 - x0) * static_cast<std::uint64_t>(y1 - y0);
            for (int c = 0; c < 4; ++c)
                out.pixels[pixelIndex(x, y, width) + std::size_t(c)] =
                    static_cast<std::uint8_t>((sum[c] + count / 2) / count);
        }
    }
    return out;
}

void placeInContactSheet(Rgba8Pixels& sheet, const ContactSheetLayout& layout, int cell,
                         const Rgba8Pixels& frame) {
    GRASS_ASSERT(cell >= 0 && cell < static_cast<int>(layout.frames.size()));
    GRASS_ASSERT(sheet.width == layout.width() && sheet.height == layout.height());
    const Rgba8Pixels thumb = boxDownscale(frame, std::min(layout.cellWidth, frame.width),
                                           std::min(layout.cellHeight, frame.height));
    const int left = layout.gapPx + (cell % layout.columns) * (layout.cellWidth + layout.gapPx);
    const int top = layout.gapPx + (cell / layout.columns) * (layout.cellHeight + layout.gapPx);
    const std::size_t rowBytes = static_cast<std::size_t>(thumb.width) * 4;
    for (int y = 0; y < thumb.height; ++y)
        std::copy_n(
            thumb.pixels.begin() + static_cast<std::ptrdiff_t>(pixelIndex(0, y, thumb.width)),
            rowBytes,
            sheet.pixels.begin() +
                static_cast<std::ptrdiff_t>(pixelIndex(left, top + y, sheet.width)));
}

}  // namespace grass
