#include "util/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
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

Result<void> commitTemporaryFile(const fs::path& temporary, const fs::path& target) {
    std::error_code ec;
    if (auto synced = syncFile(temporary); !synced) {
        fs::remove(temporary, ec);
        return synced;
    }
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
