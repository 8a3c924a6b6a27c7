// Where glvnd's libEGL looks for EGL vendor files (the JSON that names a driver's EGL library).
// glvnd searches /etc/glvnd and /usr/share/glvnd only, so a GPU driver mounted elsewhere (NVIDIA's
// container toolkit puts its files under /usr/local/nvidia) stays invisible and a headless
// context finds no device. The headless context adds such folders before EGL loads. GL-free.
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace grass::core {

// glvnd's own search folders, which setting __EGL_VENDOR_LIBRARY_DIRS replaces (so they are kept).
inline constexpr const char* kGlvndEglVendorDirs[] = {"/etc/glvnd/egl_vendor.d",
                                                      "/usr/share/glvnd/egl_vendor.d"};
// Where drivers installed outside /usr put their vendor files.
inline constexpr const char* kDriverEglVendorDirs[] = {
    "/usr/local/nvidia/share/glvnd/egl_vendor.d", "/usr/local/share/glvnd/egl_vendor.d",
    "/run/opengl-driver/share/glvnd/egl_vendor.d"};

// The value for __EGL_VENDOR_LIBRARY_DIRS: the driver folders that hold a vendor file, then
// glvnd's own. Nothing when the user set __EGL_VENDOR_LIBRARY_FILENAMES or _DIRS (their choice
// stands) or when no driver folder holds one (glvnd's defaults already cover the system).
std::optional<std::string> eglVendorDirsValue(
    const char* filenamesEnv, const char* dirsEnv,
    const std::function<bool(const std::string& folder)>& holdsVendorFile);

// True when the folder exists and holds at least one *.json file.
bool folderHoldsJsonFile(const std::string& folder);

}  // namespace grass::core
