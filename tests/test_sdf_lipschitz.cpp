// Numerical Lipschitz estimates of the SDF primitives, domain operators and combinators against
// the bounds they document (sdf/lipschitz.h): max |f(a) - f(b)| / |a - b| over random pairs, some
// along the gradient, some close to the surface, many across cell faces and blend bands. A bound
// must hold (estimate <= bound + 1e-3) and, where the documentation says it is reached, the
// estimate must come close to it -- so a bound that is wrong in either direction fails (the exact
// distances must come out at 1, the sqrt 2 of round and chamfer blends and the 1 + |A w| of the
// sine displacement must be approached).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>

#include "sdf/sdf.hpp"

using sdf::float3;

namespace {

using Field = std::function<float(float3)>;

const float kSqrt2 = std::sqrt(2.0f);
const double kSlack = 1e-3;

// Pairs (a, b): a uniform in [lo, hi], every other one retried until it lies within 0.05 of the
// surface; b = a + s dir with s log-uniform in [1e-2, 1] (smaller separations would let float
// rounding of f, ~1e-7, reach 1e-4 of the ratio), dir along the gradient for a quarter of the
// pairs (found by central differences) and uniformly random otherwise.
double lipschitz_estimate(const Field& f, float3 lo, float3 hi, unsigned seed, int pairs = 20000) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    auto uniform_point = [&]() { return lo + (hi - lo) * float3(u01(rng), u01(rng), u01(rng)); };
    auto random_direction = [&]() {
        for (;;) {
            float3 v(gauss(rng), gauss(rng), gauss(rng));
            float l = glm::length(v);
            if (l > 1e-6f) return v / l;
        }
    };
    double worst = 0.0;
    for (int i = 0; i < pairs; ++i) {
        float3 a = uniform_point();
        for (int tries = 0; i % 2 == 1 && tries < 64 && std::fabs(f(a)) > 0.05f; ++tries) a = uniform_point();
        float3 dir = random_direction();
        if (i % 4 == 0) {
            const float h = 1e-3f;
            float3 g(f(a + float3(h, 0, 0)) - f(a - float3(h, 0, 0)), f(a + float3(0, h, 0)) - f(a - float3(0, h, 0)),
                     f(a + float3(0, 0, h)) - f(a - float3(0, 0, h)));
            if (glm::length(g) > 0.0f) dir = glm::normalize(g);
        }
        float s = std::pow(10.0f, -2.0f + 2.0f * u01(rng));
        float3 b = a + dir * s;
        double dx = double(b.x) - double(a.x), dy = double(b.y) - double(a.y), dz = double(b.z) - double(a.z);
        double distance = std::sqrt(dx * dx + dy * dy + dz * dz);
        if (distance <= 0.0) continue;
        worst = std::fmax(worst, std::fabs(double(f(a)) - double(f(b))) / distance);
    }
    return worst;
}

const float3 kLo(-3.0f, -3.0f, -3.0f);
const float3 kHi(3.0f, 3.0f, 3.0f);

// Checks estimate <= bound + slack and, when `reached`, estimate >= reached.
void check_bound(const char* name, const Field& f, double bound, double reached, unsigned seed) {
    double estimate = lipschitz_estimate(f, kLo, kHi, seed);
    std::printf("  %-46s estimate %.5f  bound %.5f\n", name, estimate, bound);
    INFO(name << ": estimate " << estimate << ", bound " << bound);
    CHECK(estimate <= bound + kSlack);
    if (reached > 0.0) CHECK(estimate >= reached);
}

// An exact distance: the estimate is 1 from both sides.
void check_exact(const char* name, const Field& f, unsigned seed) { check_bound(name, f, 1.0, 1.0 - kSlack, seed); }

}  // namespace

TEST_CASE("SDF Lipschitz: every primitive is an exact distance (estimate 1)", "[sdf]") {
    std::printf("SDF Lipschitz estimates, primitives:\n");
    check_exact("fSphere r=1", [](float3 p) { return sdf::fSphere(p, 1.0f); }, 1);
    check_exact("fPlane n=(1,2,2)/3 offset 0.5", [](float3 p) { return sdf::fPlane(p, float3(1, 2, 2) / 3.0f, 0.5f); }, 2);
    check_exact("fBox (1,0.5,1.5)", [](float3 p) { return sdf::fBox(p, float3(1, 0.5f, 1.5f)); }, 3);
    check_exact("fRoundBox (1,0.5,1.5) r=0.3", [](float3 p) { return sdf::fRoundBox(p, float3(1, 0.5f, 1.5f), 0.3f); }, 4);
    check_exact("fTorus 1.5/0.4", [](float3 p) { return sdf::fTorus(p, 1.5f, 0.4f); }, 5);
    check_exact("fCylinder r=0.8 h=1.2", [](float3 p) { return sdf::fCylinder(p, 0.8f, 1.2f); }, 6);
    check_exact("fCapsule r=0.5 h=1", [](float3 p) { return sdf::fCapsule(p, 0.5f, 1.0f); }, 7);
    check_exact("fCone r=1 h=2", [](float3 p) { return sdf::fCone(p, 1.0f, 2.0f); }, 8);
    check_exact("fCone r=2 h=0.5 (flat)", [](float3 p) { return sdf::fCone(p, 2.0f, 0.5f); }, 9);
    check_exact("fCone r=0.3 h=2.5 (needle)", [](float3 p) { return sdf::fCone(p, 0.3f, 2.5f); }, 10);
}

TEST_CASE("SDF Lipschitz: domain operators keep the bound where documented, and break it where documented", "[sdf]") {
    std::printf("SDF Lipschitz estimates, domain operators:\n");
    // centred and inside their cells: exact distances to the whole array
    check_exact("pMod3 period 1, centred sphere r=0.4", [](float3 p) { return sdf::fSphere(sdf::pMod3(p, float3(1.0f)), 0.4f); }, 11);
    check_exact("pMod3 period (1.5,0,1.2), centred box", [](float3 p) {
        return sdf::fBox(sdf::pMod3(p, float3(1.5f, 0.0f, 1.2f)), float3(0.5f, 0.3f, 0.4f));
    }, 12);
    check_exact("pModInterval3 1.2, 3x1x4 copies, torus", [](float3 p) {
        return sdf::fTorus(sdf::pModInterval3(p, float3(1.2f), float3(-1, 0, -2), float3(1, 0, 1)), 0.4f, 0.15f);
    }, 13);
    // any shape, even one crossing the mirror plane, stays 1-Lipschitz (the fold is non-expanding)
    check_bound("pMirror x=0.2, sphere crossing the plane", [](float3 p) {
        return sdf::fSphere(sdf::pMirror(p, float3(1, 0, 0), -0.2f) - float3(0.5f, 0, 0), 0.6f);
    }, 1.0, 1.0 - kSlack, 14);

    // the documented breaks: a shape off its cell centre, and a shape poking out of its cell
    auto off_centre_sphere = [](float3 p) { return sdf::fSphere(sdf::pMod3(p, float3(1.0f)) - float3(0.3f, 0, 0), 0.15f); };
    auto poking_out_box = [](float3 p) { return sdf::fBox(sdf::pMod3(p, float3(1.0f)) - float3(0.2f, 0, 0), float3(0.4f)); };
    double off_centre = lipschitz_estimate(off_centre_sphere, kLo, kHi, 15);
    double poking_out = lipschitz_estimate(poking_out_box, kLo, kHi, 16);
    std::printf("  %-46s estimate %.5f  (bound broken, as documented)\n", "pMod3, sphere off its cell centre", off_centre);
    std::printf("  %-46s estimate %.5f  (bound broken, as documented)\n", "pMod3, box poking out of its cell", poking_out);
    CHECK(off_centre > 2.0);
    CHECK(poking_out > 2.0);
}

TEST_CASE("SDF Lipschitz: combinators stay within their documented bounds, which are reached", "[sdf]") {
    std::printf("SDF Lipschitz estimates, combinators:\n");
    auto s1 = [](float3 p) { return sdf::fSphere(p - float3(-0.5f, 0, 0), 1.0f); };
    auto s2 = [](float3 p) { return sdf::fSphere(p - float3(0.7f, 0.2f, 0), 0.8f); };
    auto box = [](float3 p) { return sdf::fBox(p - float3(0.3f, -0.4f, 0.1f), float3(0.9f, 0.6f, 0.7f)); };
    // two parallel half-spaces facing the same way: the worst case of round and chamfer blends
    auto floor0 = [](float3 p) { return p.y; };
    auto floor1 = [](float3 p) { return p.y + 0.1f; };
    // two perpendicular half-spaces: the case round and chamfer blends are designed for
    auto wall = [](float3 p) { return p.x; };

    const double one = sdf::lipschitz_union(1.0f, 1.0f);
    const double round = sdf::lipschitz_round(1.0f, 1.0f);
    const double chamfer = sdf::lipschitz_chamfer(1.0f, 1.0f);
    CHECK(one == 1.0);
    CHECK(round == Approx(kSqrt2));
    CHECK(chamfer == Approx(kSqrt2));

    check_bound("fOpUnion, two spheres", [&](float3 p) { return sdf::fOpUnion(s1(p), s2(p)); }, one, one - kSlack, 21);
    check_bound("fOpIntersection, sphere and box", [&](float3 p) { return sdf::fOpIntersection(s1(p), box(p)); }, one, one - kSlack, 22);
    check_bound("fOpSubtraction, box minus sphere", [&](float3 p) { return sdf::fOpSubtraction(box(p), s2(p)); }, one, one - kSlack, 23);

    check_bound("fOpUnionSmooth k=0.6, two spheres", [&](float3 p) { return sdf::fOpUnionSmooth(s1(p), s2(p), 0.6f); }, one,
                one - kSlack, 24);
    check_bound("fOpUnionSmooth k=1, parallel planes", [&](float3 p) { return sdf::fOpUnionSmooth(floor0(p), floor1(p), 1.0f); }, one,
                one - kSlack, 25);

    check_bound("fOpUnionRound r=0.5, perpendicular planes", [&](float3 p) { return sdf::fOpUnionRound(floor0(p), wall(p), 0.5f); },
                one, one - kSlack, 26);
    check_bound("fOpUnionRound r=0.5, parallel planes", [&](float3 p) { return sdf::fOpUnionRound(floor0(p), floor1(p), 0.5f); }, round,
                1.41, 27);
    check_bound("fOpUnionRound r=0.4, two spheres", [&](float3 p) { return sdf::fOpUnionRound(s1(p), s2(p), 0.4f); }, round, 0.0, 28);
    check_bound("fOpIntersectionRound r=0.5, parallel planes",
                [&](float3 p) { return sdf::fOpIntersectionRound(floor0(p), floor1(p), 0.5f); }, round, 1.41, 29);
    check_bound("fOpIntersectionRound r=0.3, sphere and box", [&](float3 p) { return sdf::fOpIntersectionRound(s1(p), box(p), 0.3f); },
                round, 0.0, 30);
    check_bound("fOpSubtractionRound r=0.3, box minus sphere", [&](float3 p) { return sdf::fOpSubtractionRound(box(p), s2(p), 0.3f); },
                round, 0.0, 31);

    check_bound("fOpUnionChamfer r=0.5, perpendicular planes",
                [&](float3 p) { return sdf::fOpUnionChamfer(floor0(p), wall(p), 0.5f); }, one, one - kSlack, 32);
    check_bound("fOpUnionChamfer r=0.5, parallel planes", [&](float3 p) { return sdf::fOpUnionChamfer(floor0(p), floor1(p), 0.5f); },
                chamfer, 1.41, 33);
    check_bound("fOpUnionChamfer r=0.4, two spheres", [&](float3 p) { return sdf::fOpUnionChamfer(s1(p), s2(p), 0.4f); }, chamfer, 0.0,
                34);
    check_bound("fOpIntersectionChamfer r=0.3, sphere and box",
                [&](float3 p) { return sdf::fOpIntersectionChamfer(s1(p), box(p), 0.3f); }, chamfer, 0.0, 35);
    check_bound("fOpSubtractionChamfer r=0.3, box minus sphere",
                [&](float3 p) { return sdf::fOpSubtractionChamfer(box(p), s2(p), 0.3f); }, chamfer, 0.0, 36);
}

TEST_CASE("SDF Lipschitz: the sine displacement breaks 1-Lipschitz by exactly |amplitude frequency|", "[sdf]") {
    std::printf("SDF Lipschitz estimates, displacement:\n");
    const float amplitude = 0.1f, frequency = 5.0f;
    const double bound = sdf::lipschitz_displace_sine(1.0f, amplitude, frequency);
    CHECK(bound == Approx(1.5));
    // on a plane y = const the displacement's steepest gradient (0, A w, 0) adds to the plane's: reached
    check_bound("fOpDisplaceSine A=0.1 w=5 on a plane", [&](float3 p) {
        return sdf::fOpDisplaceSine(sdf::fPlane(p, float3(0, 1, 0), 0.0f), p, amplitude, frequency);
    }, bound, 1.48, 41);
    // on a sphere it is above 1 too, so a marcher that assumed 1 could overshoot
    check_bound("fOpDisplaceSine A=0.1 w=5 on a sphere", [&](float3 p) {
        return sdf::fOpDisplaceSine(sdf::fSphere(p, 1.5f), p, amplitude, frequency);
    }, bound, 1.3, 42);
    // the displacement alone: |grad| <= |A w| (not |A w| sqrt 3), reached
    check_bound("displacement term alone, A=0.1 w=5", [&](float3 p) { return sdf::fOpDisplaceSine(0.0f, p, amplitude, frequency); },
                bound - 1.0, bound - 1.0 - 0.01, 43);
}
