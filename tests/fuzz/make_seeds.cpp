// Writes the generated seeds of tests/fuzz/corpus/ with the application's own writers: maps in
// every sample format each extension takes (saveMapImage) and as RGBA (writeRgba8Image), a
// billboard texture, a project with every field, the packing-cache target's cache
// (loadOrPackSpheres on its fixture) and raw blade and patch records. make_seeds.sh adds the
// seeds that are files of the repository.
//   build-fuzz/bin/fuzz_make_seeds tests/fuzz/corpus
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "collider/packing_cache.h"
#include "export/raw_export.h"
#include "fuzz_scratch.h"
#include "maps/map_image.h"
#include "packing_fixture.h"
#include "project/project.h"
#include "util/image_file.h"

namespace {

namespace fs = std::filesystem;
using namespace grass;

// Small: a seed should cost the fuzzer little, yet have more than one row and column.
constexpr int WIDTH = 8;
constexpr int HEIGHT = 6;

void check(const Result<void>& written) {
    if (!written)
        fuzz::fail(written.error().str());
}

void writeText(const fs::path& file, const std::string& bytes) {
    fuzz::writeBytes(file, {reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
}

core::MapImage gradientMap() {
    core::MapImage map = core::makeConstantMap(WIDTH, HEIGHT, 0.0f);
    for (int y = 0; y < HEIGHT; ++y)
        for (int x = 0; x < WIDTH; ++x)
            map.texels[static_cast<std::size_t>(y * WIDTH + x)] =
                static_cast<float>(x + y) / static_cast<float>(WIDTH + HEIGHT - 2);
    return map;
}

// Half the texels transparent, so that loadGrassTexture accepts it.
std::vector<std::uint8_t> rgbaPixels() {
    std::vector<std::uint8_t> pixels;
    for (int y = 0; y < HEIGHT; ++y)
        for (int x = 0; x < WIDTH; ++x)
            for (const int value : {40 * x, 30 * y, 100, (x + y) % 2 == 0 ? 255 : 0})
                pixels.push_back(static_cast<std::uint8_t>(value));
    return pixels;
}

void writeMaps(const fs::path& corpus) {
    using Format = core::MapSampleFormat;
    struct Seed {
        const char* target;
        const char* name;
        Format format;
    };
    const Seed seeds[] = {
        {"map_png", "grey8.png", Format::UInt8},     {"map_png", "grey16.png", Format::UInt16},
        {"map_tiff", "grey8.tif", Format::UInt8},    {"map_tiff", "grey16.tif", Format::UInt16},
        {"map_tiff", "float.tif", Format::Float},    {"map_exr", "half.exr", Format::Half},
        {"map_exr", "float.exr", Format::Float},
    };
    const core::MapImage map = gradientMap();
    for (const Seed& seed : seeds) {
        fs::create_directories(corpus / seed.target);
        check(core::saveMapImage(map, corpus / seed.target / seed.name, seed.format));
    }
    const auto pixels = rgbaPixels();
    for (const auto& [target, name] : {std::pair{"map_png", "rgba8.png"},
                                       {"map_tiff", "rgba8.tif"}, {"map_exr", "rgba.exr"},
                                       {"map_tga", "rgba8.tga"},
                                       {"grass_texture", "rgba8.png"}}) {
        fs::create_directories(corpus / target);
        check(writeRgba8Image(corpus / target / name, WIDTH, HEIGHT, pixels));
    }
    // Colour-mapped TGAs (decoded by grass, util/tga_palette.h), 4×3 with four entries: raw
    // (type 1) with 24-bit entries, bottom-left; run-length (type 9) with 16-bit entries and an
    // alpha bit, top-left, a run crossing a row.
    const auto tga = [](char type, char entryBits, char descriptor, const std::string& rest) {
        std::string bytes = {'\0', '\1', type, '\0', '\0', '\4', '\0', entryBits, '\0', '\0',
                             '\0', '\0', '\4', '\0', '\3', '\0', '\x08', descriptor};
        return bytes + rest;
    };
    writeText(corpus / "map_tga" / "palette_raw.tga",
              tga('\1', '\x18', '\0',
                  std::string("\0\0\xff\0\xff\0\xff\0\0\x80\x80\x80"
                              "\0\1\2\3\3\2\1\0\1\1\2\2",
                              24)));
    writeText(corpus / "map_tga" / "palette_rle.tga",
              tga('\x09', '\x10', '\x21',
                  std::string("\x00\xfc\xe0\x83\x1f\x00\x10\xc2\x83\0\x01\1\2\x85\3", 15)));
}

void writePackingCache(const fs::path& corpus) {
    const fs::path meshFile = fuzz::scratchDir() / "rock.glb";
    writeText(meshFile, std::string(fuzz::PACKING_MESH_BYTES));
    const auto params = fuzz::packingParams();
    const fs::path cache = core::packingCachePath(fuzz::scratchDir(), meshFile, params);
    const auto packing = core::loadOrPackSpheres(meshFile, fuzz::packingMesh(), params, cache);
    if (!packing)
        fuzz::fail(packing.error().str());
    fs::create_directories(corpus / "packing_cache");
    fs::copy_file(cache, corpus / "packing_cache" / "sphere.spheres.json",
                  fs::copy_options::overwrite_existing);
}

void writeRawRecords(const fs::path& corpus) {
    std::vector<core::Blade> blades(3);
    for (std::size_t i = 0; i < blades.size(); ++i) {
        const float x = static_cast<float>(i);
        blades[i].v0Theta = {x, 0.0f, 0.5f, 0.3f};
        blades[i].v1H = {x, 0.4f, 0.5f, 0.5f};
        blades[i].v2W = {x + 0.1f, 0.5f, 0.5f, 0.02f};
    }
    std::vector<core::Patch> patches(2);
    patches[1].firstBlade = 2;
    patches[0].bladeCount = 2;
    patches[1].bladeCount = 1;
    patches[0].bounds = {{0.0f, 0.0f, 0.0f}, {1.0f, 0.5f, 1.0f}};
    patches[1].bounds = {{2.0f, 0.0f, 0.0f}, {2.5f, 0.5f, 1.0f}};
    fs::create_directories(corpus / "raw_export");
    writeText(corpus / "raw_export" / "three.blades.bin", core::rawBladeBytes(blades));
    writeText(corpus / "raw_export" / "two.patches.bin", core::rawPatchBytes(patches));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: fuzz_make_seeds <tests/fuzz/corpus>\n");
        return 2;
    }
    const fs::path corpus = argv[1];
    writeMaps(corpus);
    writePackingCache(corpus);
    writeRawRecords(corpus);
    // Every field of the format, each at its default.
    fs::create_directories(corpus / "project");
    writeText(corpus / "project" / "defaults.json", core::serializeProject(core::Project{}));
    fuzz::clearScratch();
    return 0;
}
