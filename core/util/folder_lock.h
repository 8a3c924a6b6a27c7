// An advisory lock on a folder (flock on the folder itself, so no lock file is left behind):
// two exports into one folder would each rename their files over the other's and remove what
// the other still names. The second one now fails at once with a message that says why.
#pragma once

#include <filesystem>
#include <string_view>

#include "util/result.h"

namespace grass {

class FolderLock {
public:
    // Takes the lock or fails without waiting; `what` says who holds it in the message
    // ("another grass export is writing into DIR").
    static Result<FolderLock> acquire(const std::filesystem::path& folder, std::string_view what);
    FolderLock(FolderLock&& other) noexcept : mFd(other.mFd) { other.mFd = -1; }
    FolderLock& operator=(FolderLock&&) = delete;
    FolderLock(const FolderLock&) = delete;
    ~FolderLock();

private:
    explicit FolderLock(int fd) : mFd(fd) {}
    int mFd = -1;
};

}  // namespace grass
