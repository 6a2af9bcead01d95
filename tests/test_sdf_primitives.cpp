// The SDF primitives against closed-form distances worked out by hand at chosen points: inside,
// outside, on the surface, in the regions of faces, edges, corners, the cone's rim and apex; and
// their analytic normals against the directions those closed forms imply.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "sdf/sdf.hpp"

using sdf::float3;

namespace {

struct Expected {
    float3 p;
    float distance;
};

void check_distances(const char* name, const std::function<float(float3)>& f, const std::vector<Expected>& cases) {
    for (const Expected& c : cases) {
        INFO(name << " at (" << c.p.x << ", " << c.p.y << ", " << c.p.z << ")");
        CHECK(f(c.p) == Approx(c.distance).margin(1e-5));
    }
}

const float kSqrt2 = std::sqrt(2.0f);
const float kSqrt3 = std::sqrt(3.0f);
const float kSqrt5 = std::sqrt(5.0f);

}  // namespace

TEST_CASE("SDF primitives: exact distances at hand-picked points", "[sdf]") {
    check_distances("sphere r=1", [](float3 p) { return sdf::fSphere(p, 1.0f); },
                    {{{0, 0, 0}, -1.0f}, {{2, 0, 0}, 1.0f}, {{0, 1, 0}, 0.0f}, {{0, 0, -0.25f}, -0.75f}, {{1, 1, 1}, kSqrt3 - 1.0f}});

    // the plane y = 1 with the solid below, and a tilted plane through the origin
    check_distances("plane y=1", [](float3 p) { return sdf::fPlane(p, float3(0, 1, 0), -1.0f); },
                    {{{3, 4, 5}, 3.0f}, {{-7, 1, 2}, 0.0f}, {{0, -1, 0}, -2.0f}});
    check_distances("plane (1,1,0)/sqrt2", [](float3 p) { return sdf::fPlane(p, float3(1, 1, 0) / kSqrt2, 0.0f); },
                    {{{1, 1, 7}, kSqrt2}, {{1, -1, 3}, 0.0f}, {{-2, 0, 0}, -kSqrt2}});

    // half extents (1, 2, 3): inside the nearest face wins; outside faces, edges and corners
    check_distances("box (1,2,3)", [](float3 p) { return sdf::fBox(p, float3(1, 2, 3)); },
                    {{{0, 0, 0}, -1.0f},
                     {{0, 0.5f, 2.5f}, -0.5f},
                     {{0.9f, -1.95f, 0}, -0.05f},
                     {{1, 0, 0}, 0.0f},
                     {{1, 2, 3}, 0.0f},
                     {{2, 0, 0}, 1.0f},
                     {{0, 0, -3.5f}, 0.5f},
                     {{2, 3, 0}, kSqrt2},
                     {{1.5f, -2.5f, 0}, std::sqrt(0.5f)},
                     {{2, 3, 4}, kSqrt3},
                     {{-2, -3, -4}, kSqrt3}});

    // outer half extents 1, rounding 0.25: the core box has half extents 0.75
    check_distances("round box (1,1,1) r=0.25", [](float3 p) { return sdf::fRoundBox(p, float3(1, 1, 1), 0.25f); },
                    {{{0, 0, 0}, -1.0f},
                     {{2, 0, 0}, 1.0f},
                     {{1, 0.5f, 0}, 0.0f},
                     {{0, -0.9f, 0.2f}, -0.1f},
                     {{1.5f, 1.5f, 0}, kSqrt2 * 0.75f - 0.25f},
                     {{2, 2, 2}, kSqrt3 * 1.25f - 0.25f},
                     {{0.75f + 0.25f / kSqrt3, 0.75f + 0.25f / kSqrt3, 0.75f + 0.25f / kSqrt3}, 0.0f}});
    // a radius beyond the smallest half extent is capped there (a capsule-like slab, not an inverted box)
    CHECK(sdf::fRoundBox(float3(0, 0, 0), float3(2, 0.5f, 2), 1.0f) == Approx(-0.5f).margin(1e-6));
    CHECK(sdf::fRoundBox(float3(0, 1, 0), float3(2, 0.5f, 2), 1.0f) == Approx(0.5f).margin(1e-6));

    // major 2, minor 0.5, around y
    check_distances("torus 2/0.5", [](float3 p) { return sdf::fTorus(p, 2.0f, 0.5f); },
                    {{{2, 0, 0}, -0.5f},
                     {{0, 0, -2}, -0.5f},
                     {{0, 0, 0}, 1.5f},
                     {{0, 1, 0}, kSqrt5 - 0.5f},
                     {{3, 0, 0}, 0.5f},
                     {{0, 0, 2.5f}, 0.0f},
                     {{2, 1, 0}, 0.5f},
                     {{1.2f, 0.3f, 1.6f}, 0.3f - 0.5f}});

    // radius 1, half height 2, around y: side, caps, rims
    check_distances("cylinder r=1 h=2", [](float3 p) { return sdf::fCylinder(p, 1.0f, 2.0f); },
                    {{{0, 0, 0}, -1.0f},
                     {{0.5f, 1.8f, 0}, -0.2f},
                     {{2, 0, 0}, 1.0f},
                     {{0.6f, 0, 0.8f}, 0.0f},
                     {{0, 3, 0}, 1.0f},
                     {{0, -2.5f, 0}, 0.5f},
                     {{1, 2, 0}, 0.0f},
                     {{2, 3, 0}, kSqrt2},
                     {{1.2f, -3, 1.6f}, kSqrt2}});

    // radius 0.5, segment from y=-1 to y=1
    check_distances("capsule r=0.5 h=1", [](float3 p) { return sdf::fCapsule(p, 0.5f, 1.0f); },
                    {{{0, 0, 0}, -0.5f},
                     {{1, 0, 0}, 0.5f},
                     {{0, 0.9f, 0.5f}, 0.0f},
                     {{0, 2, 0}, 0.5f},
                     {{0, -1.5f, 0}, 0.0f},
                     {{1, 2, 0}, kSqrt2 - 0.5f},
                     {{0, 1.2f, 0}, -0.3f}});

    // base radius 1 at y=0, apex at y=2: slant line 2 rho + y = 2, its normal (2, 1)/sqrt5
    check_distances("cone r=1 h=2", [](float3 p) { return sdf::fCone(p, 1.0f, 2.0f); },
                    {{{0, 2, 0}, 0.0f},                    // apex
                     {{0, 3, 0}, 1.0f},                    // above the apex
                     {{0.5f, 2.5f, 0}, std::sqrt(0.5f)},   // apex region, off axis
                     {{0, 1.9f, 0}, -0.1f / kSqrt5},       // inside under the apex: the slant is nearest
                     {{0, 0, 0}, 0.0f},                    // base centre
                     {{0, -1, 0}, 1.0f},                   // below the base
                     {{0.3f, -0.5f, -0.4f}, 0.5f},         // below the base, off axis
                     {{1, 0, 0}, 0.0f},                    // rim
                     {{2, 0, 0}, 1.0f},                    // outside the rim, level with the base
                     {{1.5f, -0.5f, 0}, std::sqrt(0.5f)},  // rim region, below and outside
                     {{0, 0.5f, 0}, -0.5f},                // inside: the base is nearest
                     {{0, 1, 0}, -1.0f / kSqrt5},          // inside: the slant is nearest
                     {{1, 1, 0}, 1.0f / kSqrt5},           // outside the slant, foot (0.6, 0.8) on it
                     {{0.6f, 1, 0.8f}, 1.0f / kSqrt5},     // the same, rotated about y
                     {{0.5f, 1, 0}, 0.0f}});               // on the slant
}

TEST_CASE("SDF primitives: analytic normals at hand-picked points", "[sdf]") {
    auto check = [](const char* name, float3 got, float3 want) {
        INFO(name << ": got (" << got.x << ", " << got.y << ", " << got.z << "), want (" << want.x << ", " << want.y << ", " << want.z
                  << ")");
        CHECK(glm::length(got - want) < 1e-6f);
    };
    check("sphere", sdf::nSphere(float3(0, 0, -3), 1.0f), float3(0, 0, -1));
    check("sphere centre", sdf::nSphere(float3(0, 0, 0), 1.0f), float3(0, 1, 0));
    check("plane", sdf::nPlane(float3(5, 5, 5), float3(0, 0, 1), 2.0f), float3(0, 0, 1));
    check("box face inside", sdf::nBox(float3(0, 0.5f, -2.5f), float3(1, 2, 3)), float3(0, 0, -1));
    check("box face outside", sdf::nBox(float3(-2, 0.5f, 1), float3(1, 2, 3)), float3(-1, 0, 0));
    check("box edge", sdf::nBox(float3(2, 3, 0), float3(1, 2, 3)), float3(1, 1, 0) / kSqrt2);
    check("box corner", sdf::nBox(float3(2, -3, 4), float3(1, 2, 3)), float3(1, -1, 1) / kSqrt3);
    check("box on face", sdf::nBox(float3(0.2f, 2, 0.1f), float3(1, 2, 3)), float3(0, 1, 0));
    check("round box corner", sdf::nRoundBox(float3(2, 2, 2), float3(1, 1, 1), 0.25f), float3(1, 1, 1) / kSqrt3);
    check("torus outer", sdf::nTorus(float3(0, 0, 3), 2.0f, 0.5f), float3(0, 0, 1));
    check("torus inner", sdf::nTorus(float3(1.5f, 0, 0), 2.0f, 0.5f), float3(-1, 0, 0));
    check("torus top", sdf::nTorus(float3(0, 0.5f, -2), 2.0f, 0.5f), float3(0, 1, 0));
    check("cylinder side", sdf::nCylinder(float3(0, 1, 2), 1.0f, 2.0f), float3(0, 0, 1));
    check("cylinder cap", sdf::nCylinder(float3(0.2f, -3, 0), 1.0f, 2.0f), float3(0, -1, 0));
    check("cylinder rim", sdf::nCylinder(float3(2, 3, 0), 1.0f, 2.0f), float3(1, 1, 0) / kSqrt2);
    check("cylinder inside near cap", sdf::nCylinder(float3(0, 1.9f, 0.1f), 1.0f, 2.0f), float3(0, 1, 0));
    check("capsule side", sdf::nCapsule(float3(-1, 0.5f, 0), 0.5f, 1.0f), float3(-1, 0, 0));
    check("capsule end", sdf::nCapsule(float3(0, 3, 0), 0.5f, 1.0f), float3(0, 1, 0));
    check("cone slant", sdf::nCone(float3(1, 1, 0), 1.0f, 2.0f), float3(2, 1, 0) / kSqrt5);
    check("cone slant inside", sdf::nCone(float3(0, 1, 0.2f), 1.0f, 2.0f), float3(0, 1, 2) / kSqrt5);
    check("cone base", sdf::nCone(float3(0.3f, -0.5f, 0), 1.0f, 2.0f), float3(0, -1, 0));
    check("cone base inside", sdf::nCone(float3(0.3f, 0.1f, 0), 1.0f, 2.0f), float3(0, -1, 0));
    check("cone apex region", sdf::nCone(float3(0.5f, 2.5f, 0), 1.0f, 2.0f), float3(1, 1, 0) / kSqrt2);
    check("cone rim region", sdf::nCone(float3(1.5f, -0.5f, 0), 1.0f, 2.0f), float3(1, -1, 0) / kSqrt2);
}
