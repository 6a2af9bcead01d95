// Robustness sweep: over 10^6 random and edge inputs (parameters at the ends of their ranges or not
// numbers at all, directions at the horizon, at the poles, equal, opposite, mirrored, below the
// surface) eval, pdf and sample never return NaN, infinity or negative values, and a successful
// sample's direction is unit length.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "brdf/brdf.hpp"
#include "validation/random_inputs.hpp"

using namespace lab::validation;
using brdf::float3;

namespace {

// A random direction, or one of the cases that break naive formulas.
float3 edge_direction(UniformRandom& rng) {
    float phi = rng.uniform(0.0f, 6.2831853f);
    float c = std::cos(phi), s = std::sin(phi);
    switch (rng.next_bits() % 8) {
        case 0: return float3(c, s, 0.0f);                                  // exactly at the horizon
        case 1: return float3(0.0f, 0.0f, rng.next_float() < 0.5f ? 1.0f : -1.0f);  // a pole
        case 2: {                                                             // grazing, either side
            float z = (rng.next_float() < 0.5f ? 1.0f : -1.0f) * std::pow(10.0f, rng.uniform(-7.0f, -2.0f));
            float r = std::sqrt(1.0f - z * z);
            return float3(r * c, r * s, z);
        }
        case 3: return float3(1.0f, 0.0f, 0.0f);                             // along the tangent
        default: return uniform_sphere_direction(rng);
    }
}

float edge_uniform(UniformRandom& rng) {
    switch (rng.next_bits() % 6) {
        case 0: return 0.0f;
        case 1: return 0.99999994f;  // the largest float below 1
        default: return rng.next_float();
    }
}

// Some parameters not numbers or infinite: the entry points clamp the material, which must tame them.
void poison(brdf::Material* m, UniformRandom& rng) {
    const float bad[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                         -std::numeric_limits<float>::infinity(), -1.0f, 1e30f};
    float* fields[] = {&m->albedo[0], &m->roughness, &m->metallic, &m->fresnel, &m->subsurface, &m->subsurface_asymmetry,
                       &m->retroreflection, &m->anisotropic, &m->tangent_rotation, &m->hc_shape, &m->weight_diffuse,
                       &m->weight_glossy, &m->weight_specular, &m->weight_transmission, &m->ior};
    *fields[rng.next_bits() % 15] = bad[rng.next_bits() % 5];
}

bool bad_value(float3 v) { return !brdf::finite3(v) || v.x < 0.0f || v.y < 0.0f || v.z < 0.0f; }
bool bad_value(float v) { return !std::isfinite(v) || v < 0.0f; }

std::string describe(const brdf::Material& m, float3 wo, float3 wi) {
    std::ostringstream s;
    s << "model " << m.model << " dist " << m.distribution << " albedo " << m.albedo[0] << " roughness " << m.roughness
      << " metallic " << m.metallic << " fresnel " << m.fresnel << " subsurface " << m.subsurface << " g "
      << m.subsurface_asymmetry << " retro " << m.retroreflection << " aniso " << m.anisotropic << " rotation "
      << m.tangent_rotation << " shape " << m.hc_shape << " lobes " << m.weight_diffuse << " " << m.weight_glossy << " "
      << m.weight_specular << " " << m.weight_transmission << " ior " << m.ior << "; wo (" << wo.x << ", " << wo.y << ", "
      << wo.z << ") wi (" << wi.x << ", " << wi.y << ", " << wi.z << ")";
    return s.str();
}

}  // namespace

TEST_CASE("robustness: eval, pdf and sample never return NaN, infinity or negative values", "[robustness]") {
    auto start = std::chrono::steady_clock::now();
    UniformRandom rng(4242);
    const long cases = 1000000;
    long failures = 0;
    std::string first;
    for (long i = 0; i < cases; ++i) {
        int model = i % 8 == 0 ? BRDF_MODEL_DTOADQ2017 : BRDF_MODEL_LAB;
        brdf::Material m = random_edge_material(rng, model, 0.3f);
        if (i % 4 == 1) m.weight_diffuse = m.weight_glossy = m.weight_specular = m.weight_transmission = 0.0f;
        if (i % 50 == 7) poison(&m, rng);
        float3 wo = edge_direction(rng), wi;
        switch (rng.next_bits() % 6) {
            case 0: wi = wo; break;
            case 1: wi = -wo; break;
            case 2: wi = float3(-wo.x, -wo.y, wo.z); break;  // the mirror direction
            default: wi = edge_direction(rng); break;
        }
        float3 u(edge_uniform(rng), edge_uniform(rng), edge_uniform(rng));

        const char* what = nullptr;
        float3 f = brdf::bsdf_eval(&m, wo, wi);
        float pdf = brdf::bsdf_pdf(&m, wo, wi);
        brdf::BsdfSample s = brdf::bsdf_sample(&m, wo, u);
        if (bad_value(f)) what = "eval";
        else if (bad_value(pdf)) what = "pdf";
        else if (s.flags != 0 && (bad_value(s.f) || !(s.pdf > 0.0f) || !std::isfinite(s.pdf))) what = "sample value";
        else if (s.flags != 0 && !(std::fabs(brdf::length(s.wi) - 1.0f) <= 1e-4f)) what = "sample direction";
        if (what) {
            if (failures++ == 0) {
                std::ostringstream out;
                out << what << " at case " << i << ": " << describe(m, wo, wi) << "; f (" << f.x << ", " << f.y << ", " << f.z
                    << ") pdf " << pdf << "; sample flags " << s.flags << " wi (" << s.wi.x << ", " << s.wi.y << ", "
                    << s.wi.z << ") pdf " << s.pdf << " f " << s.f.x;
                first = out.str();
            }
        }
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("robustness: %ld cases, %ld failures, %.1f s\n", cases, failures, seconds);
    INFO("first failure: " << first);
    CHECK(failures == 0);
}
