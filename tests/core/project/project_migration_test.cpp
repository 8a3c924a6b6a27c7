// Saved projects keep opening (issue 23 item 9): a version 1 file reads as the same project in
// the current version and saves as the current version; the limits of version 2 refuse a version
// 1 file that passes them as they refuse a version 2 file; a version this build does not know is
// refused naming the ones it reads. (ProjectFiles checks every committed project opens.)
#include <gtest/gtest.h>

#include <string>

#include "project/project.h"

namespace grass::core {
namespace {

std::string document(int version, const std::string& body) {
    return R"({"format": "grass-project", "version": )" + std::to_string(version) + body + "}";
}

TEST(ProjectMigration, AVersion1FileReadsAsTheSameProjectAndSavesAsTheCurrentVersion) {
    const std::string body =
        R"(, "name": "old", "physics": {"step_s": 0.02}, "layers": [{"name": "a"}])";
    const auto old = parseProject(document(1, body), "old.json");
    ASSERT_TRUE(old) << old.error().message;
    const auto current = parseProject(document(PROJECT_FORMAT_VERSION, body), "new.json");
    ASSERT_TRUE(current) << current.error().message;
    EXPECT_EQ(*old, *current);
    EXPECT_NE(serializeProject(*old).find("\"version\": " + std::to_string(PROJECT_FORMAT_VERSION)),
              std::string::npos);
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
