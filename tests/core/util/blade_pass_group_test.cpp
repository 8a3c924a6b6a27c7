// The work-group size of the per-blade passes: 32, or GRASS_COMPUTE_GROUP's value when it is a size
// both passes can run; anything else is an error that names the variable.
#include <gtest/gtest.h>

#include "util/blade_pass_group.h"

namespace grass::core {
namespace {

TEST(BladePassGroup, UnsetIsThe32EveryFigureWasMeasuredWith) {
    for (const char* unset : {static_cast<const char*>(nullptr), ""})
        EXPECT_EQ(bladePassGroupSize(unset).value(), 32u);
}

TEST(BladePassGroup, TheVariableChoosesAnyMultipleOf32UpTo256) {
    for (const auto& [text, size] :
         {std::pair{"32", 32u}, {"64", 64u}, {"96", 96u}, {"128", 128u}, {"256", 256u}}) {
        EXPECT_EQ(bladePassGroupSize(text).value(), size) << text;
    }
}

TEST(BladePassGroup, AnyOtherValueIsAnErrorNamingTheVariable) {
    for (const char* text : {"0", "16", "48", "288", "512", "-32", "abc", "256x", " 64", "64.0",
                             "99999999999999999999"}) {
        const Result<std::uint32_t> size = bladePassGroupSize(text);
        ASSERT_FALSE(size.ok()) << text;
        EXPECT_EQ(size.error().path, "GRASS_COMPUTE_GROUP");
        EXPECT_NE(size.error().message.find(text), std::string::npos) << size.error().str();
        EXPECT_NE(size.error().message.find("multiple of 32"), std::string::npos);
    }
}

TEST(BladePassGroup, ASizeIsOneBothPassesCanRun) {
    for (const std::uint32_t size : {32u, 64u, 224u, 256u})
        EXPECT_TRUE(isBladePassGroupSize(size)) << size;
    for (const std::uint32_t size : {0u, 16u, 48u, 288u, 1024u})
        EXPECT_FALSE(isBladePassGroupSize(size)) << size;
}

TEST(BladePassGroup, TheDefinesSizeEachShadersGroup) {
    EXPECT_EQ(physicsGroupDefine(256), "GROUP_SIZE 256");
    EXPECT_EQ(cullGroupDefine(256), "GROUP_RUNS 8");
    EXPECT_EQ(cullGroupDefine(32), "GROUP_RUNS 1");
}

}  // namespace
}  // namespace grass::core
