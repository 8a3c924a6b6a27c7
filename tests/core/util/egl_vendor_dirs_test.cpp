#include "util/egl_vendor_dirs.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace grass::core {
namespace {

bool onlyNvidia(const std::string& folder) {
    return folder == "/usr/local/nvidia/share/glvnd/egl_vendor.d";
}

TEST(EglVendorDirs, ADriverFolderIsSearchedBeforeGlvndsOwn) {
    EXPECT_EQ(eglVendorDirsValue(nullptr, nullptr, onlyNvidia),
              "/usr/local/nvidia/share/glvnd/egl_vendor.d:/etc/glvnd/egl_vendor.d:"
              "/usr/share/glvnd/egl_vendor.d");
}

TEST(EglVendorDirs, TheUsersChoiceStands) {
    EXPECT_EQ(eglVendorDirsValue("/x/10_nvidia.json", nullptr, onlyNvidia), std::nullopt);
    EXPECT_EQ(eglVendorDirsValue(nullptr, "/x", onlyNvidia), std::nullopt);
    // An empty variable is no choice.
    EXPECT_TRUE(eglVendorDirsValue("", "", onlyNvidia).has_value());
}

TEST(EglVendorDirs, NoDriverFolderLeavesGlvndAlone) {
    EXPECT_EQ(eglVendorDirsValue(nullptr, nullptr, [](const std::string&) { return false; }),
              std::nullopt);
}

TEST(EglVendorDirs, EveryDriverFolderWithAFileIsKept) {
    const auto value =
        eglVendorDirsValue(nullptr, nullptr, [](const std::string&) { return true; });
    ASSERT_TRUE(value.has_value());
    for (const char* folder : kDriverEglVendorDirs)
        EXPECT_NE(value->find(folder), std::string::npos) << folder;
    EXPECT_EQ(value->back(), 'd');  // no trailing separator
}

TEST(EglVendorDirs, AFolderHoldsAVendorFileOnlyWithJson) {
    const auto folder = std::filesystem::temp_directory_path() / "grass_egl_vendor_dirs_test";
    std::filesystem::remove_all(folder);
    EXPECT_FALSE(folderHoldsJsonFile(folder.string()));  // missing
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "README") << "not a vendor file";
    EXPECT_FALSE(folderHoldsJsonFile(folder.string()));
    std::ofstream(folder / "10_nvidia.json") << "{}";
    EXPECT_TRUE(folderHoldsJsonFile(folder.string()));
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace grass::core
