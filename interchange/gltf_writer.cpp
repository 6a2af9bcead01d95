#include "interchange/gltf_writer.hpp"

#include <nlohmann/json.hpp>

#include "interchange/gltf_mapping.hpp"

namespace interchange {
namespace {

using nlohmann::json;
using brdf::shortest_decimal;

json rgb(const float* c) { return json::array({shortest_decimal(c[0]), shortest_decimal(c[1]), shortest_decimal(c[2])}); }
bool same(const float* a, const float* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }

}  // namespace

json gltf_document(const brdf::Preset& preset, Notes* notes) {
    require_openpbr(preset);
    const brdf::Material& m = preset.material;
    // a parameter at its default needs no note when the reader gives it back by default
    const brdf::Material d = brdf::default_material(BRDF_MODEL_OPENPBR);
    json material;
    material["name"] = preset.name;
    json pbr;
    float base[3];
    for (int c = 0; c < 3; ++c) base[c] = m.base_weight * m.albedo[c];
    if (m.base_weight != 1.0f)
        notes->add("base_weight", "glTF has no base weight: folded into baseColorFactor (the same diffuse and metal colour; read back as base_weight 1)");
    pbr["baseColorFactor"] = {shortest_decimal(base[0]), shortest_decimal(base[1]), shortest_decimal(base[2]), 1.0};
    pbr["metallicFactor"] = shortest_decimal(m.metallic);
    json extensions = json::object();
    if (m.anisotropic != 0.0f) {
        const GltfAnisotropy a = gltf_anisotropy_of(m.roughness, m.anisotropic);
        pbr["roughnessFactor"] = shortest_decimal(a.roughness);
        extensions["KHR_materials_anisotropy"] = {{"anisotropyStrength", shortest_decimal(a.strength)}};
        if (a.clamped)
            notes->add("specular_roughness_anisotropy", "the stretched lobe's alphas leave glTF's range or reach the lab's smallest alpha 1e-4: written as clamped");
    } else {
        pbr["roughnessFactor"] = shortest_decimal(m.roughness);
    }
    material["pbrMetallicRoughness"] = pbr;
    if (m.base_diffuse_roughness != 0.0f)
        notes->add("base_diffuse_roughness", "glTF's diffuse is Lambert: the Oren-Nayar roughness is dropped");

    // specular: glTF scales the whole dielectric Fresnel by specularFactor and its F0 by
    // specularColorFactor; OpenPBR scales F0 through the index and tints the whole reflection
    if (m.specular_weight != 1.0f || !is_grey(m.specular_color, 1.0f)) {
        json specular;
        specular["specularFactor"] = shortest_decimal(m.specular_weight);
        specular["specularColorFactor"] = rgb(m.specular_color);
        extensions["KHR_materials_specular"] = specular;
        if (m.specular_weight != 1.0f)
            notes->add("specular_weight", "written as specularFactor, which scales glTF's whole dielectric Fresnel (OpenPBR scales F0 through the index) and not the metal's");
        if (!is_grey(m.specular_color, 1.0f) && m.metallic < 1.0f)
            notes->add("specular_color", "written as specularColorFactor, which tints glTF's dielectric F0 only (OpenPBR tints the whole dielectric reflection)");
        if (!is_grey(m.specular_color, 1.0f) && m.metallic > 0.0f)
            notes->add("specular_color", "the metal's F82 edge tint: glTF's metal is Schlick's Fresnel of baseColorFactor, without a tint");
    }
    if (m.ior != 1.5f) extensions["KHR_materials_ior"] = {{"ior", shortest_decimal(m.ior)}};

    // glTF tints the transmitted light by baseColorFactor, which the reader gives back as transmission_color
    if (m.weight_transmission != 0.0f) {
        extensions["KHR_materials_transmission"] = {{"transmissionFactor", shortest_decimal(m.weight_transmission)}};
        if (!same(m.transmission_color, base))
            notes->add("transmission_color", "glTF tints the transmitted light by baseColorFactor, not a colour of its own: read back as the base colour");
    } else if (!same(m.transmission_color, d.transmission_color)) {
        notes->add("transmission_color", "transmission_weight is 0: the transmission's tint is not written");
    }

    if (m.subsurface != 0.0f) notes->add("subsurface_weight", "glTF's extensions used here have no subsurface lobe: dropped");
    if (!same(m.subsurface_color, d.subsurface_color)) notes->add("subsurface_color", "no subsurface lobe in glTF: dropped");
    if (m.subsurface_asymmetry != d.subsurface_asymmetry) notes->add("subsurface_scatter_anisotropy", "no subsurface lobe in glTF: dropped");

    if (m.coat_weight != 0.0f || m.coat_roughness != 0.0f) {
        extensions["KHR_materials_clearcoat"] = {{"clearcoatFactor", shortest_decimal(m.coat_weight)},
                                                 {"clearcoatRoughnessFactor", shortest_decimal(m.coat_roughness)}};
    }
    if (!same(m.coat_color, d.coat_color)) notes->add("coat_color", "glTF's clearcoat is colourless: dropped");
    if (m.coat_roughness_anisotropy != 0.0f) notes->add("coat_roughness_anisotropy", "glTF's clearcoat is isotropic: dropped");
    // the reader gives a coat glTF's index 1.5, and no coat the lab's default
    const float coat_ior_read = m.coat_weight != 0.0f ? 1.5f : d.coat_ior;
    if (m.coat_ior != coat_ior_read) notes->add("coat_ior", "glTF's clearcoat has the index 1.5: dropped");
    if (m.coat_darkening != d.coat_darkening) notes->add("coat_darkening", "glTF has no control of the coat's darkening: dropped");

    // glTF's sheen is the same Charlie lobe, alpha = roughness^2; its colour carries the weight
    if (m.fuzz_weight != 0.0f) {
        float sheen[3];
        for (int c = 0; c < 3; ++c) sheen[c] = m.fuzz_weight * m.fuzz_color[c];
        extensions["KHR_materials_sheen"] = {{"sheenColorFactor", rgb(sheen)}, {"sheenRoughnessFactor", shortest_decimal(m.fuzz_roughness)}};
        if (m.fuzz_weight != 1.0f) notes->add("fuzz_weight", "glTF has no sheen weight: folded into sheenColorFactor (read back as fuzz_weight 1)");
    } else {
        if (!same(m.fuzz_color, d.fuzz_color)) notes->add("fuzz_color", "fuzz_weight is 0: the fuzz's colour is not written");
        if (m.fuzz_roughness != d.fuzz_roughness) notes->add("fuzz_roughness", "fuzz_weight is 0: the fuzz's roughness is not written");
    }

    if (m.thin_film_weight != 0.0f) {
        const double nanometres = shortest_decimal(m.thin_film_thickness * kNanometresPerMicrometre);
        extensions["KHR_materials_iridescence"] = {{"iridescenceFactor", shortest_decimal(m.thin_film_weight)},
                                                   {"iridescenceIor", shortest_decimal(m.thin_film_ior)},
                                                   {"iridescenceThicknessMinimum", nanometres},
                                                   {"iridescenceThicknessMaximum", nanometres}};
    } else {
        if (m.thin_film_thickness != d.thin_film_thickness) notes->add("thin_film_thickness", "thin_film_weight is 0: the film's thickness is not written");
        if (m.thin_film_ior != d.thin_film_ior) notes->add("thin_film_ior", "thin_film_weight is 0: the film's index is not written");
    }

    if (m.emission_luminance != 0.0f) {
        material["emissiveFactor"] = rgb(m.emission_color);
        if (m.emission_luminance != 1.0f)
            extensions["KHR_materials_emissive_strength"] = {{"emissiveStrength", shortest_decimal(m.emission_luminance)}};
        if (is_grey(m.emission_color, 0.0f)) notes->add("emission_color", "black: read back as no emission (luminance 0)");
    } else if (!same(m.emission_color, d.emission_color)) {
        notes->add("emission_color", "emission_luminance is 0: the colour is not written");
    }
    if (!m.energy_compensation)
        notes->add("energy_compensation", "glTF has no switch for it: the lab's single-scattering lobes (false) are written as glTF's model");

    if (!extensions.empty()) material["extensions"] = extensions;
    json doc;
    doc["asset"] = {{"version", "2.0"}, {"generator", "dtoadq convert"}};
    if (!extensions.empty()) {
        json used = json::array();
        for (auto it = extensions.begin(); it != extensions.end(); ++it) used.push_back(it.key());
        doc["extensionsUsed"] = used;
    }
    doc["materials"] = json::array({material});
    return doc;
}

std::string gltf_text(const brdf::Preset& preset, Notes* notes) { return gltf_document(preset, notes).dump(2) + "\n"; }

}  // namespace interchange
