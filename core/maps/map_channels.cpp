#include "maps/map_channels.h"

#include <algorithm>

#include "util/file_extension.h"
#include "util/image_layout.h"

namespace grass::core {

namespace {

const std::string LUMINANCE = "converted to luminance (Rec. 709 weights on the stored values)";

std::string channelName(const OIIO::ImageSpec& spec, int c) {
    return c < static_cast<int>(spec.channelnames.size()) ? spec.channelnames[c]
                                                          : "channel " + std::to_string(c);
}

int named(const OIIO::ImageSpec& spec, const std::string& wanted) {
    for (int c = 0; c < spec.nchannels; ++c)
        if (asciiLowerCase(channelName(spec, c)) == wanted)
            return c;
    return -1;
}

bool isAlpha(const OIIO::ImageSpec& spec, int c) {
    return c == alphaChannelOf(spec);
}

// "A, Z" for the channels other than `used`.
std::string others(const OIIO::ImageSpec& spec, const std::vector<int>& used) {
    std::string list;
    for (int c = 0; c < spec.nchannels; ++c) {
        if (std::find(used.begin(), used.end(), c) != used.end())
            continue;
        list += (list.empty() ? "" : ", ") + channelName(spec, c);
    }
    return list;
}

MapChannels weighted(std::vector<std::pair<int, float>> weights, std::string note) {
    return {std::move(weights), std::move(note)};
}

}  // namespace

MapChannels chooseMapChannels(const OIIO::ImageSpec& spec) {
    const int n = spec.nchannels;
    // Two channels that carry only OpenImageIO's default names (a TIFF that names none):
    // grey and alpha, what two channels mean in PNG and in most tools.
    if (n == 2 && channelName(spec, 0) == "R" && channelName(spec, 1) == "G" &&
        alphaChannelOf(spec) < 0)
        return weighted({{0, 1.0f}}, "2 channels (grey + alpha): using grey, alpha ignored");
    const int r = named(spec, "r"), g = named(spec, "g"), b = named(spec, "b"),
              y = named(spec, "y");
    if (r >= 0 && g >= 0 && b >= 0) {
        const std::string rest = others(spec, {r, g, b});
        const bool rgba = n == 4 && alphaChannelOf(spec) >= 0;
        std::string note = (n == 3 ? "RGB " : rgba ? "RGBA " : "R, G, B ") + LUMINANCE;
        if (rgba)
            note += "; alpha ignored";
        else if (!rest.empty())
            note += "; " + rest + " ignored";
        return weighted({{r, LUMA_R}, {g, LUMA_G}, {b, LUMA_B}}, note);
    }
    if (y < 0 && n >= 3 && r < 0 && g < 0 && b < 0) {
        std::string note = "the first 3 of " + std::to_string(n) + " channels " + LUMINANCE;
        if (n > 3)
            note += "; channels 4 to " + std::to_string(n) + " ignored";
        return weighted({{0, LUMA_R}, {1, LUMA_G}, {2, LUMA_B}}, note);
    }
    int value = y;
    for (int c = 0; value < 0 && c < n; ++c)
        if (!isAlpha(spec, c))
            value = c;
    if (value < 0)
        return weighted({{0, 1.0f}}, "its only channel is alpha (" + channelName(spec, 0) +
                                         "): read as the value");
    const std::string rest = others(spec, {value});
    if (rest.empty())
        return weighted({{value, 1.0f}}, "");
    if (n == 2 && isAlpha(spec, 1 - value))
        return weighted({{value, 1.0f}}, "2 channels (grey + alpha): using grey, alpha ignored");
    return weighted({{value, 1.0f}}, "channels " + others(spec, {}) + ": " +
                                         channelName(spec, value) + " read as the value, " + rest +
                                         " ignored");
}

}  // namespace grass::core
