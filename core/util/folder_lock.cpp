#include "util/folder_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace grass {

Result<FolderLock> FolderLock::acquire(const std::filesystem::path& folder, std::string_view what) {
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0)
        return makeError(folder.string(),
                         std::string("cannot open the folder: ") + std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
        const int error = errno;
        ::close(fd);
        if (error == EWOULDBLOCK)
            return makeError(folder.string(),
                             "another " + std::string(what) +
                                 " is writing into this folder right now; wait for it to "
                                 "finish, or choose another folder");
        return makeError(folder.string(),
                         std::string("cannot lock the folder: ") + std::strerror(error));
    }
    return FolderLock(fd);
}

FolderLock::~FolderLock() {
    if (mFd >= 0)
        ::close(mFd);  // releases the lock
}

}  // namespace grass
