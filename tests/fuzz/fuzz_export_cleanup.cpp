// Fuzz target: the clean-up an export runs on its output folder (removeUnreferencedExportFiles),
// which reads every .gltf and manifest.json already there: files the user (or anyone) put
// there, not ours. The input is written as a .gltf and as manifest.json beside two
// content-addressed files, one of which the input may name. Whatever the bytes, the clean-up
// must not crash or hang (a 50,000-level nest overflowed its recursive walk), must remove
// nothing when an entry point cannot be read, and never a file an entry point names.
#include <string>

#include "export/content_names.h"
#include "fuzz_scratch.h"
#include "util/json_text.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace grass;
    const std::filesystem::path folder = fuzz::scratchDir();
    const std::string text(reinterpret_cast<const char*>(data), size);
    fuzz::writeBytes(folder / "layer.gltf", {data, size});
    fuzz::writeBytes(folder / "manifest.json", {data, size});
    const std::string named = "grass-0123456789abcdef.bin";
    const std::uint8_t byte = 0;
    fuzz::writeBytes(folder / named, {&byte, 1});
    fuzz::writeBytes(folder / "grass-fedcba9876543210.bin", {&byte, 1});
    core::removeUnreferencedExportFiles(folder);
    // Not JSON (or nested too deep to walk): nothing may go. A "uri" naming the file: it stays.
    // (The JSON parser stops at a NUL byte, as at the end of the text: what follows is not
    // part of the document.)
    const bool kept = std::filesystem::exists(folder / named);
    const std::string document = text.substr(0, text.find('\0'));
    if (!parseJsonText(text, "input") && !kept)
        fuzz::fail("the clean-up removed a file though an entry point could not be read");
    if (document.find("\"uri\":\"" + named + "\"") != std::string::npos && !kept)
        fuzz::fail("the clean-up removed a file that the entry point names");
    fuzz::clearScratch();
    return 0;
}
