// Which of an image's channels make a map's one value (docs/project-format.md, maps): chosen by
// the channels' names, as OpenImageIO reports them (R, G, B, A, Y for the common formats;
// OpenEXR stores its channels sorted by name, so R need not come first, and holds any names).
#pragma once

#include <OpenImageIO/imageio.h>

#include <string>
#include <utility>
#include <vector>

namespace grass::core {

// Rec. 709 luma weights: a colour's value is their sum over its stored R, G and B.
inline constexpr float LUMA_R = 0.2126f, LUMA_G = 0.7152f, LUMA_B = 0.0722f;

struct MapChannels {
    // The channels used (the file's index) and the weight of each.
    std::vector<std::pair<int, float>> weights;
    std::string note;  // what was done, for the user; empty for one plain grey channel
};

// R, G and B named: Rec. 709 luminance of those. Else Y named: Y. Else three or more channels
// none of which is named R, G, B or Y: the luminance of the first three, as before names were
// read. Else the first channel that is not alpha, and alpha only when it is all there is. Alpha
// (OpenImageIO's alpha channel, or one named A) is coverage, never the value, while anything
// else is there.
MapChannels chooseMapChannels(const OIIO::ImageSpec& spec);

}  // namespace grass::core
