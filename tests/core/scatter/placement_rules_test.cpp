// Placement rules (issue 27): on the rules terrain (a ground, a 70° cliff, a floating sphere and
// a tree-like blob, none with UVs) each rule removes grass exactly where it says, counted per
// part, and leaves every other candidate as the density map alone would.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <map>

#include "mesh/closest_point.h"
#include "mesh/gltf_loader.h"
#include "mesh/mesh_parts.h"
#include "mesh/procedural.h"
#include "scatter/placement_rules.h"
#include "support/rules_terrain.h"
#include "support/scratch_folder.h"

namespace grass::core {
namespace {

class PlacementRulesTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        test::ScratchFolder folder("placement-rules");
        test::writeRulesTerrain(folder / "terrain.glb");
        auto imported = loadGltf(folder / "terrain.glb");
        ASSERT_TRUE(imported) << imported.error().str();
        sMesh = new SurfaceMesh(std::move(imported->mesh));
        ScatterParams params;
        params.density = 30.0f;  // ~13 000 candidates over the ~440 m² of surface
        sCandidates = new ScatterCandidates(scatterCandidates(*sMesh, params, 7));
    }
    static void TearDownTestSuite() {
        delete sMesh;
        delete sCandidates;
    }

    // The node that placed candidate i's face ("Ground", "Cliff", "Cloud", "Trunk", "Canopy").
    static const std::string& nodeOf(std::size_t i) {
        const MeshParts& table = *meshPartsOf(*sMesh);
        return table.parts[table.faceParts[sCandidates->faces[i]]].nodes.front();
    }

    // Live candidates per node under `rules`.
    static std::map<std::string, std::size_t> liveByNode(const PlacementRules& rules,
                                                         const RuleWorld& world = {}) {
        const std::vector<float> factors = placementFactors(*sMesh, *sCandidates, rules, world);
        std::map<std::string, std::size_t> live;
        for (std::size_t i = 0; i < sCandidates->blades.size(); ++i) {
            const float factor = factors.empty() ? 1.0f : factors[i];
            live[nodeOf(i)] += keepsCandidate(*sCandidates, i, nullptr, factor) ? 1 : 0;
        }
        return live;
    }

    static glm::vec3 faceNormal(std::uint32_t face) {
        const auto p = facePositions(*sMesh, sMesh->face_handle(static_cast<int>(face)));
        return glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    }

    static inline SurfaceMesh* sMesh = nullptr;
    static inline ScatterCandidates* sCandidates = nullptr;
};

TEST_F(PlacementRulesTest, TheTerrainNamesEveryPartItsFileNames) {
    const std::vector<std::string> names = partNames(*sMesh);
    for (const char* name : {"Ground", "Cliff", "Cloud", "Tree", "Trunk", "Canopy", "Soil", "Rock",
                             "Leaves", "Bark", "GroundMesh", "CanopyMesh"})
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    const auto open = liveByNode({});
    for (const char* node : {"Ground", "Cliff", "Cloud", "Trunk", "Canopy"})
        EXPECT_GT(open.at(node), 20u) << node << ": the open rules grow on every part";
}

TEST_F(PlacementRulesTest, OpenRulesNeedNoFactors) {
    EXPECT_TRUE(rulesAreOpen({}));
    EXPECT_TRUE(placementFactors(*sMesh, *sCandidates, {}, {}).empty());
    PlacementRules clearanceAlone;
    clearanceAlone.clearanceM = 2.0f;  // no colliders chosen, no parts: still open
    EXPECT_TRUE(rulesAreOpen(clearanceAlone));
}

TEST_F(PlacementRulesTest, ExcludingCloudsTreesAndSteepGroundLeavesTheGroundWhole) {
    PlacementRules rules;
    rules.exclude = {"Cloud", "Tree"};
    rules.slopeMaxDeg = 45.0f;
    const auto open = liveByNode({});
    const auto ruled = liveByNode(rules);
    EXPECT_EQ(ruled.at("Ground"), open.at("Ground")) << "flat ground is inside every window";
    for (const char* node : {"Cliff", "Cloud", "Trunk", "Canopy"})
        EXPECT_EQ(ruled.at(node), 0u) << node;
}

TEST_F(PlacementRulesTest, TheSlopeWindowCutsAtItsAngleExactly) {
    PlacementRules rules;
    rules.slopeMinDeg = 60.0f;
    rules.slopeMaxDeg = 80.0f;
    const std::vector<float> factors = placementFactors(*sMesh, *sCandidates, rules, {});
    std::size_t cliffLive = 0, inside = 0;
    for (std::size_t i = 0; i < factors.size(); ++i) {
        const float slope = glm::degrees(std::acos(glm::clamp(
            glm::dot(faceNormal(sCandidates->faces[i]), glm::vec3(0, 1, 0)), -1.0f, 1.0f)));
        // A hard edge: 1 inside, 0 outside (half a degree of float slack at the window's ends).
        if (slope > 60.5f && slope < 79.5f) {
            EXPECT_EQ(factors[i], 1.0f) << slope;
        }
        if (slope < 59.5f || slope > 80.5f) {
            EXPECT_EQ(factors[i], 0.0f) << slope;
        }
        inside += factors[i] > 0.0f ? 1 : 0;
        cliffLive += factors[i] > 0.0f && nodeOf(i) == "Cliff" ? 1 : 0;
    }
    EXPECT_GT(cliffLive, 100u);
    EXPECT_EQ(liveByNode(rules).at("Ground"), 0u);
    EXPECT_GT(inside, cliffLive) << "the sphere's and blob's steep belts are in the window too";
}

TEST_F(PlacementRulesTest, ASoftSlopeEdgeThinsLinearly) {
    PlacementRules rules;
    rules.slopeMaxDeg = 60.0f;
    rules.slopeSoftDeg = 20.0f;
    EXPECT_FLOAT_EQ(windowFactor(70.0f, 0.0f, 60.0f, 20.0f), 0.5f);
    EXPECT_FLOAT_EQ(windowFactor(85.0f, 0.0f, 60.0f, 20.0f), 0.0f);
    EXPECT_FLOAT_EQ(windowFactor(-5.0f, 0.0f, 60.0f, 20.0f), 0.75f);
    // The 70° cliff keeps about half its candidates.
    const auto open = liveByNode({});
    const auto soft = liveByNode(rules);
    const double kept = double(soft.at("Cliff")) / double(open.at("Cliff"));
    EXPECT_NEAR(kept, 0.5, 0.1) << soft.at("Cliff") << " of " << open.at("Cliff");
}

TEST_F(PlacementRulesTest, TheAltitudeWindowFollowsGravity) {
    PlacementRules rules;
    rules.altitudeMaxM = 2.0f;
    rules.altitudeSoftM = 1.0f;
    const std::vector<float> factors = placementFactors(*sMesh, *sCandidates, rules, {});
    for (std::size_t i = 0; i < factors.size(); ++i) {
        const float y = sCandidates->blades[i].v0().y;
        EXPECT_NEAR(factors[i], std::clamp(1.0f - (y - 2.0f), 0.0f, 1.0f), 1e-5f) << y;
    }
    EXPECT_EQ(liveByNode(rules).at("Cloud"), 0u) << "the cloud floats 4.5 m up and more";
    // Gravity along +X: "up" is −X, and the cliff (x > 6.3) is far below altitude −2.
    RuleWorld sideways;
    sideways.gravity = {1.0f, 0.0f, 0.0f, 9.81f};
    PlacementRules below;
    below.altitudeMaxM = -6.0f;
    const auto sideLive = liveByNode(below, sideways);
    EXPECT_EQ(sideLive.at("Cloud"), 0u);
    EXPECT_GT(sideLive.at("Cliff"), 100u);
}

TEST_F(PlacementRulesTest, CentreGravityMeasuresDistanceFromTheCentre) {
    ProceduralMeshParams sphere;
    sphere.shape = ProceduralShape::Sphere;
    const SurfaceMesh planet = makeProceduralMesh(sphere);
    ScatterParams sparse;
    sparse.density = 20.0f;
    const ScatterCandidates candidates = scatterCandidates(planet, sparse, 3);
    RuleWorld world;
    world.gravityMode = GravityMode::Centre;
    world.gravity = glm::vec4(0.0f, 0.0f, 0.0f, 9.81f);
    PlacementRules rules;
    rules.slopeMaxDeg = 10.0f;  // every point of a sphere is level against centre gravity
    const std::vector<float> factors = placementFactors(planet, candidates, rules, world);
    ASSERT_FALSE(factors.empty());
    EXPECT_EQ(std::count(factors.begin(), factors.end(), 1.0f), std::ptrdiff_t(factors.size()));
    const glm::vec3 p = candidates.blades[0].v0();
    EXPECT_FLOAT_EQ(altitudeM(p, world), glm::length(p));
}

TEST_F(PlacementRulesTest, NamesMatchNodesTheirParentsMeshesAndMaterials) {
    PlacementRules byParent;
    byParent.exclude = {"Tree"};
    const auto noTree = liveByNode(byParent);
    EXPECT_EQ(noTree.at("Trunk"), 0u);
    EXPECT_EQ(noTree.at("Canopy"), 0u);
    EXPECT_EQ(noTree.at("Ground"), liveByNode({}).at("Ground"));

    PlacementRules byMaterial;
    byMaterial.include = {"Soil", "Leaves"};
    const auto soil = liveByNode(byMaterial);
    EXPECT_GT(soil.at("Ground"), 0u);
    EXPECT_GT(soil.at("Canopy"), 0u);
    for (const char* node : {"Cliff", "Cloud", "Trunk"})
        EXPECT_EQ(soil.at(node), 0u) << node;

    PlacementRules byMesh;
    byMesh.include = {"CloudMesh"};
    byMesh.exclude = {"Cloud"};  // exclude wins
    for (const auto& [node, live] : liveByNode(byMesh))
        EXPECT_EQ(live, 0u) << node;
}

TEST_F(PlacementRulesTest, ClearanceKeepsGroundBareAroundChosenPartsAndColliders) {
    PlacementRules rules;
    rules.clearanceM = 1.0f;
    rules.clearOf = {"Trunk"};
    const std::vector<float> factors = placementFactors(*sMesh, *sCandidates, rules, {});
    std::vector<ClearanceGrid::Triangle> trunk;
    const MeshParts& table = *meshPartsOf(*sMesh);
    for (const auto fh : sMesh->faces())
        if (table.parts[table.faceParts[std::size_t(fh.idx())]].nodes.front() == "Trunk")
            trunk.push_back(facePositions(*sMesh, fh));
    ASSERT_FALSE(trunk.empty());
    std::size_t removed = 0;
    for (std::size_t i = 0; i < factors.size(); ++i) {
        const glm::vec3 p = sCandidates->blades[i].v0();
        float nearest = INFINITY;
        for (const auto& t : trunk)
            nearest = std::min(nearest, glm::length(p - closestPointOnTriangle(p, t[0], t[1], t[2])));
        EXPECT_EQ(factors[i], nearest < 1.0f ? 0.0f : 1.0f) << nearest;
        removed += nearest < 1.0f && nodeOf(i) == "Ground" ? 1 : 0;
    }
    // A 0.4 m trunk with 1 m around it bares about π·1.2² ≈ 4.5 m² of ground: ~135 candidates.
    EXPECT_GT(removed, 60u);

    PlacementRules colliders;
    colliders.clearanceM = 0.5f;
    colliders.clearColliders = true;
    RuleWorld world;
    // A collider box 2 m across on the ground at the origin: its top, bottom and sides.
    const glm::vec3 lo(-1.0f, 0.0f, -1.0f), hi(1.0f, 2.0f, 1.0f);
    world.colliderTriangles = {{lo, {hi.x, lo.y, lo.z}, {hi.x, lo.y, hi.z}},
                               {lo, {hi.x, lo.y, hi.z}, {lo.x, lo.y, hi.z}}};
    const std::vector<float> nearCollider = placementFactors(*sMesh, *sCandidates, colliders, world);
    for (std::size_t i = 0; i < nearCollider.size(); ++i) {
        const glm::vec3 p = sCandidates->blades[i].v0();
        // Distance to the square [-1, 1]² at y = 0.
        const glm::vec3 outside(std::max(std::abs(p.x) - 1.0f, 0.0f), p.y,
                                std::max(std::abs(p.z) - 1.0f, 0.0f));
        const bool under = glm::length(outside) < 0.49f;
        const bool away = glm::length(outside) > 0.51f;
        if (under) {
            EXPECT_EQ(nearCollider[i], 0.0f);
        }
        if (away) {
            EXPECT_EQ(nearCollider[i], 1.0f);
        }
    }
}

// A collider wider than twice the clearance: the ground under it is cleared too, however far
// from its walls, and the ground beyond the clearance is not. Before (2026-12-07), a box 4 m
// across cleared by 0.3 m kept the grass in its middle, hidden inside it.
TEST_F(PlacementRulesTest, ClearanceClearsTheGroundUnderAColliderToo) {
    PlacementRules rules;
    rules.clearanceM = 0.3f;
    rules.clearColliders = true;
    RuleWorld world;
    // A closed box sunk 0.5 m into the ground at the origin, 4 m across and 1 m above it.
    const glm::vec3 lo(-2.0f, -0.5f, -2.0f), hi(2.0f, 1.0f, 2.0f);
    const auto corner = [&](int i) {
        return glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    };
    for (const auto& q : std::array<std::array<int, 4>, 6>{{{0, 4, 6, 2},
                                                            {1, 3, 7, 5},
                                                            {0, 1, 5, 4},
                                                            {2, 6, 7, 3},
                                                            {0, 2, 3, 1},
                                                            {4, 5, 7, 6}}}) {
        world.colliderTriangles.push_back({corner(q[0]), corner(q[1]), corner(q[2])});
        world.colliderTriangles.push_back({corner(q[0]), corner(q[2]), corner(q[3])});
    }
    world.colliderEnds = {world.colliderTriangles.size()};
    // Each ground candidate's factor under `rules`, with its distance outside the box's
    // footprint (0 under it).
    const auto eachGroundRoot = [&](const auto& visit) {
        const std::vector<float> factors = placementFactors(*sMesh, *sCandidates, rules, world);
        ASSERT_EQ(factors.size(), sCandidates->blades.size());
        for (std::size_t i = 0; i < factors.size(); ++i) {
            const glm::vec3 p = sCandidates->blades[i].v0();
            if (nodeOf(i) == "Ground")
                visit(p,
                      glm::length(glm::vec2(std::max(std::abs(p.x) - 2.0f, 0.0f),
                                            std::max(std::abs(p.z) - 2.0f, 0.0f))),
                      factors[i]);
        }
    };
    std::size_t under = 0, beyond = 0, deepInside = 0;
    eachGroundRoot([&](glm::vec3 p, float outside, float factor) {
        if (outside == 0.0f) {
            ++under;
            EXPECT_EQ(factor, 0.0f) << "a root under the box at " << p.x << ", " << p.z;
            deepInside += std::max(std::abs(p.x), std::abs(p.z)) < 1.5f ? 1 : 0;
        } else if (outside > 0.31f) {
            ++beyond;
            EXPECT_EQ(factor, 1.0f) << "a root " << outside << " m from the box";
        }
    });
    EXPECT_GT(deepInside, 100u) << "roots farther than the clearance from every wall";
    EXPECT_GT(beyond, 1000u);
    std::printf("[ clearance ] %zu roots under the box cleared (%zu deeper than the clearance)\n",
                under, deepInside);

    // "clear colliders" with no clearance: the ground under the box only. Before, a clearance
    // of 0 left the rule open, the box's checkbox doing nothing.
    rules.clearanceM = 0.0f;
    EXPECT_FALSE(rulesAreOpen(rules));
    std::size_t besideKept = 0;
    eachGroundRoot([&](glm::vec3 p, float outside, float factor) {
        EXPECT_EQ(factor, outside == 0.0f ? 0.0f : 1.0f)
            << "a root " << outside << " m from the box at " << p.x << ", " << p.z;
        besideKept += outside > 0.0f && outside < 0.3f ? 1 : 0;
    });
    EXPECT_GT(besideKept, 5u) << "the ring the clearance took is grass again";
}

TEST_F(PlacementRulesTest, RulesMultiplyTheDensityMap) {
    // A map of 0.5 everywhere and a soft rule of 0.5 on a candidate: it lives where keep < 0.25.
    PlacementRules rules;
    rules.altitudeMaxM = -0.5f;
    rules.altitudeSoftM = 1.0f;  // factor 0.5 at the ground (y = 0)
    const std::vector<float> factors = placementFactors(*sMesh, *sCandidates, rules, {});
    MapImage half = makeConstantMap(4, 4, 0.5f);
    for (std::size_t i = 0; i < sCandidates->uniformCount; ++i) {
        if (nodeOf(i) != "Ground")
            continue;
        ASSERT_NEAR(factors[i], 0.5f, 1e-6f);
        EXPECT_EQ(keepsCandidate(*sCandidates, i, &half, factors[i]),
                  sCandidates->thinning[i].keep < 0.25f);
    }
}

TEST_F(PlacementRulesTest, ASurfaceWithoutNamesIsOneUnnamedPart) {
    const SurfaceMesh plane = makeProceduralMesh({});
    const ScatterCandidates candidates = scatterCandidates(plane, ScatterParams{}, 5);
    PlacementRules exclude;
    exclude.exclude = {"Ground"};
    const auto excluded = placementFactors(plane, candidates, exclude, {});
    EXPECT_EQ(std::count(excluded.begin(), excluded.end(), 1.0f), std::ptrdiff_t(excluded.size()));
    PlacementRules include;
    include.include = {"Ground"};
    const auto included = placementFactors(plane, candidates, include, {});
    EXPECT_EQ(std::count(included.begin(), included.end(), 0.0f), std::ptrdiff_t(included.size()));
}

}  // namespace
}  // namespace grass::core
