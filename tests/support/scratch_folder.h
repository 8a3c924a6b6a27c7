// A fresh folder under the system temp folder for one test, removed when it goes out of scope.
// The process id in its name keeps two build trees running the same tests at once from
// sharing (and deleting) each other's files.
#pragma once

#include <filesystem>
#include <string>
#include <system_error>

#include <unistd.h>

namespace grass::test {

class ScratchFolder {
public:
    explicit ScratchFolder(const std::string& name)
        : mPath(std::filesystem::temp_directory_path() /
                ("grass-" + name + "-" + std::to_string(static_cast<long>(getpid())))) {
        std::filesystem::remove_all(mPath);
        std::filesystem::create_directories(mPath);
    }
    ~ScratchFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(mPath, ignored);
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;

    const std::filesystem::path& path() const { return mPath; }
    std::filesystem::path operator/(const std::string& file) const { return mPath / file; }

private:
    std::filesystem::path mPath;
};

}  // namespace grass::test
