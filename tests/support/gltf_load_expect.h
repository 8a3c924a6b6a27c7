// core::loadGltf in tests that expect it to succeed or to fail, for the glTF loader's tests.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>

#include "mesh/gltf_loader.h"

namespace grass::test {

// The import, or an empty one after a test failure naming the error.
inline core::GltfImport loadGltfExpectingSuccess(const std::filesystem::path& file) {
    auto result = core::loadGltf(file);
    EXPECT_TRUE(result.ok()) << result.error().str();
    return result.ok() ? std::move(result).value() : core::GltfImport{};
}

// The error's text, which must name the file and fit on one line (as every load error does);
// empty, after a test failure, when the file loaded.
inline std::string loadGltfError(const std::filesystem::path& file) {
    const auto result = core::loadGltf(file);
    EXPECT_FALSE(result.ok()) << file << " loaded, but should not have";
    if (result.ok())
        return {};
    const std::string message = result.error().str();
    EXPECT_NE(message.find(file.filename().string()), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
}

}  // namespace grass::test
