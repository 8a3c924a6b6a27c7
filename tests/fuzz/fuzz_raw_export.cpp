// Fuzz target: a raw export read back (readRawBlades, readRawPatches), the input as both a
// <layer>.blades.bin and a <layer>.patches.bin.
#include "export/raw_export.h"
#include "fuzz_scratch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace grass;
    const std::filesystem::path blades = fuzz::scratchDir() / "grass.blades.bin";
    const std::filesystem::path patches = fuzz::scratchDir() / "grass.patches.bin";
    fuzz::writeBytes(blades, {data, size});
    fuzz::writeBytes(patches, {data, size});
    if (const auto read = core::readRawBlades(blades); !read)
        fuzz::checkError(read.error());
    else if (read->size() * core::RAW_BLADE_STRIDE != size)
        fuzz::fail("readRawBlades did not read every record");
    if (const auto read = core::readRawPatches(patches); !read)
        fuzz::checkError(read.error());
    else if (read->size() * core::RAW_PATCH_STRIDE != size)
        fuzz::fail("readRawPatches did not read every record");
    fuzz::clearScratch();
    return 0;
}
