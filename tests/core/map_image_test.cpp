#include "maps/map_image.h"

#include <gtest/gtest.h>

// Writing RGB, two-channel and NaN images needs OIIO directly: saveMapImage writes only
// single-channel, finite maps.
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>

#include "support/test_paths.h"
#include "util/rng.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

MapImage randomMap(int width, int height, std::uint64_t seed) {
    MapImage map = makeConstantMap(width, height, 0.0f);
    Rng rng(seed);
    for (float& t : map.texels)
        t = rng.uniform();
    map.texels[0] = 0.0f;  // the ends of the range survive too
    map.texels[1] = 1.0f;
    return map;
}

float maxError(const MapImage& a, const MapImage& b) {
    float worst = 0.0f;
    for (std::size_t i = 0; i < a.texels.size(); ++i)
        worst = std::max(worst, std::abs(a.texels[i] - b.texels[i]));
    return worst;
}

void writeWithOiio(const fs::path& file, int width, int height, int channels,
                   const std::vector<float>& pixels, OIIO::TypeDesc type) {
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out) << file;
    OIIO::ImageSpec spec(width, height, channels, type);
    // Write the values as given (no division by alpha): what a paint program stores.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    ASSERT_TRUE(out->open(file.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    ASSERT_TRUE(out->close());
}

struct RoundTrip {
    const char* name;
    MapSampleFormat format;
    float tolerance;  // one quantisation step: rounding gives half of it
};

TEST(MapImage, SaveLoadRoundTripsWithinOneStep) {
    const fs::path dir = test::scratchDir("map_image_round_trip");
    const std::uint64_t seed = 17;
    const MapImage map = randomMap(37, 23, seed);
    for (const RoundTrip& c : {RoundTrip{"eight.png", MapSampleFormat::UInt8, 1.0f / 255.0f},
                               RoundTrip{"sixteen.png", MapSampleFormat::Auto, 1.0f / 65535.0f},
                               RoundTrip{"map.tif", MapSampleFormat::Auto, 1.0f / 65535.0f},
                               RoundTrip{"map.exr", MapSampleFormat::Auto, 0.0f}}) {
        const fs::path file = dir / c.name;
        const Result<void> saved = saveMapImage(map, file, c.format);
        ASSERT_TRUE(saved.ok()) << saved.error().str();
        const Result<MapImage> loaded = loadMapImage(file);
        ASSERT_TRUE(loaded.ok()) << loaded.error().str();
        EXPECT_EQ(loaded->width, 37);
        EXPECT_EQ(loaded->height, 23);
        EXPECT_TRUE(loaded->warnings.empty()) << c.name;
        EXPECT_LE(maxError(map, *loaded), c.tolerance) << c.name << " seed " << seed;
    }
    // Nothing but the four maps: the temporary files were renamed away.
    int files = 0;
    for (const auto& entry : fs::directory_iterator(dir))
        files += entry.is_regular_file() ? 1 : 0;
    EXPECT_EQ(files, 4);
}

TEST(MapImage, SaveRefusesFormatsTheFileCannotHold) {
    const fs::path dir = test::scratchDir("map_image_formats");
    const MapImage map = makeConstantMap(2, 2, 0.5f);
    EXPECT_FALSE(saveMapImage(map, dir / "a.png", MapSampleFormat::Float).ok());
    EXPECT_FALSE(saveMapImage(map, dir / "a.exr", MapSampleFormat::UInt8).ok());
    const Result<void> noFolder = saveMapImage(map, dir / "missing" / "a.png");
    ASSERT_FALSE(noFolder.ok());
    EXPECT_NE(noFolder.error().str().find("a.png"), std::string::npos);
}

TEST(MapImage, RgbIsConvertedToLuminanceWithWarning) {
    const fs::path dir = test::scratchDir("map_image_rgb");
    const fs::path file = dir / "rgb.png";
    // Pure red, green, blue, white: luminance = the Rec. 709 weights and 1.
    const std::vector<float> rgb = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    writeWithOiio(file, 2, 2, 3, rgb, OIIO::TypeDesc::UINT16);
    const Result<MapImage> map = loadMapImage(file);
    ASSERT_TRUE(map.ok()) << map.error().str();
    EXPECT_NEAR(map->at(0, 0), 0.2126f, 1e-4f);
    EXPECT_NEAR(map->at(1, 0), 0.7152f, 1e-4f);
    EXPECT_NEAR(map->at(0, 1), 0.0722f, 1e-4f);
    EXPECT_NEAR(map->at(1, 1), 1.0f, 1e-4f);
    ASSERT_EQ(map->warnings.size(), 1u);
    EXPECT_NE(map->warnings[0].find("luminance"), std::string::npos);

    // RGBA: alpha does not count.
    const fs::path rgbaFile = dir / "rgba.tif";
    writeWithOiio(rgbaFile, 1, 1, 4, {0, 1, 0, 0.25f}, OIIO::TypeDesc::FLOAT);
    const Result<MapImage> rgba = loadMapImage(rgbaFile);
    ASSERT_TRUE(rgba.ok()) << rgba.error().str();
    EXPECT_NEAR(rgba->at(0, 0), 0.7152f, 1e-6f);
    EXPECT_NE(rgba->warnings[0].find("alpha"), std::string::npos);

    // Two channels: the first, with a warning.
    const fs::path greyAlpha = dir / "ga.png";
    writeWithOiio(greyAlpha, 1, 1, 2, {0.6f, 0.2f}, OIIO::TypeDesc::UINT16);
    const Result<MapImage> ga = loadMapImage(greyAlpha);
    ASSERT_TRUE(ga.ok()) << ga.error().str();
    EXPECT_NEAR(ga->at(0, 0), 0.6f, 1e-4f);
    EXPECT_EQ(ga->warnings.size(), 1u);
}

TEST(MapImage, OutOfRangeIsClampedAndNanIsAnError) {
    const fs::path dir = test::scratchDir("map_image_range");
    writeWithOiio(dir / "range.exr", 2, 1, 1, {-0.5f, 3.0f}, OIIO::TypeDesc::FLOAT);
    const Result<MapImage> range = loadMapImage(dir / "range.exr");
    ASSERT_TRUE(range.ok()) << range.error().str();
    EXPECT_EQ(range->texels, (std::vector<float>{0.0f, 1.0f}));
    EXPECT_EQ(range->warnings.size(), 1u);

    writeWithOiio(dir / "nan.exr", 2, 1, 1, {0.5f, std::nanf("")}, OIIO::TypeDesc::FLOAT);
    const Result<MapImage> nan = loadMapImage(dir / "nan.exr");
    ASSERT_FALSE(nan.ok());
    EXPECT_NE(nan.error().str().find("nan.exr"), std::string::npos);
    EXPECT_NE(nan.error().message.find("NaN"), std::string::npos);
}

TEST(MapImage, OversizedImageIsRefused) {
    const fs::path dir = test::scratchDir("map_image_big");
    writeWithOiio(dir / "wide.png", 16385, 1, 1, std::vector<float>(16385, 0.5f),
                  OIIO::TypeDesc::UINT8);
    const Result<MapImage> wide = loadMapImage(dir / "wide.png");
    ASSERT_FALSE(wide.ok());
    EXPECT_NE(wide.error().message.find("16384"), std::string::npos) << wide.error().str();
}

TEST(MapImage, MissingOrBrokenFilesNameTheFile) {
    const fs::path dir = test::scratchDir("map_image_errors");
    const Result<MapImage> missing = loadMapImage(dir / "nowhere.png");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().str().find("nowhere.png"), std::string::npos);
    EXPECT_NE(missing.error().message.find("file not found"), std::string::npos);

    const fs::path text = dir / "x.png";
    std::ofstream(text) << "this is not a picture\n";
    const Result<MapImage> broken = loadMapImage(text);
    ASSERT_FALSE(broken.ok());
    EXPECT_NE(broken.error().str().find("x.png"), std::string::npos);
    EXPECT_EQ(broken.error().str().find('\n'), std::string::npos) << broken.error().str();
}

// Texel centres at (i + 0.5) / size; v = 0 is the top row; clamp to edge outside [0, 1].
TEST(MapImage, SampleIsBilinearWithClampToEdge) {
    MapImage map = makeConstantMap(2, 2, 0.0f);
    map.texels = {0.0f, 1.0f,    // top row (v = 0.25)
                  0.5f, 0.25f};  // bottom row (v = 0.75)
    EXPECT_FLOAT_EQ(map.sample({0.25f, 0.25f}), 0.0f);
    EXPECT_FLOAT_EQ(map.sample({0.75f, 0.25f}), 1.0f);
    EXPECT_FLOAT_EQ(map.sample({0.25f, 0.75f}), 0.5f);
    EXPECT_FLOAT_EQ(map.sample({0.75f, 0.75f}), 0.25f);
    EXPECT_FLOAT_EQ(map.sample({0.5f, 0.25f}), 0.5f);
    EXPECT_FLOAT_EQ(map.sample({0.5f, 0.5f}), (0.0f + 1.0f + 0.5f + 0.25f) / 4.0f);
    EXPECT_FLOAT_EQ(map.sample({0.375f, 0.25f}), 0.25f);
    EXPECT_FLOAT_EQ(map.sample({0.0f, 0.0f}), 0.0f);
    EXPECT_FLOAT_EQ(map.sample({-3.0f, 0.25f}), 0.0f);
    EXPECT_FLOAT_EQ(map.sample({1.0f, 0.0f}), 1.0f);
    EXPECT_FLOAT_EQ(map.sample({5.0f, 5.0f}), 0.25f);
    EXPECT_FLOAT_EQ(map.maxValue(), 1.0f);
    EXPECT_EQ(MapImage{}.sample({0.5f, 0.5f}), 0.0f);
    EXPECT_EQ(makeConstantMap(3, 2, 0.7f).texels.size(), 6u);
    EXPECT_FLOAT_EQ(makeConstantMap(3, 2, 7.0f).maxValue(), 1.0f);
}

}  // namespace
}  // namespace grass::core
