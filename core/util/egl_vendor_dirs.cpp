#include "util/egl_vendor_dirs.h"

#include <filesystem>
#include <system_error>

namespace grass::core {

std::optional<std::string> eglVendorDirsValue(
    const char* filenamesEnv, const char* dirsEnv,
    const std::function<bool(const std::string& folder)>& holdsVendorFile) {
    if ((filenamesEnv && *filenamesEnv) || (dirsEnv && *dirsEnv))
        return std::nullopt;
    std::string value;
    for (const char* folder : kDriverEglVendorDirs)
        if (holdsVendorFile(folder))
            value += std::string(folder) + ":";
    if (value.empty())
        return std::nullopt;
    for (const char* folder : kGlvndEglVendorDirs)
        value += std::string(folder) + ":";
    value.pop_back();
    return value;
}

bool folderHoldsJsonFile(const std::string& folder) {
    std::error_code error;
    for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end;
         it.increment(error))
        if (it->path().extension() == ".json")
            return true;
    return false;
}

}  // namespace grass::core
