#include "brdf/host/parameters.hpp"

namespace brdf {

const char* model_name(int model) {
    if (model == BRDF_MODEL_MEASURED) return "measured";
    return model == BRDF_MODEL_DTOADQ2017 ? "dtoadq2017" : "lab";
}

const char* distribution_name(int distribution) {
    return distribution == BRDF_DISTRIBUTION_HYPER_CAUCHY ? "hyper_cauchy" : "ggx";
}

Material default_material() {
    Material m{};
    for (const ScalarParameter& p : scalar_parameters()) {
        if (p.field)
            m.*p.field = p.fallback * p.to_material;
        else
            m.albedo[0] = m.albedo[1] = m.albedo[2] = p.fallback;
    }
    m.model = BRDF_MODEL_LAB;
    m.distribution = BRDF_DISTRIBUTION_GGX;
    // the lab model gives back the energy single scattering loses (docs/materials.md); the tables are
    // conservative, so the compensated lobes stay within energy conservation (validation/energy_tables.hpp)
    m.energy_compensation = 1;
    return m;
}

}  // namespace brdf
