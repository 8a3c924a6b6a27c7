// The clearance rule's interiors (scatter/collider_interior.h): a point under a collider's
// surface, inside a closed one or under one open at the bottom, counted by the crossings of a
// half-line along "up".
#include "scatter/collider_interior.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace grass::core {
namespace {

using Triangle = ClearanceGrid::Triangle;

// The 12 triangles of the box [lo, hi], each face split along a diagonal; without its bottom
// (y = lo.y) face when `bottom` is false.
std::vector<Triangle> box(glm::vec3 lo, glm::vec3 hi, bool bottom = true) {
    const auto corner = [&](int i) {
        return glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    };
    // Faces as four corners in order round the face: -x, +x, -y, +y, -z, +z.
    const std::array<std::array<int, 4>, 6> faces{
        {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}}};
    std::vector<Triangle> triangles;
    for (std::size_t f = 0; f < faces.size(); ++f) {
        if (f == 2 && !bottom)
            continue;
        const auto& q = faces[f];
        triangles.push_back({corner(q[0]), corner(q[1]), corner(q[2])});
        triangles.push_back({corner(q[0]), corner(q[2]), corner(q[3])});
    }
    return triangles;
}

ColliderInteriors interiorsOf(const std::vector<std::vector<Triangle>>& colliders) {
    static std::vector<Triangle> all;  // kept alive for the span (the tests run one at a time)
    all.clear();
    std::vector<std::size_t> ends;
    for (const auto& collider : colliders) {
        all.insert(all.end(), collider.begin(), collider.end());
        ends.push_back(all.size());
    }
    return ColliderInteriors(all, ends);
}

constexpr glm::vec3 UP{0.0f, 1.0f, 0.0f};

TEST(ColliderInteriors, APointInsideAClosedBoxIsUnderItFromAnyDirection) {
    const ColliderInteriors rock = interiorsOf({box({-1, -1, -1}, {1, 1, 1})});
    for (const glm::vec3 up : {UP, glm::vec3(1, 1, 0.3f), glm::vec3(-0.2f, -1, 0.7f)}) {
        EXPECT_TRUE(rock.inside({0, 0, 0}, up));
        EXPECT_TRUE(rock.inside({0.9f, -0.9f, 0.37f}, up));
        EXPECT_FALSE(rock.inside({2, 0, 0}, up)) << "beside it";
        EXPECT_FALSE(rock.inside({0, -2, 0}, up)) << "below it";
    }
    EXPECT_FALSE(rock.inside({0, 0, 0}, glm::vec3(0.0f))) << "no direction";
    EXPECT_FALSE(rock.inside({0, 0, 0}, glm::vec3(NAN, 1, 0)));
}

// A ray up from (0.2, 0, 0.2) meets the top face on the diagonal its two triangles share: one
// crossing, not two (the hit test is watertight and the search steps past the crossing).
TEST(ColliderInteriors, ARayThroughASharedEdgeCrossesOnce) {
    const ColliderInteriors rock = interiorsOf({box({-1, -1, -1}, {1, 1, 1})});
    EXPECT_TRUE(rock.inside({0.2f, 0.0f, 0.2f}, UP));
    EXPECT_TRUE(rock.inside({-0.5f, 0.0f, -0.5f}, UP));
    EXPECT_TRUE(rock.inside({1.0f - 1e-4f, 0.0f, 1.0f - 1e-4f}, UP)) << "near a corner";
}

// A scanned rock has no underside: sunk into the ground, the grass under it is under its top.
TEST(ColliderInteriors, UnderARockOpenAtTheBottomCountsAsInside) {
    const ColliderInteriors rock = interiorsOf({box({-1, -0.5f, -1}, {1, 1, 1}, false)});
    EXPECT_TRUE(rock.inside({0.3f, 0.0f, -0.4f}, UP));
    EXPECT_FALSE(rock.inside({0.3f, 0.0f, 1.5f}, UP)) << "beside it";
    EXPECT_FALSE(rock.inside({0.3f, -0.7f, 0.0f}, UP)) << "below its box";
}

TEST(ColliderInteriors, EachColliderIsItsOwnSolid) {
    // Two boxes overlapping in x ∈ [0, 1]: a point in both is inside either one (two crossings
    // of the union would say outside).
    const ColliderInteriors rocks =
        interiorsOf({box({-2, -1, -1}, {1, 1, 1}), box({0, -1, -1}, {3, 1, 1})});
    EXPECT_TRUE(rocks.inside({0.5f, 0.0f, 0.0f}, UP));
    EXPECT_TRUE(rocks.inside({2.5f, 0.0f, 0.0f}, UP));
    EXPECT_FALSE(rocks.inside({3.5f, 0.0f, 0.0f}, UP));
    EXPECT_TRUE(ColliderInteriors().empty());
    EXPECT_FALSE(ColliderInteriors().inside({0, 0, 0}, UP));
}

// Far from the origin (a georeferenced ground, float steps of 2–4 mm) the crossings count as
// near it: the step past each one is sized to the coordinates' rounding, not the rock alone.
TEST(ColliderInteriors, AFarRockCountsItsCrossingsToo) {
    const glm::vec3 at(25000.0f, 300.0f, -40000.0f);
    const ColliderInteriors rock = interiorsOf({box(at - glm::vec3(1), at + glm::vec3(1))});
    EXPECT_TRUE(rock.inside(at + glm::vec3(0.2f, 0.0f, 0.3f), UP));
    EXPECT_FALSE(rock.inside(at + glm::vec3(1.5f, 0.0f, 0.3f), UP));
}

}  // namespace
}  // namespace grass::core
