#include "util/atomic_file.h"

#include <atomic>

#include "util/process_alive.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <stdio.h>  // renameat2

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "util/byte_size.h"

namespace grass {

namespace fs = std::filesystem;

fs::path temporaryPathFor(const fs::path& target) {
    // Numbered within the process: two threads writing one target (the editor's worker growing
    // a project while a cancelled one still packs the same collider cache) must not write into
    // one temporary.
    static std::atomic<std::uint64_t> written{0};
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    return dir / ("." + target.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                  std::to_string(written.fetch_add(1) + 1) + target.extension().string());
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
    if (end == tag + 5)
        return 0;
    // The number within the process ("-12"; names before it had none).
    if (end + 1 < name.size() && name[end] == '-' && name[end + 1] >= '0' && name[end + 1] <= '9')
        for (++end; end < name.size() && name[end] >= '0' && name[end] <= '9';)
            ++end;
    // Then the end of the name or the target's extension.
    if (end < name.size() && name[end] != '.')
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
        if (owner <= 0 || owner == ::getpid() || processRunsElsewhere(owner))
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

Result<void> commitTemporaryFile(const fs::path& temporary, const fs::path& target,
                                 std::uint64_t minimumBytes) {
    std::error_code ec;
    const auto refuse = [&](Result<void> failed) {
        fs::remove(temporary, ec);
        return failed;
    };
    if (auto synced = syncFile(temporary); !synced)
        return refuse(synced);
    const std::uintmax_t size = fs::file_size(temporary, ec);
    if (ec || size < minimumBytes)
        return refuse(
            makeError(target.string(), "write failed: only " + std::to_string(ec ? 0 : size) +
                                           " bytes reached the disk (disk full?); the file was "
                                           "left as it was"));
    testSaveDelay();
    fs::rename(temporary, target, ec);
    if (ec)
        return refuse(makeError(target.string(), "cannot replace the file: " + ec.message()));
    return {};
}

Result<bool> copyFileAtomic(const fs::path& source, const fs::path& target) {
    std::error_code ec;
    if (fs::exists(target, ec))
        return false;
    const fs::path temporary = temporaryPathFor(target);
    const auto refuse = [&](const std::string& reason) -> Result<bool> {
        fs::remove(temporary, ec);
        return makeError(target.string(), "cannot copy " + source.string() + " (" + reason + ")");
    };
    if (!fs::copy_file(source, temporary, ec))
        return refuse(ec.message());
    if (auto synced = syncFile(temporary); !synced)
        return refuse(synced.error().message);
    if (fs::file_size(temporary, ec) != fs::file_size(source, ec) || ec)
        return refuse("the copy came out short (disk full?)");
    // Renamed only where no file is: a copy that another finished first must not be replaced
    // under the reader that chose it.
    if (::renameat2(AT_FDCWD, temporary.c_str(), AT_FDCWD, target.c_str(), RENAME_NOREPLACE) == 0)
        return true;
    if (errno == EEXIST) {
        fs::remove(temporary, ec);
        return false;
    }
    // A file system without the flag (some network ones): look, then rename.
    if (errno == EINVAL || errno == ENOSYS) {
        if (fs::exists(target, ec)) {
            fs::remove(temporary, ec);
            return false;
        }
        fs::rename(temporary, target, ec);
        if (!ec)
            return true;
        return refuse(ec.message());
    }
    return refuse(std::strerror(errno));
}

Result<void> writeFileAtomic(const fs::path& target, std::string_view bytes) {
    const fs::path temporary = temporaryPathFor(target);
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0)
        return makeError(target.string(), "cannot write: " + std::string(std::strerror(errno)));
    std::size_t done = 0;
    int writeError = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            writeError = n < 0 ? errno : ENOSPC;
            break;
        }
        done += static_cast<std::size_t>(n);
    }
    // close() reports what a network or quota file system deferred.
    if (::close(fd) != 0 && writeError == 0)
        writeError = errno;
    if (writeError != 0) {
        std::error_code ec;
        fs::remove(temporary, ec);
        return makeError(target.string(),
                         "write failed: " + std::string(std::strerror(writeError)) +
                             "; the file was left as it was");
    }
    return commitTemporaryFile(temporary, target, bytes.size());
}

Result<void> checkFileWritable(const std::filesystem::path& target, std::string_view example) {
    std::error_code ec;
    if (std::filesystem::is_directory(target, ec))
        return makeError(target.string(),
                         "is a folder: give a file name such as " + std::string(example));
    if (target.has_parent_path() && !std::filesystem::is_directory(target.parent_path(), ec))
        return makeError(target.string(),
                         "the folder " + target.parent_path().string() + " does not exist");
    // Write access is only known by trying: the temporary the save will use, made and removed
    // (a read-only or full file system, a folder of someone else's, /proc).
    const fs::path probe = temporaryPathFor(target);
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0)
        return makeError(target.string(),
                         "cannot write here: " + std::string(std::strerror(errno)));
    ::close(fd);
    fs::remove(probe, ec);
    return {};
}

// What a path is when it is not a regular file, for the message.
static std::string kindOf(mode_t mode) {
    if (S_ISDIR(mode))
        return "is a folder, not a file";
    if (S_ISFIFO(mode))
        return "is a FIFO (named pipe), not a regular file; reading it could wait for ever";
    if (S_ISCHR(mode) || S_ISBLK(mode))
        return "is a device, not a regular file";
    if (S_ISSOCK(mode))
        return "is a socket, not a regular file";
    return "is not a regular file";
}

Result<void> checkRegularFile(const fs::path& file) {
    struct stat info {};
    if (::stat(file.c_str(), &info) != 0)
        return makeError(file.string(), errno == ENOENT
                                            ? std::string("file not found")
                                            : std::string("cannot open: ") + std::strerror(errno));
    if (!S_ISREG(info.st_mode))
        return makeError(file.string(), kindOf(info.st_mode));
    return {};
}

Result<std::string> readFile(const fs::path& file, std::uint64_t maxBytes) {
    // Non-blocking, so that a FIFO put in a file's place cannot hang the open itself.
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0)
        return makeError(file.string(), errno == ENOENT
                                            ? std::string("file not found")
                                            : std::string("cannot open: ") + std::strerror(errno));
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        ::close(fd);
        return makeError(file.string(), kindOf(info.st_mode));
    }
    const auto size = static_cast<std::uint64_t>(info.st_size);
    if (size > maxBytes) {
        ::close(fd);
        return makeError(file.string(), "is " + byteSizeText(static_cast<double>(size)) +
                                            ", more than the " +
                                            byteSizeText(static_cast<double>(maxBytes)) +
                                            " this reader accepts; is it the right file?");
    }
    std::string contents(static_cast<std::size_t>(size), '\0');
    std::size_t done = 0;
    while (done < contents.size()) {
        const ssize_t n = ::read(fd, contents.data() + done, contents.size() - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            const int error = errno;
            ::close(fd);
            return makeError(file.string(), std::string("read failed: ") + std::strerror(error));
        }
        if (n == 0)
            break;  // shrank while we read: what is there is the file
        done += static_cast<std::size_t>(n);
    }
    ::close(fd);
    contents.resize(done);
    return contents;
}

}  // namespace grass
