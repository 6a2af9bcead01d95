#include "fit/fit_space.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "brdf/host/parameters.hpp"
#include "common/input_error.hpp"

namespace lab::fit {
namespace {

const brdf::ScalarParameter& table_entry(const std::string& key) {
    for (const brdf::ScalarParameter& p : brdf::scalar_parameters())
        if (key == p.key) return p;
    throw std::logic_error("fit: no parameter " + key + " in the parameter table");
}

FitParameter bounded(const std::string& name, const std::string& key) {
    const brdf::ScalarParameter& p = table_entry(key);
    return {name, double(p.min), double(p.max)};
}

// Below alpha BRDF_SMOOTH_ALPHA the glossy lobe is a delta, which a table cannot hold and the
// optimiser would see as a cliff; the search starts just above it.
double roughness_floor() { return 1.01 * std::sqrt(double(BRDF_SMOOTH_ALPHA)); }

// Glossy alone: a conductor whose F0 is the albedo (metallic 1), the only way its colour and
// strength are both free. Diffuse and glossy: albedo, Fresnel F0 and metallic all fitted.
bool conductor_only(const FitSpace& s) { return s.glossy && !s.diffuse; }

FitParameter openpbr_bounded(const std::string& name, const std::string& key) {
    for (const brdf::ScalarParameter& p : brdf::openpbr_parameters())
        if (key == p.key) return {name, double(p.min), double(p.max)};
    throw std::logic_error("fit: no parameter " + key + " in the openpbr table");
}

// The openpbr space's parameters: the base colour, the specular's roughness, the metalness and the
// dielectric's index (its F0), and the stretch when anisotropic.
std::vector<FitParameter> openpbr_fit_parameters(const FitSpace& s) {
    std::vector<FitParameter> p;
    for (const char* c : {"base_color_r", "base_color_g", "base_color_b"}) p.push_back(openpbr_bounded(c, "base_color"));
    FitParameter r = openpbr_bounded("specular_roughness", "specular_roughness");
    r.min = std::fmax(r.min, roughness_floor());
    p.push_back(r);
    p.push_back(openpbr_bounded("base_metalness", "base_metalness"));
    p.push_back(openpbr_bounded("specular_ior", "specular_ior"));
    if (s.anisotropic) p.push_back(openpbr_bounded("specular_roughness_anisotropy", "specular_roughness_anisotropy"));
    return p;
}

}  // namespace

void parse_lobes(const std::string& text, FitSpace* space) {
    FitSpace s = *space;
    s.diffuse = s.glossy = s.retroreflection = s.subsurface = false;
    std::stringstream in(text);
    std::string name;
    int count = 0;
    while (std::getline(in, name, ',')) {
        ++count;
        if (name == "diffuse") s.diffuse = true;
        else if (name == "glossy") s.glossy = true;
        else if (name == "retroreflection") s.retroreflection = true;
        else if (name == "subsurface") s.subsurface = true;
        else if (name == "specular" || name == "transmission")
            throw InputError("command line", "--lobes", "\"" + name + "\" cannot be fitted: a reflectance table holds no delta or transmitted light");
        else
            throw InputError("command line", "--lobes", "unknown lobe \"" + name + "\" (expected diffuse, glossy, retroreflection, subsurface)");
    }
    if (count == 0 || (!s.diffuse && !s.glossy))
        throw InputError("command line", "--lobes", "needs diffuse or glossy, got \"" + text + "\"");
    if ((s.retroreflection || s.subsurface) && !s.diffuse)
        throw InputError("command line", "--lobes", "retroreflection and subsurface blend into the diffuse lobe: add diffuse");
    *space = s;
}

std::vector<FitParameter> fit_parameters(const FitSpace& s) {
    if (s.openpbr) return openpbr_fit_parameters(s);
    std::vector<FitParameter> p;
    const char* channel[3] = {"albedo_r", "albedo_g", "albedo_b"};
    for (const char* c : channel) p.push_back(bounded(c, "albedo"));
    if (s.glossy) {
        FitParameter r = bounded("roughness", "roughness");
        r.min = std::fmax(r.min, roughness_floor());
        p.push_back(r);
        if (!conductor_only(s)) {
            p.push_back(bounded("glossy_share", "lobes.glossy"));
            p.push_back(bounded("fresnel", "fresnel"));
            p.push_back(bounded("metallic", "metallic"));
        }
        if (s.distribution == BRDF_DISTRIBUTION_HYPER_CAUCHY) {
            // searched as 1 / g: the tails change about evenly in it (g = 2 is GGX, 1 / g -> 0 Beckmann),
            // where in g itself all of [1.6, 4] is a sliver of the range, and BOBYQA crawled there
            const FitParameter g = bounded("hc_shape", "hc_shape");
            p.push_back({"hc_inverse_shape", 1.0 / g.max, 1.0 / g.min});
        }
        if (s.anisotropic) p.push_back(bounded("anisotropic", "anisotropic"));
    }
    if (s.retroreflection) p.push_back(bounded("retroreflection", "retroreflection"));
    if (s.subsurface) {
        p.push_back(bounded("subsurface", "subsurface"));
        p.push_back(bounded("subsurface_asymmetry", "subsurface_asymmetry"));
    }
    return p;
}

brdf::Material material_from_parameters(const FitSpace& s, const std::vector<double>& x) {
    if (s.openpbr) {
        if (x.size() != openpbr_fit_parameters(s).size()) throw std::logic_error("fit: parameter vector of the wrong length");
        brdf::Material m = brdf::default_material(BRDF_MODEL_OPENPBR);
        for (int c = 0; c < 3; ++c) m.albedo[c] = float(x[c]);
        m.roughness = float(x[3]);
        m.metallic = float(x[4]);
        m.ior = float(x[5]);
        if (s.anisotropic) m.anisotropic = float(x[6]);
        return m;
    }
    brdf::Material m = brdf::default_material();
    m.model = BRDF_MODEL_LAB;
    m.distribution = s.distribution;
    m.energy_compensation = 1;
    m.weight_specular = m.weight_transmission = 0.0f;
    m.weight_diffuse = s.diffuse ? 1.0f : 0.0f;
    m.weight_glossy = s.glossy ? 1.0f : 0.0f;
    m.metallic = conductor_only(s) ? 1.0f : 0.0f;
    m.anisotropic = 0.0f;
    m.retroreflection = m.subsurface = 0.0f;
    size_t i = 0;
    for (int c = 0; c < 3; ++c) m.albedo[c] = float(x.at(i++));
    if (s.glossy) {
        m.roughness = float(x.at(i++));
        if (!conductor_only(s)) {
            // one share rather than two weights: the model normalises the weights by their sum
            const float share = float(x.at(i++));
            m.weight_glossy = share;
            m.weight_diffuse = 1.0f - share;
            m.fresnel = float(x.at(i++));
            m.metallic = float(x.at(i++));
        }
        if (s.distribution == BRDF_DISTRIBUTION_HYPER_CAUCHY) m.hc_shape = float(1.0 / x.at(i++));
        if (s.anisotropic) m.anisotropic = float(x.at(i++));
    }
    if (s.retroreflection) m.retroreflection = float(x.at(i++));
    if (s.subsurface) {
        m.subsurface = float(x.at(i++));
        m.subsurface_asymmetry = float(x.at(i++));
    }
    if (i != x.size()) throw std::logic_error("fit: parameter vector of the wrong length");
    return m;
}

std::vector<double> parameters_from_material(const FitSpace& s, const brdf::Material& m) {
    std::vector<double> x;
    if (s.openpbr) {
        x = {m.albedo[0], m.albedo[1], m.albedo[2], m.roughness, m.metallic, m.ior};
        if (s.anisotropic) x.push_back(m.anisotropic);
        return x;
    }
    for (int c = 0; c < 3; ++c) x.push_back(m.albedo[c]);
    if (s.glossy) {
        x.push_back(m.roughness);
        if (!conductor_only(s)) {
            const double sum = double(m.weight_diffuse) + double(m.weight_glossy);
            x.push_back(sum > 0.0 ? m.weight_glossy / sum : 0.0);
            x.push_back(m.fresnel);
            x.push_back(m.metallic);
        }
        if (s.distribution == BRDF_DISTRIBUTION_HYPER_CAUCHY) x.push_back(1.0 / m.hc_shape);
        if (s.anisotropic) x.push_back(m.anisotropic);
    }
    if (s.retroreflection) x.push_back(m.retroreflection);
    if (s.subsurface) {
        x.push_back(m.subsurface);
        x.push_back(m.subsurface_asymmetry);
    }
    return x;
}

}  // namespace lab::fit
