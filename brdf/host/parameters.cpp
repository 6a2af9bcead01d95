#include "brdf/host/parameters.hpp"

namespace brdf {

const char* model_name(int model) {
    if (model == BRDF_MODEL_MEASURED) return "measured";
    if (model == BRDF_MODEL_OPENPBR) return "openpbr";
    return model == BRDF_MODEL_DTOADQ2017 ? "dtoadq2017" : "lab";
}

const char* distribution_name(int distribution) {
    return distribution == BRDF_DISTRIBUTION_HYPER_CAUCHY ? "hyper_cauchy" : "ggx";
}

const std::vector<ScalarParameter>& openpbr_parameters() {
    using M = Material;
    auto scalar = [](const char* group, const char* key, float M::*field, float lo, float hi, float fallback, const char* unit,
                     const char* meaning) { return ScalarParameter{key, field, lo, hi, fallback, 1.0f, unit, meaning, nullptr, group}; };
    auto color = [](const char* group, const char* key, float (M::*field)[3], float fallback, const char* meaning) {
        return ScalarParameter{key, nullptr, 0.0f, 1.0f, fallback, 1.0f, "linear RGB", meaning, field, group};
    };
    static const std::vector<ScalarParameter> table{
        scalar("base", "base_weight", &M::base_weight, 0.0f, 1.0f, 1.0f, "", "multiplier on the diffuse and metal base's reflection"),
        color("base", "base_color", &M::albedo, 0.8f, "colour of the diffuse reflection and the metal's F0"),
        scalar("base", "base_diffuse_roughness", &M::base_diffuse_roughness, 0.0f, 1.0f, 0.0f, "",
               "roughness of the energy-preserving Oren-Nayar diffuse (0 Lambert)"),
        scalar("base", "base_metalness", &M::metallic, 0.0f, 1.0f, 0.0f, "", "mix from the dielectric base (0) to the F82-tint metal (1)"),
        scalar("specular", "specular_weight", &M::specular_weight, 0.0f, 1.0f, 1.0f, "",
               "scales the dielectric's F0 (through its index) and the metal's Fresnel"),
        color("specular", "specular_color", &M::specular_color, 1.0f, "metal: the F82 edge tint; dielectric: tint of its reflection"),
        scalar("specular", "specular_roughness", &M::roughness, 0.0f, 1.0f, 0.3f, "",
               "GGX roughness of the metal and dielectric specular; alpha = roughness^2"),
        scalar("specular", "specular_roughness_anisotropy", &M::anisotropic, 0.0f, 1.0f, 0.0f, "",
               "OpenPBR's stretch: alpha_t = alpha sqrt(2 / (1 + (1 - a)^2)), alpha_b = (1 - a) alpha_t"),
        scalar("specular", "specular_ior", &M::ior, BRDF_IOR_MIN, BRDF_IOR_MAX, 1.5f, "", "index of refraction of the dielectric base"),
        scalar("transmission", "transmission_weight", &M::weight_transmission, 0.0f, 1.0f, 0.0f, "",
               "mix from the opaque dielectric base to the rough dielectric interface (reflection and refraction)"),
        color("transmission", "transmission_color", &M::transmission_color, 1.0f,
              "tint of the transmissive interface at the surface (no participating medium: transmission_depth 0)"),
        scalar("subsurface", "subsurface_weight", &M::subsurface, 0.0f, 1.0f, 0.0f, "",
               "mix from the diffuse to the subsurface lobe (Henyey-Greenstein single scattering)"),
        color("subsurface", "subsurface_color", &M::subsurface_color, 0.8f, "albedo of the subsurface lobe"),
        scalar("subsurface", "subsurface_scatter_anisotropy", &M::subsurface_asymmetry, -BRDF_ASYMMETRY_MAX, BRDF_ASYMMETRY_MAX, 0.0f, "",
               "Henyey-Greenstein g of the subsurface lobe (OpenPBR allows [-1, 1])"),
        scalar("coat", "coat_weight", &M::coat_weight, 0.0f, 1.0f, 0.0f, "", "presence of the dielectric clear coat"),
        color("coat", "coat_color", &M::coat_color, 1.0f, "transmittance of the coat at normal incidence, both ways (absorption)"),
        scalar("coat", "coat_roughness", &M::coat_roughness, 0.0f, 1.0f, 0.0f, "", "GGX roughness of the coat; it also roughens the specular below"),
        scalar("coat", "coat_roughness_anisotropy", &M::coat_roughness_anisotropy, 0.0f, 1.0f, 0.0f, "", "the coat's stretch, mapped as the specular's"),
        scalar("coat", "coat_ior", &M::coat_ior, BRDF_IOR_MIN, BRDF_IOR_MAX, 1.6f, "", "index of refraction of the coat"),
        scalar("coat", "coat_darkening", &M::coat_darkening, 0.0f, 1.0f, 1.0f, "", "how much of the coat's internal-reflection darkening applies"),
        scalar("fuzz", "fuzz_weight", &M::fuzz_weight, 0.0f, 1.0f, 0.0f, "", "presence of the fuzz (sheen) layer on top"),
        color("fuzz", "fuzz_color", &M::fuzz_color, 1.0f, "colour of the fuzz"),
        scalar("fuzz", "fuzz_roughness", &M::fuzz_roughness, 0.0f, 1.0f, 0.5f, "", "roughness of the fuzz's fibres (Charlie sheen)"),
        scalar("thin film", "thin_film_weight", &M::thin_film_weight, 0.0f, 1.0f, 0.0f, "", "coverage of the thin film on the dielectric specular and the metal"),
        scalar("thin film", "thin_film_thickness", &M::thin_film_thickness, 0.0f, BRDF_THIN_FILM_THICKNESS_MAX, 0.5f, "micrometres",
               "thickness of the film"),
        scalar("thin film", "thin_film_ior", &M::thin_film_ior, BRDF_IOR_MIN, BRDF_IOR_MAX, 1.4f, "", "index of refraction of the film"),
        scalar("emission", "emission_luminance", &M::emission_luminance, 0.0f, BRDF_EMISSION_LUMINANCE_MAX, 0.0f, "nits",
               "luminance of the light the surface emits on its outer side: radiance emission_luminance emission_color in the renderer's units (1 = 1 nit of white)"),
        color("emission", "emission_color", &M::emission_color, 1.0f, "colour of the emitted light (multiplies emission_luminance)"),
    };
    return table;
}

std::vector<ScalarParameter> parameters_of_model(int model) {
    if (model == BRDF_MODEL_OPENPBR) return openpbr_parameters();
    return std::vector<ScalarParameter>(scalar_parameters().begin(), scalar_parameters().end());
}

Material default_material(int model) {
    Material m{};
    for (const ScalarParameter& p : scalar_parameters()) {
        if (p.field)
            m.*p.field = p.fallback * p.to_material;
        else
            m.albedo[0] = m.albedo[1] = m.albedo[2] = p.fallback;
    }
    // every model's struct holds OpenPBR's inputs at their defaults; the fields it shares with the lab
    // model's keep the lab's defaults unless the material is an openpbr one
    auto lab_sets = [](const ScalarParameter& q) {
        for (const ScalarParameter& p : scalar_parameters())
            if (q.field ? p.field == q.field : (p.field == nullptr && q.color == &Material::albedo)) return true;
        return false;
    };
    for (const ScalarParameter& p : openpbr_parameters()) {
        if (model != BRDF_MODEL_OPENPBR && lab_sets(p)) continue;
        if (p.field)
            m.*p.field = p.fallback;
        else
            for (float& c : m.*p.color) c = p.fallback;
    }
    m.model = model;
    m.distribution = BRDF_DISTRIBUTION_GGX;
    // the lab model gives back the energy single scattering loses (docs/materials.md); the tables are
    // conservative, so the compensated lobes stay within energy conservation (validation/energy_tables.hpp)
    m.energy_compensation = 1;
    return m;
}

}  // namespace brdf
