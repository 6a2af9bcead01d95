// The openpbr model compiled as OpenCL C (kernels/brdf_batch.cl on PoCL) against its C++ build: random
// OpenPBR materials (every input over its range, 30 % of draws at an end), directions with grazing and
// mirror pairs among them, and random numbers give bsdf_eval, bsdf_pdf and bsdf_sample equal to 1e-5
// relative, the BSDF agreement test's tolerance (tests/test_opencl_agreement.cpp). Where the C++ build
// itself moves by more than that when its inputs move by two ulps (the thin film's interference phase,
// hundreds of radians, makes some items so), the OpenCL result must stay within 1e-5 plus 4 times that
// movement, as in that test; fewer than 2 % of the items may need this. A sample's f and pdf are also
// allowed what two ulps of its own returned direction move them in the C++ build (a sharp lobe's f and
// pdf follow the last bits of wi: direction_sensitivity). A material with a thin film is held to 1e-3
// instead, the film's phase's own rounding (below).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"
#include "brdf/host/parameters.hpp"
#include "kernels/host/brdf_batch.hpp"
#include "opencl/runtime.hpp"
#include "validation/random_inputs.hpp"
#include "validation/uniform_random.hpp"

using brdf::float3;

namespace {

double relative(float a, float b) {
    if (a == b) return 0.0;
    double scale = std::fmax(std::fabs(double(a)), std::fabs(double(b)));
    return scale <= 1e-30 ? 0.0 : std::fabs(double(a) - b) / scale;
}

double largest(float3 a, float3 b) { return std::fmax(relative(a.x, b.x), std::fmax(relative(a.y, b.y), relative(a.z, b.z))); }

// A direction as one vector, relative to its length: a component near 0 carries no relative precision.
double direction_difference(float3 a, float3 b) {
    double d = std::fmax(std::fabs(double(a.x) - b.x), std::fmax(std::fabs(double(a.y) - b.y), std::fabs(double(a.z) - b.z)));
    return d / std::fmax(1e-30, std::fmax(glm::length(a), glm::length(b)));
}

// An item's differences in two parts: eval and pdf at the given directions, and the sample (f, pdf
// and wi; infinite where the flags differ, 0 where neither sampled).
struct ItemDifference {
    double at_directions = 0.0, sample = 0.0;
    double largest() const { return std::fmax(at_directions, sample); }
};

ItemDifference item_difference(float3 f0, float p0, const brdf::BsdfSample& s0, float3 f1, float p1, const brdf::BsdfSample& s1) {
    ItemDifference d;
    d.at_directions = std::fmax(largest(f0, f1), relative(p0, p1));
    if (s0.flags != s1.flags) d.sample = INFINITY;
    else if (s0.flags != 0)
        d.sample = std::fmax(std::fmax(largest(s0.f, s1.f), relative(s0.pdf, s1.pdf)), direction_difference(s0.wi, s1.wi));
    return d;
}

// How far a non-delta sample's f and pdf are defined by the direction it returns: the C++ build's
// eval and pdf at its sampled wi moved by two ulps per component, against its sample's own f and pdf.
// The sampler computes f and pdf from its microfacet normal and rounds wi afterwards; on a lobe so
// sharp that its pdf is 1e5 (rough transmission at the lowest roughness), two ulps of wi move the
// half vector, and f and pdf with it, by some 0.3 %, which no 2-ulp move of the inputs shows.
double direction_sensitivity(const brdf::Material& m, float3 wo, const brdf::BsdfSample& s) {
    if (s.flags == 0 || (s.flags & BSDF_DELTA)) return 0.0;
    double own = 0.0;
    for (int k = 0; k < 3; ++k)
        for (float toward : {-2.0f, 2.0f}) {
            float3 wi = s.wi;
            wi[k] = std::nextafter(std::nextafter(wi[k], toward), toward);
            own = std::fmax(own, std::fmax(largest(brdf::bsdf_eval(&m, wo, wi), s.f), relative(brdf::bsdf_pdf(&m, wo, wi), s.pdf)));
        }
    return own;
}

}  // namespace

TEST_CASE("OpenCL: the openpbr model agrees with the C++ build", "[opencl][openpbr]") {
    lab::validation::UniformRandom rng(3737);
    std::vector<brdf::Material> materials;
    for (int k = 0; k < 400; ++k) materials.push_back(lab::validation::random_edge_material(rng, BRDF_MODEL_OPENPBR, 0.3f));
    std::vector<int> index;
    std::vector<float3> wo, wi, u;
    for (int m = 0; m < int(materials.size()); ++m)
        for (int k = 0; k < 100; ++k) {
            float3 o = lab::validation::uniform_sphere_direction(rng), i = lab::validation::uniform_sphere_direction(rng);
            if (k % 4 != 0) o.z = std::fabs(o.z);  // mostly from outside, where the layers are
            if (k % 10 == 1) i = float3(-o.x, -o.y, o.z);
            index.push_back(m), wo.push_back(o), wi.push_back(i), u.push_back(rng.next_float3());
        }
    lab::opencl::Runtime runtime;
    lab::kernels::BrdfBatch batch(runtime);
    batch.set_materials(materials);
    std::vector<float3> f_cl = batch.eval(index, wo, wi);
    std::vector<float> p_cl = batch.pdf(index, wo, wi);
    std::vector<brdf::BsdfSample> s_cl = batch.sample(index, wo, u);
    size_t ill_conditioned = 0, failures = 0, nonzero = 0, deltas = 0;
    double worst[2] = {0.0, 0.0};  // without and with a film
    std::string first;
    for (size_t n = 0; n < index.size(); ++n) {
        const brdf::Material& m = materials[size_t(index[n])];
        float3 f = brdf::bsdf_eval(&m, wo[n], wi[n]);
        float p = brdf::bsdf_pdf(&m, wo[n], wi[n]);
        brdf::BsdfSample s = brdf::bsdf_sample(&m, wo[n], u[n]);
        nonzero += f.x + f.y + f.z > 0.0f;
        deltas += (s.flags & BSDF_DELTA) != 0;
        const ItemDifference d = item_difference(f, p, s, f_cl[n], p_cl[n], s_cl[n]);
        // a film's Airy series sums cos(m phase) for m up to 64 with a phase of up to 2 pi OPD nu = 160 rad
        // (OPD <= 2 x 3 x 2 um, nu <= 2.15 / um): the phase's own rounding, 2^-24 of it, turns the
        // highest harmonic by 64 x 160 x 6e-8 = 6e-4 rad, so a filmed material is held to 1e-3
        const double tolerance = m.thin_film_weight > 0.0f && m.thin_film_thickness > 0.0f ? 1e-3 : 1e-5;
        if (d.largest() <= tolerance) {
            worst[tolerance > 1e-5] = std::fmax(worst[tolerance > 1e-5], d.largest());
            continue;
        }
        // the C++ build's own movement when its inputs move by two ulps (each component of wo, wi, u),
        // for each part; the sample's also by what its direction defines (direction_sensitivity)
        ItemDifference own;
        for (int k = 0; k < 9; ++k)
            for (float toward : {-2.0f, 2.0f}) {
                float3 o = wo[n], i = wi[n], v = u[n];
                float* x = k < 3 ? &o[k] : (k < 6 ? &i[k - 3] : &v[k - 6]);
                *x = std::nextafter(std::nextafter(*x, toward), toward);
                if (k >= 6) *x = std::fmin(std::fmax(*x, 0.0f), 0.99999994f);
                const ItemDifference moved = item_difference(f, p, s, brdf::bsdf_eval(&m, o, i), brdf::bsdf_pdf(&m, o, i), brdf::bsdf_sample(&m, o, v));
                own.at_directions = std::fmax(own.at_directions, moved.at_directions);
                own.sample = std::fmax(own.sample, moved.sample);
            }
        own.sample = std::fmax(own.sample, direction_sensitivity(m, wo[n], s));
        if (d.at_directions <= tolerance + 4.0 * own.at_directions && d.sample <= tolerance + 4.0 * own.sample) {
            ++ill_conditioned;
            continue;
        }
        if (failures++ == 0)
            first = "item " + std::to_string(n) + ": difference " + std::to_string(d.at_directions) + " at the directions, " +
                    std::to_string(d.sample) + " in the sample; eval " + std::to_string(f.x) + " vs " +
                    std::to_string(f_cl[n].x) + ", pdf " + std::to_string(p) + " vs " + std::to_string(p_cl[n]) + ", flags " +
                    std::to_string(s.flags) + " vs " + std::to_string(s_cl[n].flags);
    }
    std::printf("openpbr OpenCL agreement: %zu items (%zu nonzero evals, %zu delta samples), largest difference %.2g (%.2g with a film), %zu ill-conditioned\n",
                index.size(), nonzero, deltas, worst[0], worst[1], ill_conditioned);
    INFO(failures << " disagreements; the first: " << first);
    CHECK(failures == 0);
    CHECK(ill_conditioned < index.size() / 50);
    CHECK(nonzero > index.size() / 4);
    CHECK(deltas > index.size() / 100);
}
