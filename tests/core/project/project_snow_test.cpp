// The "snow" object of project.json (SPEC §11, issue 9): off by default, every field round trips,
// and every bad value gives one line naming its JSON pointer and the allowed range.
#include <gtest/gtest.h>

#include "project/project.h"
#include "support/project_errors.h"

namespace grass::core {
namespace {

const std::string SOURCE = "projects/test/project.json";

std::string documentWithSnow(const std::string& members) {
    return test::documentWithObject("snow", members);
}

void expectError(const std::string& members, const std::string& pointer,
                 const std::string& problem) {
    test::expectObjectError("snow", members, SOURCE, pointer, problem);
}

TEST(ProjectSnow, MissingObjectMeansNoSnow) {
    const auto parsed = parseProject(R"({"format": "grass-project", "version": 1})", SOURCE);
    ASSERT_TRUE(parsed.ok()) << parsed.error().str();
    EXPECT_EQ(parsed->snow, SnowParams{});
    EXPECT_EQ(parsed->snow.enabled, 0u);
    // The defaults: the paper's 1024² map, A = ½, B = 2; 8 samples (docs/snow.md measured it).
    EXPECT_EQ(parsed->snow.mapResolution, 1024);
    EXPECT_EQ(parsed->snow.samples, 8);
    EXPECT_EQ(parsed->snow.noiseAmplitude, 0.5f);
    EXPECT_EQ(parsed->snow.noiseFrequency, 2.0f);
}

TEST(ProjectSnow, EveryFieldRoundTrips) {
    Project project;
    SnowParams& s = project.snow;
    s.enabled = 1;
    s.amountM = 0.35f;
    s.maxAmountM = 0.8f;
    s.fallDirection = {0.2f, -1.0f, 0.1f};
    s.snowColor = {0.9f, 0.91f, 0.99f};
    s.noiseOctaves = 6;
    s.noiseAmplitude = 0.6f;
    s.noiseFrequency = 2.5f;
    s.noiseScaleM = 3.5f;
    s.inclineNoise = 0.3f;
    s.mapResolution = 2048;
    s.samples = 32;
    s.sampleRadiusTexels = 2.5f;
    s.depthBiasM = 0.05f;
    s.boundaryFalloffM = 0.4f;
    s.accumulationRate = 0.01f;
    s.meltRate = 0.002f;
    s.loadGravity = 12.0f;
    s.drift = 0.7f;
    s.driftReachM = 6.5f;
    s.driftFollowsWind = 0u;
    s.driftDirection = {-1.0f, 0.0f, 0.4f};
    const std::string text = serializeProject(project);
    EXPECT_NE(text.find("\"snow\""), std::string::npos);
    const auto again = parseProject(text, SOURCE);
    ASSERT_TRUE(again.ok()) << again.error().str();
    EXPECT_EQ(again->snow, project.snow);
    EXPECT_EQ(serializeProject(*again), text);
}

TEST(ProjectSnow, EachResolutionIsAccepted) {
    for (int resolution : {512, 1024, 2048}) {
        const auto parsed = parseProject(
            documentWithSnow("\"map_resolution\": " + std::to_string(resolution)), SOURCE);
        ASSERT_TRUE(parsed.ok()) << parsed.error().str();
        EXPECT_EQ(parsed->snow.mapResolution, resolution);
    }
}

TEST(ProjectSnow, BadValuesNameTheirPointer) {
    expectError(R"("enabled": "yes")", "/snow/enabled", "");
    expectError(R"("amount": -0.1)", "/snow/amount", "[0, 10]");
    expectError(R"("amount": 1e999)", "/snow/amount", "finite");
    expectError(R"("amount": 2, "max_amount": 1)", "/snow/amount", "max_amount");
    expectError(R"("max_amount": 11)", "/snow/max_amount", "");
    expectError(R"("fall_direction": [0, 0, 0])", "/snow/fall_direction", "zero");
    expectError(R"("drift_direction": [0, 0, 0])", "/snow/drift_direction", "zero");
    expectError(R"("drift": 1.5)", "/snow/drift", "[0, 1]");
    expectError(R"("drift_reach": 0)", "/snow/drift_reach", "(0, 100]");
    expectError(R"("drift_follows_wind": 1)", "/snow/drift_follows_wind", "true");
    expectError(R"("fall_direction": [0, -1])", "/snow/fall_direction", "");
    expectError(R"("color": [1.2, 1, 1])", "/snow/color/0", "[0, 1]");
    expectError(R"("noise_octaves": 0)", "/snow/noise_octaves", "");
    expectError(R"("noise_octaves": 9)", "/snow/noise_octaves", "");
    expectError(R"("noise_amplitude": 0)", "/snow/noise_amplitude", "");
    expectError(R"("noise_amplitude": 1.5)", "/snow/noise_amplitude", "");
    expectError(R"("noise_frequency": 1)", "/snow/noise_frequency", "");
    expectError(R"("noise_scale": 0)", "/snow/noise_scale", "");
    expectError(R"("incline_noise": 2)", "/snow/incline_noise", "");
    expectError(R"("map_resolution": 700)", "/snow/map_resolution", "512, 1024 or 2048");
    expectError(R"("map_resolution": 4096)", "/snow/map_resolution", "512, 1024 or 2048");
    expectError(R"("map_resolution": "big")", "/snow/map_resolution", "");
    expectError(R"("samples": 0)", "/snow/samples", "");
    expectError(R"("samples": 33)", "/snow/samples", "");
    expectError(R"("sample_radius": -1)", "/snow/sample_radius", "");
    expectError(R"("depth_bias": -0.01)", "/snow/depth_bias", "");
    expectError(R"("boundary_falloff": -1)", "/snow/boundary_falloff", "");
    expectError(R"("accumulation_rate": -0.1)", "/snow/accumulation_rate", "");
    expectError(R"("melt_rate": 2)", "/snow/melt_rate", "");
    expectError(R"("load_gravity": -5)", "/snow/load_gravity", "");
    expectError(R"("depth": 0.2)", "/snow/depth", "unknown key");
    test::expectProjectError(R"({"format": "grass-project", "version": 1, "snow": true})", SOURCE,
                             "/snow", "");
}

}  // namespace
}  // namespace grass::core
