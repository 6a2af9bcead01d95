#include "brdf/host/features.hpp"

namespace brdf {

namespace {

struct Needs {
    bool lab = false, dtoadq2017 = false, measured = false, openpbr = false, diffuse = false, retroreflection = false, subsurface = false,
         glossy = false, transmission = false, coat = false, fuzz = false, thin_film = false, emission = false, energy_compensation = false, ggx = false,
         hyper_cauchy = false;
};

void add_distribution(const Microfacet& mf, Needs* needs) {
    if (mf.kind == BRDF_DISTRIBUTION_HYPER_CAUCHY) needs->hyper_cauchy = true;
    else needs->ggx = true;
}

// Mirrors the branches of openpbr_eval / openpbr_pdf / openpbr_sample (brdf/openpbr_model.h).
void add_openpbr(const Material& m, Needs* needs) {
    needs->openpbr = true;
    OpenPbr p = openpbr_setup(&m, bsdf_tables(), float3(0.0f, 0.0f, 1.0f));
    needs->fuzz = needs->fuzz || m.fuzz_weight > 0.0f;
    needs->coat = needs->coat || m.coat_weight > 0.0f;
    needs->emission = needs->emission || material_emits(&m);
    if (m.coat_weight > 0.0f && !p.coat_smooth) needs->ggx = true;
    if (p.metal > 0.0f) {
        if (!p.specular_smooth) needs->ggx = true;
        needs->energy_compensation = needs->energy_compensation || p.metal_compensated;
        needs->thin_film = needs->thin_film || (m.thin_film_weight > 0.0f && m.thin_film_thickness > 0.0f);
    }
    if (p.opaque > 0.0f) {
        if (!p.specular_smooth) needs->ggx = true;
        needs->thin_film = needs->thin_film || m.thin_film_weight > 0.0f;
        needs->diffuse = needs->diffuse || m.subsurface < 1.0f;
        needs->subsurface = needs->subsurface || m.subsurface > 0.0f;
    }
    if (p.glass > 0.0f) {
        needs->transmission = true;
        if (!p.glass_smooth) needs->ggx = true;
        needs->energy_compensation = needs->energy_compensation || p.glass_compensated;
    }
}

// Mirrors the branches of lab_eval / lab_pdf / lab_sample: a feature is needed exactly when one of
// its branches can be taken for this material.
void add_material(const Material& input, Needs* needs) {
    Material m = material_clamped(&input);
    if (m.model == BRDF_MODEL_OPENPBR) {
        add_openpbr(m, needs);
        return;
    }
    if (m.model == BRDF_MODEL_DTOADQ2017) {
        needs->dtoadq2017 = true;
        return;
    }
    if (m.model == BRDF_MODEL_MEASURED) {
        needs->measured = true;
        return;
    }
    needs->lab = true;
    LobeWeights w = lab_lobe_weights(&m);
    Microfacet mf = microfacet_from_material(&m);
    if (w.diffuse > 0.0f) {
        needs->diffuse = true;
        needs->retroreflection = needs->retroreflection || m.retroreflection > 0.0f;
        needs->subsurface = needs->subsurface || m.subsurface > 0.0f;
    }
    if (w.glossy > 0.0f) {
        needs->glossy = true;
        if (!microfacet_is_smooth(mf)) add_distribution(mf, needs);
        needs->energy_compensation = needs->energy_compensation || lab_glossy_compensated(&m, mf);
    }
    if (w.transmission > 0.0f) {
        needs->transmission = true;
        if (!lab_transmission_is_smooth(&m, mf)) add_distribution(mf, needs);
        needs->energy_compensation = needs->energy_compensation || lab_dielectric_compensated(&m, mf);
    }
}

}  // namespace

std::vector<std::pair<std::string, bool>> used_features(const std::vector<Material>& materials) {
    Needs n;
    for (const Material& m : materials) add_material(m, &n);
    return {{"BRDF_FEATURE_LAB_MODEL", n.lab},
            {"BRDF_FEATURE_DTOADQ2017", n.dtoadq2017},
            {"BRDF_FEATURE_MEASURED", n.measured},
            {"BRDF_FEATURE_OPENPBR", n.openpbr},
            {"BRDF_FEATURE_DIFFUSE", n.diffuse},
            {"BRDF_FEATURE_RETROREFLECTION", n.retroreflection},
            {"BRDF_FEATURE_SUBSURFACE", n.subsurface},
            {"BRDF_FEATURE_GLOSSY", n.glossy},
            {"BRDF_FEATURE_TRANSMISSION", n.transmission},
            {"BRDF_FEATURE_COAT", n.coat},
            {"BRDF_FEATURE_FUZZ", n.fuzz},
            {"BRDF_FEATURE_THIN_FILM", n.thin_film},
            {"BRDF_FEATURE_EMISSION", n.emission},
            {"BRDF_FEATURE_ENERGY_COMPENSATION", n.energy_compensation},
            {"BRDF_FEATURE_GGX", n.ggx},
            {"BRDF_FEATURE_HYPER_CAUCHY", n.hyper_cauchy}};
}

std::string feature_defines(const std::vector<Material>& materials) {
    std::string out;
    for (const auto& [name, on] : used_features(materials)) out += "#define " + name + (on ? " 1\n" : " 0\n");
    return out;
}

std::string feature_build_options(const std::vector<Material>& materials) {
    std::string out;
    for (const auto& [name, on] : used_features(materials)) out += (out.empty() ? "-D" : " -D") + name + (on ? "=1" : "=0");
    return out;
}

}  // namespace brdf
