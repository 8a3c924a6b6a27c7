// Saved projects keep opening (issue 23 item 9): a version 1 file reads as the same project in
// the current version and saves as the current version; the limits of version 2 refuse a version
// 1 file that passes them as they refuse a version 2 file; a version this build does not know is
// refused naming the ones it reads. (ProjectFiles checks every committed project opens.)
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "project/project.h"

namespace grass::core {
namespace {

std::string document(int version, const std::string& body) {
    return R"({"format": "grass-project", "version": )" + std::to_string(version) + body + "}";
}

TEST(ProjectMigration, AVersion1FileReadsAsTheSameProjectAndSavesAsTheCurrentVersion) {
    // Layers with the height-vs-light curve stated: version 3 changed its default (below).
    const std::string body =
        R"(, "name": "old", "physics": {"step_s": 0.02}, "layers": [{"name": "a", "growth":
           {"height_light_curve": [0.1, 0.25, 0.4, 0.75, 0.8]}}])";
    const auto old = parseProject(document(1, body), "old.json");
    ASSERT_TRUE(old) << old.error().message;
    const auto current = parseProject(document(PROJECT_FORMAT_VERSION, body), "new.json");
    ASSERT_TRUE(current) << current.error().message;
    EXPECT_EQ(*old, *current);
    EXPECT_NE(serializeProject(*old).find("\"version\": " + std::to_string(PROJECT_FORMAT_VERSION)),
              std::string::npos);
}

// Version 3 turned the default height-vs-light curve over (issue 30 item 5): a layer of an older
// file without the curve keeps the rising one it meant, a layer that states one keeps its own,
// and a current file without it gets the new default.
TEST(ProjectMigration, AnOlderLayerWithoutAHeightCurveKeepsTheRisingOne) {
    const GrowthCurves rising{.hy0 = 0.1f, .hy1 = 0.25f, .hy2 = 0.4f, .hy3 = 0.75f, .hy4 = 0.8f};
    const std::string body =
        R"(, "layers": [{"name": "a"}, {"name": "b", "growth": {"enabled": true}},
                        {"name": "c", "growth": {"height_light_curve": [0.3, 0.3, 0.3, 0.3, 0.3]}}])";
    for (const int version : {1, 2}) {
        const auto old = parseProject(document(version, body), "old.json");
        ASSERT_TRUE(old) << old.error().message;
        const auto heights = [](const GrowthCurves& c) {
            return std::vector<float>{c.hy0, c.hy1, c.hy2, c.hy3, c.hy4};
        };
        EXPECT_EQ(heights(old->layers.at(0).growth.curves), heights(rising)) << version;
        EXPECT_EQ(heights(old->layers.at(1).growth.curves), heights(rising)) << version;
        EXPECT_TRUE(old->layers.at(1).growth.enabled);
        EXPECT_EQ(old->layers.at(2).growth.curves.hy2, 0.3f) << version;
        // Saved and read again, it stays as it was.
        const auto again = parseProject(serializeProject(*old), "again.json");
        ASSERT_TRUE(again) << again.error().message;
        EXPECT_EQ(*again, *old);
    }
    const auto current = parseProject(document(PROJECT_FORMAT_VERSION, body), "new.json");
    ASSERT_TRUE(current) << current.error().message;
    EXPECT_EQ(current->layers.at(0).growth.curves, GrowthCurves{});
    EXPECT_NE(GrowthCurves{}.hy0, rising.hy0);
}

TEST(ProjectMigration, TheLimitsOfVersion2RefuseAVersion1FileAsTheyRefuseAVersion2File) {
    for (const int version : {1, 2}) {
        const auto project =
            parseProject(document(version, R"(, "physics": {"step_s": 1e-7})"), "p.json");
        ASSERT_FALSE(project) << version;
        EXPECT_NE(project.error().message.find("/physics/step_s"), std::string::npos);
    }
}

TEST(ProjectMigration, ANewerOrOlderVersionIsRefusedNamingWhatThisBuildReads) {
    for (const int version : {0, PROJECT_FORMAT_VERSION + 1}) {
        const auto project = parseProject(document(version, ""), "p.json");
        ASSERT_FALSE(project) << version;
        EXPECT_NE(project.error().message.find("this build reads only versions 1 to " +
                                               std::to_string(PROJECT_FORMAT_VERSION)),
                  std::string::npos)
            << project.error().message;
    }
}

}  // namespace
}  // namespace grass::core
