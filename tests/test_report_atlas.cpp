// The stability atlas's premise (report/stability_atlas.hpp): its white conductor loses what
// single scattering loses, against an independent integration, and energy compensation gives it
// back. The reference value, E = 0.3068 for GGX at alpha = 1 (roughness 1) at normal incidence with
// F = 1, is 2e6 uniform-hemisphere samples of D G2 / (4 cos_o) cos_i in NumPy, written apart from
// the lab's code (its own standard error about 5e-4).
#include <catch2/catch.hpp>

#include <algorithm>

#include "brdf/host/angles.hpp"
#include "report/stability_atlas.hpp"
#include "validation/albedo.hpp"

TEST_CASE("Stability atlas: the white conductor's single-scattering albedo matches an independent integration", "[report]") {
    const brdf::float3 normal = brdf::direction_from_degrees(0.0f, 0.0f);
    const lab::validation::AlbedoEstimate single =
        lab::validation::directional_albedo(lab::report::atlas_white_conductor(BRDF_MODEL_LAB, 1.0f, false), normal, 64);
    CHECK(single.value.x == Approx(0.3068).margin(4.0 * single.std_error.x + 2e-3));
    const lab::validation::AlbedoEstimate compensated =
        lab::validation::directional_albedo(lab::report::atlas_white_conductor(BRDF_MODEL_LAB, 1.0f, true), normal, 64);
    CHECK(compensated.value.x == Approx(1.0).margin(4.0 * compensated.std_error.x + 5e-3));
    // the 2017 model creates energy there (docs/dtoadq2017.md): the atlas must show it above 1
    const lab::validation::AlbedoEstimate old =
        lab::validation::directional_albedo(lab::report::atlas_white_conductor(BRDF_MODEL_DTOADQ2017, 0.35f, false),
                                            brdf::direction_from_degrees(80.0f, 0.0f), 64);
    CHECK(old.value.x > 1.0 + 4.0 * old.std_error.x);
}
