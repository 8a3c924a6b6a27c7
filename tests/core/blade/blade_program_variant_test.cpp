// The blade programs' compile-time variants (core/blade/blade_program_variant.h): every
// combination has its own slot, and each feature compiles in the define the shaders test.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "blade/blade_program_variant.h"
#include "support/test_paths.h"

namespace grass::core {
namespace {

BladeProgramVariant variantOf(std::size_t bits) {
    return {.tessellate = (bits & 1u) != 0,
            .lightPerVertex = (bits & 2u) != 0,
            .sunShadows = (bits & 4u) != 0,
            .fadeOut = (bits & 8u) != 0,
            .lodBlend = (bits & 16u) != 0,
            .snowTips = (bits & 32u) != 0,
            .simpleLighting = (bits & 64u) != 0};
}

TEST(BladeProgramVariant, EveryCombinationHasItsOwnSlotAndDefines) {
    std::set<std::size_t> slots;
    std::set<std::vector<std::string>> defineSets;
    for (std::size_t bits = 0; bits < BLADE_PROGRAM_VARIANTS; ++bits) {
        const BladeProgramVariant variant = variantOf(bits);
        EXPECT_LT(variant.index(), BLADE_PROGRAM_VARIANTS);
        slots.insert(variant.index());
        // The geometry path is the stages, not a define: pairs share their defines.
        if (!variant.tessellate)
            defineSets.insert(variant.defines());
    }
    EXPECT_EQ(slots.size(), BLADE_PROGRAM_VARIANTS);
    EXPECT_EQ(defineSets.size(), BLADE_PROGRAM_VARIANTS / 2);
    EXPECT_TRUE(BladeProgramVariant{}.defines().empty());
    EXPECT_EQ(BladeProgramVariant{}.label(), "blade strips");
    const BladeProgramVariant blend{.tessellate = true, .lodBlend = true, .simpleLighting = true};
    EXPECT_EQ(blend.defines(),
              (std::vector<std::string>{"GRASS_LOD_BLEND", "GRASS_SIMPLE_LIGHTING"}));
    EXPECT_EQ(blend.label(), "blade tessellation (LOD blend) (simple lighting)");
}

// A define no shader tests would switch nothing: each one is an #ifdef of the blade shaders.
TEST(BladeProgramVariant, EveryDefineIsOneTheShadersTest) {
    std::string sources;
    for (const char* file : {"blade_strip.vert", "blade_tess.vert", "blade.tesc", "blade.tese",
                             "blade.frag", "include/blade_shade.glsl",
                             "include/blade_lod_blend.glsl", "include/sun_shadow.glsl"}) {
        std::ifstream in(test::sourceDir() / "shaders" / file);
        std::ostringstream text;
        text << in.rdbuf();
        sources += text.str();
    }
    for (const std::string& define : variantOf(BLADE_PROGRAM_VARIANTS - 1).defines())
        EXPECT_NE(sources.find("#ifdef " + define + "\n"), std::string::npos) << define;
}

}  // namespace
}  // namespace grass::core
