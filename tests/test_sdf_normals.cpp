// The finite-difference normals of sdf/normals.h (tetrahedral, 4 evaluations; central, 6) against
// the analytic normals of the primitives, at points on their surfaces; and scene_normal's dispatch.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include "sdf/sdf.hpp"

// The scene the normals differentiate: whatever the test case installs.
namespace sdf_test_normals {
using namespace sdf;
static std::function<float(float3)> current_distance;
static std::function<int(float3, float3*)> current_normal;
inline float scene_distance(float3 p) { return current_distance(p); }
inline int scene_analytic_normal(float3 p, float3* n) { return current_normal(p, n); }
#include "sdf/normals.h"
}  // namespace sdf_test_normals

using sdf::float3;
namespace scene = sdf_test_normals;

namespace {

struct Primitive {
    const char* name;
    std::function<float(float3)> f;
    std::function<float3(float3)> n;
};

std::vector<Primitive> primitives() {
    return {
        {"sphere r=1", [](float3 p) { return sdf::fSphere(p, 1.0f); }, [](float3 p) { return sdf::nSphere(p, 1.0f); }},
        {"plane", [](float3 p) { return sdf::fPlane(p, float3(1, 2, 2) / 3.0f, 0.5f); },
         [](float3 p) { return sdf::nPlane(p, float3(1, 2, 2) / 3.0f, 0.5f); }},
        {"box (1,0.5,1.5)", [](float3 p) { return sdf::fBox(p, float3(1, 0.5f, 1.5f)); },
         [](float3 p) { return sdf::nBox(p, float3(1, 0.5f, 1.5f)); }},
        {"round box r=0.3", [](float3 p) { return sdf::fRoundBox(p, float3(1, 0.5f, 1.5f), 0.3f); },
         [](float3 p) { return sdf::nRoundBox(p, float3(1, 0.5f, 1.5f), 0.3f); }},
        {"torus 1.5/0.4", [](float3 p) { return sdf::fTorus(p, 1.5f, 0.4f); }, [](float3 p) { return sdf::nTorus(p, 1.5f, 0.4f); }},
        {"cylinder r=0.8 h=1.2", [](float3 p) { return sdf::fCylinder(p, 0.8f, 1.2f); },
         [](float3 p) { return sdf::nCylinder(p, 0.8f, 1.2f); }},
        {"capsule r=0.5 h=1", [](float3 p) { return sdf::fCapsule(p, 0.5f, 1.0f); }, [](float3 p) { return sdf::nCapsule(p, 0.5f, 1.0f); }},
        {"cone r=1 h=2", [](float3 p) { return sdf::fCone(p, 1.0f, 2.0f); }, [](float3 p) { return sdf::nCone(p, 1.0f, 2.0f); }},
    };
}

double angle(float3 a, float3 b) {
    return std::atan2(double(glm::length(glm::cross(a, b))), double(glm::dot(a, b)));
}

}  // namespace

TEST_CASE("SDF normals: tetrahedral and central differences agree with the analytic normals", "[sdf]") {
    const float h = 1e-3f;
    // Points where the surface's curvature is at most 1 / 0.3 (the smallest radius below; the
    // cone's tip, where circles about the axis shrink to nothing, is left out). The tetrahedral
    // normal is first order: off by about h |H| <= h / 0.3 = 3.3e-3 rad. The central one is second
    // order on smooth parts (float rounding of f, ~1e-7 / 2h = 5e-5 rad, dominates), but only first
    // order where the curvature jumps (round box and capsule: flat or cylindrical part meets the
    // rounded part), about h * jump / 2 <= 1.7e-3 rad there.
    const double kMaxCurvature = 1.0 / 0.3;
    const double kTetrahedralTolerance = 1.2 * h * kMaxCurvature;  // 4e-3 rad, 0.23 degrees
    const double kCentralTolerance = 1e-3;                         // rad, 0.06 degrees
    std::mt19937 rng(4242);
    std::uniform_real_distribution<float> u(-2.5f, 2.5f);
    std::printf("SDF normals at h = %g on the surface (angle to the analytic normal, rad):\n", double(h));
    std::printf("  %-22s %6s %12s %12s %12s %12s\n", "primitive", "points", "tetra mean", "tetra max", "central mean", "central max");
    for (const Primitive& prim : primitives()) {
        scene::current_distance = prim.f;
        int kept = 0, tried = 0;
        double tetra_sum = 0, tetra_max = 0, central_sum = 0, central_max = 0;
        while (tried < 4000) {
            ++tried;
            float3 q(u(rng), u(rng), u(rng));
            // onto the surface: one step down the exact distance's gradient reaches the nearest point
            float3 p = q - prim.n(q) * prim.f(q);
            if (std::fabs(prim.f(p)) > 1e-5f) continue;
            // only where the normal turns no faster than kMaxCurvature over the stencil: not on an
            // edge, rim or apex, where differences straddle two faces and the analytic normal
            // picks one, nor near the cone's tip
            float3 n = prim.n(p);
            bool smooth = true;
            for (int axis = 0; axis < 3 && smooth; ++axis)
                for (float sign : {-2.0f, 2.0f}) {
                    float3 offset(0.0f);
                    offset[axis] = sign * h;
                    if (angle(prim.n(p + offset), n) > 1.01 * 2.0 * h * kMaxCurvature) smooth = false;
                }
            if (!smooth) continue;
            ++kept;
            double et = angle(scene::normal_tetrahedral(p, h), n);
            double ec = angle(scene::normal_central(p, h), n);
            tetra_sum += et;
            central_sum += ec;
            tetra_max = std::fmax(tetra_max, et);
            central_max = std::fmax(central_max, ec);
        }
        std::printf("  %-22s %6d %12.3g %12.3g %12.3g %12.3g\n", prim.name, kept, tetra_sum / kept, tetra_max, central_sum / kept,
                    central_max);
        INFO(prim.name << ": " << kept << " of " << tried << " points on smooth parts");
        CHECK(kept > tried / 5);
        CHECK(tetra_max < kTetrahedralTolerance);
        CHECK(central_max < kCentralTolerance);
        // second order beats first order where the surface curves (not on the plane and the box)
        if (tetra_sum / kept > 1e-4) CHECK(central_sum < 0.2 * tetra_sum);
    }
}

TEST_CASE("SDF normals: scene_normal dispatches, and falls back to tetrahedral without an analytic normal", "[sdf]") {
    scene::current_distance = [](float3 p) { return sdf::fTorus(p, 1.5f, 0.4f); };
    const float3 p(1.7f, 0.3f, 0.6f);
    const float h = 1e-3f;
    scene::current_normal = [](float3 q, float3* n) {
        *n = sdf::nTorus(q, 1.5f, 0.4f);
        return 1;
    };
    CHECK(scene::scene_normal(p, h, NORMAL_ANALYTIC) == sdf::nTorus(p, 1.5f, 0.4f));
    CHECK(scene::scene_normal(p, h, NORMAL_CENTRAL) == scene::normal_central(p, h));
    CHECK(scene::scene_normal(p, h, NORMAL_TETRAHEDRAL) == scene::normal_tetrahedral(p, h));
    CHECK(scene::normal_central(p, h) != scene::normal_tetrahedral(p, h));  // the cases above are distinguishable
    scene::current_normal = [](float3, float3*) { return 0; };
    CHECK(scene::scene_normal(p, h, NORMAL_ANALYTIC) == scene::normal_tetrahedral(p, h));
    // a flat field has no normal: +y rather than NaN
    scene::current_distance = [](float3) { return 1.0f; };
    CHECK(scene::normal_tetrahedral(p, h) == float3(0, 1, 0));
    CHECK(scene::normal_central(p, h) == float3(0, 1, 0));
}
