#include "util/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace grass {

namespace fs = std::filesystem;

fs::path temporaryPathFor(const fs::path& target) {
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    return dir / ("." + target.stem().string() + ".tmp-" + std::to_string(::getpid()) +
                  target.extension().string());
}

// The pid of a temporaryPathFor name, or 0 when the name is not one.
static pid_t temporaryOwner(const std::string& name) {
    if (name.empty() || name[0] != '.')
        return 0;
    const std::size_t tag = name.rfind(".tmp-");
    if (tag == std::string::npos || tag == 0)
        return 0;
    std::size_t end = tag + 5;
    long long pid = 0;
    while (end < name.size() && name[end] >= '0' && name[end] <= '9' && pid < (1LL << 31)) {
        pid = pid * 10 + (name[end] - '0');
        ++end;
    }
    // Digits, then the end of the name or the target's extension.
    if (end == tag + 5 || (end < name.size() && name[end] != '.'))
        return 0;
    return static_cast<pid_t>(pid);
}

std::size_t removeStaleTemporaries(const fs::path& folder) {
    std::error_code ec;
    std::size_t removed = 0;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        if (!it->is_regular_file(ec))
            continue;
        const pid_t owner = temporaryOwner(it->path().filename().string());
        // Alive (or not ours to ask about): its save may be under way.
        if (owner <= 0 || owner == ::getpid() || ::kill(owner, 0) == 0 || errno != ESRCH)
            continue;
        std::error_code removeError;
        if (fs::remove(it->path(), removeError))
            ++removed;
    }
    return removed;
}

static Result<void> syncFile(const fs::path& file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return makeError(file.string(), std::string("cannot reopen: ") + std::strerror(errno));
    const int rc = ::fsync(fd);
    ::close(fd);
    if (rc != 0)
        return makeError(file.string(), std::string("fsync failed: ") + std::strerror(errno));
    return {};
}

// Fault injection for tests/cli/kill_save_test.sh: GRASS_TEST_SAVE_DELAY_MS holds every finished
// temporary that long before it replaces its target, so that a kill can land mid-save.
static void testSaveDelay() {
    const char* text = std::getenv("GRASS_TEST_SAVE_DELAY_MS");
    if (text == nullptr)
        return;
    const long ms = std::strtol(text, nullptr, 10);
    if (ms > 0 && ms <= 10000)
        ::usleep(static_cast<useconds_t>(ms) * 1000u);
}

Result<void> commitTemporaryFile(const fs::path& temporary, const fs::path& target) {
    std::error_code ec;
    if (auto synced = syncFile(temporary); !synced) {
        fs::remove(temporary, ec);
        return synced;
    }
    testSaveDelay();
    fs::rename(temporary, target, ec);
    if (ec) {
        fs::remove(temporary, ec);
        return makeError(target.string(), "cannot replace the file: " + ec.message());
    }
    return {};
}

Result<void> writeFileAtomic(const fs::path& target, std::string_view bytes) {
    const fs::path temporary = temporaryPathFor(target);
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out)
            return makeError(target.string(), "cannot write: " + std::string(std::strerror(errno)));
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.flush();
        if (!out) {
            std::error_code ec;
            fs::remove(temporary, ec);
            return makeError(target.string(), "write failed (disk full?)");
        }
    }
    return commitTemporaryFile(temporary, target);
}

Result<void> checkFileWritable(const std::filesystem::path& target, std::string_view example) {
    std::error_code ec;
    if (std::filesystem::is_directory(target, ec))
        return makeError(target.string(),
                         "is a folder: give a file name such as " + std::string(example));
    if (target.has_parent_path() && !std::filesystem::is_directory(target.parent_path(), ec))
        return makeError(target.string(),
                         "the folder " + target.parent_path().string() + " does not exist");
    return {};
}

Result<std::string> readFile(const fs::path& file) {
    std::error_code ec;
    if (!fs::exists(file, ec))
        return makeError(file.string(), "file not found");
    if (fs::is_directory(file, ec))
        return makeError(file.string(), "is a folder, not a file");
    std::ifstream in(file, std::ios::binary);
    if (!in)
        return makeError(file.string(), std::string("cannot open: ") + std::strerror(errno));
    std::ostringstream contents;
    contents << in.rdbuf();
    if (in.bad())
        return makeError(file.string(), "read failed");
    return contents.str();
}

}  // namespace grass
