// What a fit may change: the lab model's parameters for the chosen distribution and lobes, as a
// vector bounded by the parameter table's ranges (brdf/host/parameters.hpp). Everything else keeps
// its default; the model is the lab's, with energy compensation on (the fit targets what renders).
#pragma once

#include <string>
#include <vector>

#include "brdf/brdf.hpp"

namespace lab::fit {

struct FitSpace {
    // the model fitted: the lab's (the default), or openpbr's (base_color, specular_roughness,
    // base_metalness, specular_ior and, when anisotropic, specular_roughness_anisotropy, under
    // OpenPBR's names and ranges; GGX only; interchange/fit_to_openpbr.hpp)
    bool openpbr = false;
    int distribution = BRDF_DISTRIBUTION_GGX;
    bool anisotropic = false;  // fit the anisotropy too (the tangent stays at rotation 0)
    bool diffuse = true, glossy = true;
    bool retroreflection = false, subsurface = false;  // blends inside the diffuse lobe
};

// One fitted parameter: its name and its bounds. The names are the preset's keys, except
// "glossy_share" (weight_glossy / (weight_diffuse + weight_glossy)) and "hc_inverse_shape" (1 / hc_shape).
struct FitParameter {
    std::string name;
    double min, max;
};

// "diffuse,glossy,retroreflection,subsurface" (any non-empty subset holding diffuse or glossy).
// Throws lab::InputError("command line", "--lobes", ...) naming the bad entry.
void parse_lobes(const std::string& text, FitSpace* space);

// The parameters of `space`, in the order of the vectors below.
std::vector<FitParameter> fit_parameters(const FitSpace& space);

// The material a parameter vector stands for (every other field at its default).
brdf::Material material_from_parameters(const FitSpace& space, const std::vector<double>& x);

// The vector of a material inside the space (the round-trip tests' truth; material_from_parameters
// gives it back for a material of the space's form).
std::vector<double> parameters_from_material(const FitSpace& space, const brdf::Material& m);

}  // namespace lab::fit
