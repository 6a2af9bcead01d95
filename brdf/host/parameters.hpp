// The table of material parameters: key, range, default, meaning. One table serves the preset
// loader, the validation sweeps, the fit's parameter space, the viewer's material panel and the
// range table of docs/materials.md (which the tests check against it). The lab and dtoadq2017
// models read scalar_parameters(); the openpbr model reads openpbr_parameters(), OpenPBR Surface
// 1.1's inputs under their own names, defaults and ranges (open_pbr_surface.mtlx), flat keys.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "brdf/brdf.hpp"

namespace brdf {

struct ScalarParameter {
    const char* key;       // JSON key; "lobes.x" lives in the "lobes" object
    float Material::*field;
    float min, max;        // in JSON units
    float fallback;        // default when a preset leaves the key out
    float to_material;     // JSON value times this is stored (degrees to radians)
    const char* unit;
    const char* meaning;
    float (Material::*color)[3] = nullptr;  // a colour (field is null): an array of 3 in JSON, each in [min, max]
    const char* group = "";                 // openpbr: OpenPBR's group (base, specular, coat, ...) for the viewer
};

inline constexpr float kDegrees = 3.14159265358979323846f / 180.0f;

inline const std::array<ScalarParameter, 15>& scalar_parameters() {
    static const std::array<ScalarParameter, 15> table{{
        {"roughness", &Material::roughness, 0.0f, 1.0f, 0.5f, 1.0f, "",
         "perceptual roughness; microfacet alpha = roughness^2 (below alpha 1e-3 the lobes are smooth deltas)"},
        {"metallic", &Material::metallic, 0.0f, 1.0f, 0.0f, 1.0f, "",
         "0 dielectric, 1 conductor: F0 moves from `fresnel` to albedo; diffuse weight moves to glossy, transmission to mirror"},
        {"fresnel", &Material::fresnel, 0.0f, 1.0f, 0.04f, 1.0f, "",
         "reflectance at normal incidence of the dielectric part (0.04 for ior 1.5)"},
        {"subsurface", &Material::subsurface, 0.0f, 1.0f, 0.0f, 1.0f, "",
         "diffuse lobe blend: 0 Lambert/Disney, 1 Henyey-Greenstein single scattering"},
        {"subsurface_asymmetry", &Material::subsurface_asymmetry, -BRDF_ASYMMETRY_MAX, BRDF_ASYMMETRY_MAX, -0.3f, 1.0f, "",
         "Henyey-Greenstein g of the subsurface lobe; negative scatters back to the light"},
        {"retroreflection", &Material::retroreflection, 0.0f, 1.0f, 0.0f, 1.0f, "",
         "diffuse lobe blend: 0 Lambert, 1 Disney's diffuse Fresnel factor (energy-bounded)"},
        {"anisotropic", &Material::anisotropic, 0.0f, 1.0f, 0.0f, 1.0f, "",
         "stretch of the microfacet distribution: alpha_x = alpha/aspect, alpha_y = alpha*aspect, aspect = sqrt(1 - 0.9 anisotropic)"},
        {"tangent_rotation", &Material::tangent_rotation, -360.0f, 360.0f, 0.0f, kDegrees, "degrees",
         "rotation of the anisotropy tangent about the normal"},
        {"hc_shape", &Material::hc_shape, BRDF_HC_SHAPE_MIN, BRDF_HC_SHAPE_MAX, 2.0f, 1.0f, "",
         "Hyper-Cauchy shape g: 2 equals GGX, lower has longer tails, higher tends to Beckmann"},
        {"ior", &Material::ior, BRDF_IOR_MIN, BRDF_IOR_MAX, 1.5f, 1.0f, "",
         "index of refraction of the transmissive lobe (inside over outside)"},
        {"lobes.diffuse", &Material::weight_diffuse, 0.0f, 1.0f, 1.0f, 1.0f, "",
         "relative weight of the diffuse lobe"},
        {"lobes.glossy", &Material::weight_glossy, 0.0f, 1.0f, 0.0f, 1.0f, "",
         "relative weight of the glossy (microfacet reflection) lobe"},
        {"lobes.specular", &Material::weight_specular, 0.0f, 1.0f, 0.0f, 1.0f, "",
         "relative weight of the mirror lobe"},
        {"lobes.transmission", &Material::weight_transmission, 0.0f, 1.0f, 0.0f, 1.0f, "",
         "relative weight of the dielectric (reflect + refract) lobe"},
        {"albedo", nullptr, 0.0f, 1.0f, 0.8f, 1.0f, "linear RGB",
         "base colour: diffuse reflectance, conductor F0, transmission tint; an array of 3"},
    }};
    return table;
}

// OpenPBR Surface 1.1's inputs that the lab evaluates (brdf/openpbr_model.h), in OpenPBR's groups and
// order. Inputs it leaves out (transmission_depth and scatter, dispersion, subsurface_radius,
// geometry_*): docs/materials.md.
const std::vector<ScalarParameter>& openpbr_parameters();

// The table a material of `model` takes its keys from: openpbr_parameters() or scalar_parameters().
std::vector<ScalarParameter> parameters_of_model(int model);

// Enumerated parameters and their spellings.
const char* model_name(int model);
const char* distribution_name(int distribution);

// A material with every parameter at its default (lab's table; openpbr's takes OpenPBR's defaults).
Material default_material(int model = BRDF_MODEL_LAB);

}  // namespace brdf
