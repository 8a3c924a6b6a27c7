#include "maps/map_image.h"

#include <gtest/gtest.h>

// Writing RGB, two-channel and NaN images needs OIIO directly: saveMapImage writes only
// single-channel, finite maps. Reading a file's spec proves what saveMapImage really wrote.
#include <OpenImageIO/imageio.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <utility>

#include "util/rng.h"

#include "support/scratch_folder.h"
#include "support/spec_on_disk.h"

namespace grass::core {
namespace {

namespace fs = std::filesystem;

using test::ScratchFolder;
using test::specOnDisk;

MapImage randomMap(int width, int height, std::uint64_t seed) {
    MapImage map = makeConstantMap(width, height, 0.0f);
    Rng rng(seed);
    for (float& t : map.texels)
        t = rng.uniform();
    map.texels[0] = 0.0f;  // the ends of the range survive too
    map.texels[1] = 1.0f;
    return map;
}

// Random texels under a top row that ramps 0 -> 1: the ramp visits every 8-bit code (width
// 256), so a systematic bias (truncation instead of rounding) shows up as well as noise.
MapImage gradientAndRandomMap(std::uint64_t seed) {
    MapImage map = randomMap(256, 5, seed);
    for (int x = 0; x < map.width; ++x)
        map.texels[static_cast<std::size_t>(x)] = static_cast<float>(x) / 255.0f;
    return map;
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

void expectOneLineErrorNaming(const Result<MapImage>& result, const std::string& file,
                              const std::string& what) {
    ASSERT_FALSE(result.ok()) << what;
    const std::string text = result.error().str();
    EXPECT_NE(text.find(file), std::string::npos) << what << ": " << text;
    EXPECT_EQ(text.find('\n'), std::string::npos) << what << ": " << text;
}

struct RoundTrip {
    const char* name;
    MapSampleFormat format;
    OIIO::TypeDesc::BASETYPE onDisk;
    // Allowed |loaded - saved| = absolute + relative * |saved|.
    float absolute;
    float relative;
};

TEST(MapImage, SaveLoadRoundTripsWithinTheFormatsPrecision) {
    const ScratchFolder dir("round_trip");
    const std::uint64_t seed = 17;
    const MapImage map = gradientAndRandomMap(seed);
    // Integer formats round to the nearest code, so the error is at most half a step (the
    // 1.001 leaves room for float rounding of the scale). Half keeps 11 significant bits: half
    // an ulp is 2^-11 of the value, and subnormals (below 2^-14) are spaced 2^-24 apart. Float
    // files hold the float texels themselves.
    const float halfStep8 = 0.5f * 1.001f / 255.0f, halfStep16 = 0.5f * 1.001f / 65535.0f;
    const std::array cases = {
        RoundTrip{"eight.png", MapSampleFormat::UInt8, OIIO::TypeDesc::UINT8, halfStep8, 0.0f},
        RoundTrip{"sixteen.png", MapSampleFormat::Auto, OIIO::TypeDesc::UINT16, halfStep16, 0.0f},
        RoundTrip{"eight.tif", MapSampleFormat::UInt8, OIIO::TypeDesc::UINT8, halfStep8, 0.0f},
        RoundTrip{"sixteen.tif", MapSampleFormat::Auto, OIIO::TypeDesc::UINT16, halfStep16, 0.0f},
        RoundTrip{"float.tiff", MapSampleFormat::Float, OIIO::TypeDesc::FLOAT, 0.0f, 0.0f},
        RoundTrip{"half.exr", MapSampleFormat::Half, OIIO::TypeDesc::HALF, 0x1p-25f, 0x1p-11f},
        RoundTrip{"float.exr", MapSampleFormat::Auto, OIIO::TypeDesc::FLOAT, 0.0f, 0.0f},
    };
    for (const RoundTrip& c : cases) {
        const fs::path file = dir / c.name;
        const Result<void> saved = saveMapImage(map, file, c.format);
        ASSERT_TRUE(saved.ok()) << saved.error().str();
        const OIIO::ImageSpec disk = specOnDisk(file);
        EXPECT_EQ(disk.format, OIIO::TypeDesc(c.onDisk)) << c.name << " is " << disk.format;
        EXPECT_EQ(disk.nchannels, 1) << c.name;

        const Result<MapImage> loaded = loadMapImage(file);
        ASSERT_TRUE(loaded.ok()) << loaded.error().str();
        EXPECT_EQ(loaded->width, map.width);
        EXPECT_EQ(loaded->height, map.height);
        EXPECT_TRUE(loaded->warnings.empty()) << c.name;
        ASSERT_EQ(loaded->texels.size(), map.texels.size());
        for (std::size_t i = 0; i < map.texels.size(); ++i) {
            const float want = map.texels[i];
            ASSERT_LE(std::abs(loaded->texels[i] - want), c.absolute + c.relative * want)
                << c.name << " texel " << i << " seed " << seed;
        }
    }
    // Nothing but the maps: the temporary files were renamed away.
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(dir.path()))
        files += entry.is_regular_file() ? 1 : 0;
    EXPECT_EQ(files, cases.size());
}

TEST(MapImage, SaveRefusesFormatsTheFileCannotHold) {
    const ScratchFolder dir("formats");
    const MapImage map = makeConstantMap(2, 2, 0.5f);
    EXPECT_FALSE(saveMapImage(map, dir / "a.png", MapSampleFormat::Float).ok());
    EXPECT_FALSE(saveMapImage(map, dir / "a.png", MapSampleFormat::Half).ok());
    EXPECT_FALSE(saveMapImage(map, dir / "a.tif", MapSampleFormat::Half).ok());
    EXPECT_FALSE(saveMapImage(map, dir / "a.exr", MapSampleFormat::UInt8).ok());
    EXPECT_FALSE(saveMapImage(map, dir / "a.exr", MapSampleFormat::UInt16).ok());
    const Result<void> noFolder = saveMapImage(map, dir / "missing" / "a.png");
    ASSERT_FALSE(noFolder.ok());
    EXPECT_NE(noFolder.error().str().find("a.png"), std::string::npos);
}

TEST(MapImage, RgbIsConvertedToLuminanceWithWarning) {
    const ScratchFolder dir("rgb");
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
}

// Each channel count gets one warning that says what was done; grey alone gets none.
TEST(MapImage, EveryChannelCountIsReadWithAWarningSayingHow) {
    const ScratchFolder dir("channels");
    struct Case {
        const char* name;
        int channels;
        std::vector<float> pixel;
        float grey;
        std::vector<std::string> said;  // phrases the warning must contain
    };
    // Alpha and extra channels hold values that would change the result if they were read.
    const std::array cases = {
        Case{"grey.tif", 1, {0.6f}, 0.6f, {}},
        Case{"ga.tif", 2, {0.6f, 0.2f}, 0.6f, {"grey", "alpha ignored"}},
        Case{"rgb.tif", 3, {0, 1, 0}, 0.7152f, {"RGB", "luminance"}},
        Case{"rgba.tif", 4, {0, 1, 0, 0.25f}, 0.7152f, {"RGBA", "luminance", "alpha ignored"}},
        Case{"five.tif", 5, {0, 1, 0, 0.25f, 0.9f}, 0.7152f, {"R, G, B", "A, channel4 ignored"}},
    };
    for (const Case& c : cases) {
        writeWithOiio(dir / c.name, 1, 1, c.channels, c.pixel, OIIO::TypeDesc::FLOAT);
        const Result<MapImage> map = loadMapImage(dir / c.name);
        ASSERT_TRUE(map.ok()) << map.error().str();
        // Float TIFF: the only error is the luminance sum's float rounding.
        EXPECT_NEAR(map->at(0, 0), c.grey, 1e-6f) << c.name;
        if (c.said.empty()) {
            EXPECT_TRUE(map->warnings.empty()) << c.name;
            continue;
        }
        ASSERT_EQ(map->warnings.size(), 1u) << c.name;
        EXPECT_NE(map->warnings[0].find(c.name), std::string::npos) << map->warnings[0];
        for (const std::string& phrase : c.said)
            EXPECT_NE(map->warnings[0].find(phrase), std::string::npos) << map->warnings[0];
    }
}

TEST(MapImage, OutOfRangeIsClampedAndNanOrInfIsAnErrorSayingWhere) {
    const ScratchFolder dir("range");
    writeWithOiio(dir / "range.exr", 2, 1, 1, {-0.5f, 3.0f}, OIIO::TypeDesc::FLOAT);
    const Result<MapImage> range = loadMapImage(dir / "range.exr");
    ASSERT_TRUE(range.ok()) << range.error().str();
    EXPECT_EQ(range->texels, (std::vector<float>{0.0f, 1.0f}));
    EXPECT_EQ(range->warnings.size(), 1u);

    // The bad texel is at x 2, y 1: the message must point at it, not just say "bad file".
    std::vector<float> pixels(6, 0.5f);
    pixels[5] = std::nanf("");
    writeWithOiio(dir / "nan.exr", 3, 2, 1, pixels, OIIO::TypeDesc::FLOAT);
    const Result<MapImage> nan = loadMapImage(dir / "nan.exr");
    expectOneLineErrorNaming(nan, "nan.exr", "NaN");
    EXPECT_NE(nan.error().message.find("NaN"), std::string::npos) << nan.error().str();
    EXPECT_NE(nan.error().message.find("(2, 1)"), std::string::npos) << nan.error().str();

    pixels[5] = 0.5f;
    pixels[1] = INFINITY;
    writeWithOiio(dir / "inf.exr", 3, 2, 1, pixels, OIIO::TypeDesc::HALF);
    const Result<MapImage> inf = loadMapImage(dir / "inf.exr");
    expectOneLineErrorNaming(inf, "inf.exr", "Inf");
    EXPECT_NE(inf.error().message.find("infinite"), std::string::npos) << inf.error().str();
    EXPECT_NE(inf.error().message.find("(1, 0)"), std::string::npos) << inf.error().str();
}

TEST(MapImage, OversizedImageIsRefused) {
    const ScratchFolder dir("big");
    writeWithOiio(dir / "wide.png", 16385, 1, 1, std::vector<float>(16385, 0.5f),
                  OIIO::TypeDesc::UINT8);
    const Result<MapImage> wide = loadMapImage(dir / "wide.png");
    ASSERT_FALSE(wide.ok());
    EXPECT_NE(wide.error().message.find("16384"), std::string::npos) << wide.error().str();
}

// The standard CRC-32 (polynomial 0xEDB88320) that every PNG chunk carries: without it libpng
// would reject the crafted header for its checksum and never look at the size.
std::uint32_t crc32(const std::vector<char>& bytes, std::size_t first, std::size_t count) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (std::size_t i = first; i < first + count; ++i) {
        crc ^= static_cast<std::uint8_t>(bytes[i]);
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc >> 1) ^ ((crc & 1u) ? 0xEDB88320u : 0u);
    }
    return ~crc;
}

std::vector<char> readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const fs::path& file, const std::vector<char>& bytes) {
    std::ofstream(file, std::ios::binary)
        .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Whatever is wrong with the file, loading returns (no crash, no hang) one line naming it.
TEST(MapImage, BadFilesGiveOneLineErrorsNamingTheFile) {
    const ScratchFolder dir("errors");
    const Result<MapImage> missing = loadMapImage(dir / "nowhere.png");
    expectOneLineErrorNaming(missing, "nowhere.png", "missing");
    EXPECT_NE(missing.error().message.find("file not found"), std::string::npos);

    fs::create_directory(dir / "folder.png");
    const Result<MapImage> folder = loadMapImage(dir / "folder.png");
    expectOneLineErrorNaming(folder, "folder.png", "folder");
    EXPECT_NE(folder.error().message.find("folder"), std::string::npos);

    std::ofstream(dir / "empty.png").close();
    expectOneLineErrorNaming(loadMapImage(dir / "empty.png"), "empty.png", "empty file");

    std::ofstream(dir / "text.png") << "this is not a picture\n";
    expectOneLineErrorNaming(loadMapImage(dir / "text.png"), "text.png", "text file");

    // Half the bytes of a valid file: the header reads, the pixels run out. 64×64 random
    // texels do not compress, so half the file loses many rows, not just a trailer.
    const MapImage noise = randomMap(64, 64, 5);
    for (const char* name : {"cut.png", "cut.exr"}) {
        ASSERT_TRUE(saveMapImage(noise, dir / name).ok());
        fs::resize_file(dir / name, fs::file_size(dir / name) / 2);
        expectOneLineErrorNaming(loadMapImage(dir / name), name, "truncated");
    }

    // A PNG whose header claims 0×0 (OIIO refuses to write one): width and height are the
    // first 8 bytes of the IHDR data at offset 16, its CRC covers offsets 12 to 28.
    ASSERT_TRUE(saveMapImage(makeConstantMap(1, 1, 0.5f), dir / "zero.png").ok());
    std::vector<char> png = readBytes(dir / "zero.png");
    ASSERT_GT(png.size(), 33u);
    ASSERT_EQ(std::string(&png[12], 4), "IHDR");
    std::fill(png.begin() + 16, png.begin() + 24, '\0');
    const std::uint32_t crc = crc32(png, 12, 17);
    for (int i = 0; i < 4; ++i)
        png[29 + static_cast<std::size_t>(i)] = static_cast<char>((crc >> (24 - 8 * i)) & 0xFFu);
    writeBytes(dir / "zero.png", png);
    expectOneLineErrorNaming(loadMapImage(dir / "zero.png"), "zero.png", "0×0 header");
}

// A header claiming 65536×65536 (16 GiB as float texels) is refused from the header alone, with
// the memory it would take: the file holds one pixel, so nothing of that size is ever allocated.
TEST(MapImage, HugeHeaderIsRefusedBeforeDecoding) {
    const ScratchFolder dir("huge");
    ASSERT_TRUE(saveMapImage(makeConstantMap(1, 1, 0.5f), dir / "huge.png").ok());
    std::vector<char> png = readBytes(dir / "huge.png");
    ASSERT_GT(png.size(), 33u);
    ASSERT_EQ(std::string(&png[12], 4), "IHDR");
    // Width and height, big-endian 0x00010000 = 65536, at offsets 16 and 20.
    for (std::size_t at : {16u, 20u}) {
        png[at] = png[at + 2] = png[at + 3] = '\0';
        png[at + 1] = '\1';
    }
    const std::uint32_t crc = crc32(png, 12, 17);
    for (int i = 0; i < 4; ++i)
        png[29 + static_cast<std::size_t>(i)] = static_cast<char>((crc >> (24 - 8 * i)) & 0xFFu);
    writeBytes(dir / "huge.png", png);
    const Result<MapImage> huge = loadMapImage(dir / "huge.png");
    expectOneLineErrorNaming(huge, "huge.png", "65536² header");
    ASSERT_FALSE(huge.ok());
    for (const char* part : {"65536×65536", "16 GiB", "16384×16384", "1 GiB", "before decoding"})
        EXPECT_NE(huge.error().message.find(part), std::string::npos) << huge.error().str();
}

// A zero size is refused at every door: nothing to save, no size to load at, and asking
// resampleMap for one is a bug in the caller (GRASS_ASSERT).
TEST(MapImage, ZeroSizesAreRefused) {
    const ScratchFolder dir("zero");
    const MapImage empty = makeConstantMap(0, 0, 0.5f);
    EXPECT_EQ(empty.width, 0);
    EXPECT_TRUE(empty.texels.empty());
    const Result<void> saved = saveMapImage(empty, dir / "empty.png");
    ASSERT_FALSE(saved.ok());
    EXPECT_NE(saved.error().str().find("empty.png"), std::string::npos);
    EXPECT_NE(saved.error().message.find("empty"), std::string::npos) << saved.error().str();

    ASSERT_TRUE(saveMapImage(makeConstantMap(3, 2, 0.5f), dir / "map.png").ok());
    expectOneLineErrorNaming(loadMapImageAt(dir / "map.png", 0, 0), "map.png", "load at 0×0");
    expectOneLineErrorNaming(loadMapImageAt(dir / "map.png", 4, -1), "map.png", "load at 4×-1");
}

TEST(MapImageDeathTest, ResampleToZeroSizeIsABug) {
    // The process already runs threads (gtest counts 5 before any test); re-running the
    // binary avoids a fork with threads (gtest's advice for death tests).
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const MapImage map = makeConstantMap(4, 4, 0.5f);
    EXPECT_DEATH((void)resampleMap(map, 0, 4), "assertion failed");
    EXPECT_DEATH((void)resampleMap(MapImage{}, 4, 4), "assertion failed");
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

// Sizes that exercise each path per axis: enlarging, shrinking by less than 2× (bilinear),
// by a non-integer factor above 2× and by an integer one (box).
struct Resize {
    int fromW, fromH, toW, toH;
};
constexpr std::array RESIZES = {Resize{40, 30, 100, 75}, Resize{40, 30, 27, 20},
                                Resize{40, 30, 7, 4},    Resize{40, 30, 5, 6},
                                Resize{40, 30, 100, 4},  Resize{40, 30, 40, 7}};

TEST(MapImageResample, SameSizeIsABitExactCopy) {
    MapImage map = randomMap(13, 9, 3);
    map.warnings.push_back("from the file");
    const MapImage same = resampleMap(map, 13, 9);
    EXPECT_EQ(same.width, 13);
    EXPECT_EQ(same.height, 9);
    EXPECT_EQ(same.texels, map.texels);
    EXPECT_EQ(same.warnings, map.warnings);
}

TEST(MapImageResample, ConstantStaysConstant) {
    for (const Resize& r : RESIZES) {
        const MapImage out = resampleMap(makeConstantMap(r.fromW, r.fromH, 0.37f), r.toW, r.toH);
        ASSERT_EQ(out.width, r.toW);
        ASSERT_EQ(out.height, r.toH);
        ASSERT_EQ(out.texels.size(), static_cast<std::size_t>(r.toW * r.toH));
        // The weights sum to 1 up to float rounding: at most ~10 taps per axis here, each
        // rounding by 2^-24 relative, so 1e-6 is several times the worst case.
        for (const float t : out.texels)
            ASSERT_NEAR(t, 0.37f, 1e-6f)
                << r.fromW << "×" << r.fromH << " -> " << r.toW << "×" << r.toH;
    }
}

// A linear ramp f(u, v) resampled must still read f at each new texel centre's UV.
TEST(MapImageResample, LinearRampStaysARamp) {
    const float a = 0.5f, b = 0.25f;  // f = 0.2 + a u + b v stays inside [0, 1]
    const auto ramp = [&](float u, float v) { return 0.2f + a * u + b * v; };
    for (const Resize& r : RESIZES) {
        MapImage map = makeConstantMap(r.fromW, r.fromH, 0.0f);
        for (int y = 0; y < r.fromH; ++y)
            for (int x = 0; x < r.fromW; ++x)
                map.texels[static_cast<std::size_t>(y * r.fromW + x)] =
                    ramp((static_cast<float>(x) + 0.5f) / static_cast<float>(r.fromW),
                         (static_cast<float>(y) + 0.5f) / static_cast<float>(r.fromH));
        const MapImage out = resampleMap(map, r.toW, r.toH);
        // Bilinear reproduces a linear function exactly. The box averages the source's
        // staircase (texels are constant over their footprint), which differs from the ramp
        // by a zero-mean sawtooth of amplitude half a source step; its integral over any
        // interval is at most 1/8 of a step, so the average is off by at most a step / 8 (and
        // by less the wider the footprint). 1e-5 covers float rounding.
        const bool boxU = r.fromW > 2 * r.toW, boxV = r.fromH > 2 * r.toH;
        const float stepU = a / static_cast<float>(r.fromW),
                    stepV = b / static_cast<float>(r.fromH);
        const float tolerance = (boxU ? stepU / 8.0f : 0.0f) + (boxV ? stepV / 8.0f : 0.0f) + 1e-5f;
        int checked = 0;
        for (int y = 0; y < r.toH; ++y) {
            for (int x = 0; x < r.toW; ++x) {
                const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(r.toW);
                const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(r.toH);
                // Outside the outermost source texel centres the source itself is clamped to
                // its edge (MapImage::sample), not a ramp, when enlarging.
                const float edgeU = 0.5f / static_cast<float>(r.fromW);
                const float edgeV = 0.5f / static_cast<float>(r.fromH);
                if (u < edgeU || u > 1.0f - edgeU || v < edgeV || v > 1.0f - edgeV)
                    continue;
                ++checked;
                ASSERT_NEAR(out.at(x, y), ramp(u, v), tolerance)
                    << "texel (" << x << ", " << y << ") of " << r.fromW << "×" << r.fromH << " -> "
                    << r.toW << "×" << r.toH;
            }
        }
        EXPECT_GT(checked, r.toW * r.toH / 2) << r.toW << "×" << r.toH;
    }
}

// A checkerboard of cell × cell texels shifted by `offset` texels.
MapImage checkerboard(int size, int cell, int offset) {
    MapImage board = makeConstantMap(size, size, 0.0f);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            board.texels[static_cast<std::size_t>(y * size + x)] =
                static_cast<float>(((x + offset) / cell + (y + offset) / cell) % 2);
    return board;
}

// Fine checkerboards are the worst case for aliasing: sampling reads a few texels and gets
// black or white; averaging each new texel's footprint gives the mean.
TEST(MapImageResample, ShrinkingACheckerboardGivesItsMean) {
    // 8×: each 8×8 footprint is half white for both boards, and 1/8 weights are exact. The
    // second board is the trap for a bilinear shortcut: at 8× it would read texels 8i + 3 and
    // 8i + 4, which there lie in the same cell, and return 0 or 1.
    for (const auto& [cell, offset] : {std::pair{1, 0}, std::pair{2, 1}}) {
        const MapImage eighth = resampleMap(checkerboard(64, cell, offset), 8, 8);
        for (const float t : eighth.texels)
            ASSERT_EQ(t, 0.5f) << "cell " << cell << " offset " << offset;
    }

    // 64 -> 9 and 7 (7.1× and 9.1×): a footprint of s texels holds at most one unpaired
    // partial texel per row, so each row's mean is within 0.5 / s of 0.5; averaging rows keeps
    // that bound.
    const MapImage odd = resampleMap(checkerboard(64, 1, 0), 9, 7);
    const float tolerance = 0.5f / (64.0f / 9.0f);
    for (const float t : odd.texels)
        ASSERT_NEAR(t, 0.5f, tolerance);
}

TEST(MapImageResample, LoadAtWarnsOnlyWhenItResamples) {
    const ScratchFolder dir("load_at");
    const fs::path file = dir / "map.png";
    ASSERT_TRUE(saveMapImage(randomMap(30, 20, 11), file).ok());
    const Result<MapImage> plain = loadMapImage(file);
    ASSERT_TRUE(plain.ok()) << plain.error().str();

    const Result<MapImage> same = loadMapImageAt(file, 30, 20);
    ASSERT_TRUE(same.ok()) << same.error().str();
    EXPECT_TRUE(same->warnings.empty());
    EXPECT_EQ(same->texels, plain->texels);

    const Result<MapImage> bigger = loadMapImageAt(file, 64, 48);
    ASSERT_TRUE(bigger.ok()) << bigger.error().str();
    EXPECT_EQ(bigger->width, 64);
    EXPECT_EQ(bigger->height, 48);
    EXPECT_EQ(bigger->texels, resampleMap(*plain, 64, 48).texels);
    ASSERT_EQ(bigger->warnings.size(), 1u);
    EXPECT_NE(bigger->warnings[0].find("map.png"), std::string::npos) << bigger->warnings[0];
    EXPECT_NE(bigger->warnings[0].find("resampled from 30×20 to 64×48"), std::string::npos)
        << bigger->warnings[0];

    expectOneLineErrorNaming(loadMapImageAt(dir / "nowhere.png", 8, 8), "nowhere.png",
                             "missing file at a size");
}

}  // namespace
}  // namespace grass::core
