#include "fuzz_scratch.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>

namespace grass::fuzz {

namespace fs = std::filesystem;

namespace {

// Owns the scratch folder; its destructor runs at exit (libFuzzer ends with exit()).
class ScratchFolder {
public:
    ScratchFolder() {
        const char* tmp = std::getenv("TMPDIR");
        const fs::path base = tmp != nullptr && *tmp != '\0' ? fs::path(tmp) : fs::path("/tmp");
        mPath = base / ("grass-fuzz-" + std::to_string(::getpid()));
        std::error_code ec;
        fs::remove_all(mPath, ec);
        fs::create_directories(mPath, ec);
        if (ec)
            fail("cannot create the scratch folder " + mPath.string() + ": " + ec.message());
    }
    ~ScratchFolder() {
        std::error_code ec;
        fs::remove_all(mPath, ec);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    const fs::path& path() const { return mPath; }

private:
    fs::path mPath;
};

}  // namespace

const fs::path& scratchDir() {
    static const ScratchFolder folder;
    return folder.path();
}

void writeBytes(const fs::path& file, std::span<const std::uint8_t> bytes) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out)
        fail("cannot write " + file.string());
}

void clearScratch() {
    std::error_code ec;
    for (fs::directory_iterator it(scratchDir(), ec), end; !ec && it != end; it.increment(ec)) {
        std::error_code removeError;
        fs::remove_all(it->path(), removeError);
    }
}

void fail(std::string_view what) {
    std::fprintf(stderr, "grass fuzz check failed: %.*s\n", static_cast<int>(what.size()),
                 what.data());
    std::abort();
}

void checkError(const Error& error) {
    if (error.path.empty())
        fail("the error names no file: " + error.message);
    if (error.message.empty())
        fail("the error of " + error.path + " says nothing");
    if (error.str().find('\n') != std::string::npos)
        fail("the error is not one line: " + error.str());
}

}  // namespace grass::fuzz
