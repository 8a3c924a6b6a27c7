// Accessors appended to a test glTF document (support/gltf_writer.h) for what the writer does not
// model: skins (JOINTS_0, WEIGHTS_0, inverseBindMatrices) and morph targets. Shared by
// gltf_skin_pose_test.cpp and gltf_morph_test.cpp.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "support/gltf_writer.h"
#include "support/test_paths.h"

namespace grass::test {

inline constexpr int UNSIGNED_BYTE = 5121;
inline constexpr int UNSIGNED_SHORT = 5123;
inline constexpr int FLOAT = 5126;

// Appends `values` to the document's buffer as a new bufferView; returns its index.
template <class T>
int addBufferView(GltfDocument& doc, const std::vector<T>& values) {
    while (doc.bin.size() % 4 != 0)
        doc.bin.push_back(0);
    const std::size_t offset = doc.bin.size();
    const std::size_t size = values.size() * sizeof(T);
    doc.bin.resize(offset + size);
    std::memcpy(doc.bin.data() + offset, values.data(), size);
    doc.json["buffers"][0]["byteLength"] = doc.bin.size();
    doc.json["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}});
    return static_cast<int>(doc.json["bufferViews"].size() - 1);
}

// Appends `values` as a new bufferView and an accessor over it of `count` elements of `type`
// ("VEC3", "MAT4", ...); returns the accessor's index.
template <class T>
int addAccessor(GltfDocument& doc, const std::vector<T>& values, int componentType,
                const char* type, std::size_t count, bool normalized = false) {
    nlohmann::json accessor = {{"bufferView", addBufferView(doc, values)},
                               {"componentType", componentType},
                               {"count", count},
                               {"type", type}};
    if (normalized)
        accessor["normalized"] = true;
    doc.json["accessors"].push_back(accessor);
    return static_cast<int>(doc.json["accessors"].size() - 1);
}

// A float VEC3 accessor, one element per value.
inline int addVec3Accessor(GltfDocument& doc, const std::vector<glm::vec3>& values) {
    return addAccessor(doc, values, FLOAT, "VEC3", values.size());
}

// `doc` written as <scratch folder>/<name>.gltf, its buffer inline (a data: URI).
// The folder is the test's own (named after the running test and `name`): ctest runs the tests
// of one suite in parallel processes, and a folder shared by the suite was emptied under a
// neighbour's feet.
inline std::filesystem::path writeDataUriGltf(const GltfDocument& doc, const std::string& folder,
                                              const std::string& name) {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const std::filesystem::path file =
        scratchDir(folder + "/" + test + "/" + name) / (name + ".gltf");
    writeGltf(file, doc, BufferStorage::DataUri);
    return file;
}

}  // namespace grass::test
