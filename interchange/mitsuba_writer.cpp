#include "interchange/mitsuba_writer.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <pugixml.hpp>

#include "interchange/base_mix.hpp"

namespace interchange {
namespace {

void add_value(pugi::xml_node bsdf, const char* kind, const char* name, const std::string& value) {
    pugi::xml_node n = bsdf.append_child(kind);
    n.append_attribute("name") = name;
    n.append_attribute("value") = value.c_str();
}
void add_float(pugi::xml_node bsdf, const char* name, float v) { add_value(bsdf, "float", name, float_text(v)); }
void add_rgb(pugi::xml_node bsdf, const char* name, const float* c) {
    add_value(bsdf, "rgb", name, float_text(c[0]) + ", " + float_text(c[1]) + ", " + float_text(c[2]));
}

pugi::xml_node new_bsdf(pugi::xml_node parent, const char* type, const std::string& id) {
    pugi::xml_node bsdf = parent.append_child("bsdf");
    bsdf.append_attribute("type") = type;
    if (!id.empty()) bsdf.append_attribute("id") = id.c_str();
    return bsdf;
}

// The specular lobe's two GGX alphas as the lab renders them (OpenPBR's stretch).
brdf::Microfacet specular_lobe(const brdf::Material& m) { return brdf::openpbr_microfacet(m.roughness, m.anisotropic); }

// principled's roughness and anisotropic for the same two alphas under Disney's stretch
// (alpha_x = r^2 / aspect, alpha_y = r^2 aspect, aspect = sqrt(1 - 0.9 anisotropic)).
void add_principled_roughness(pugi::xml_node bsdf, const brdf::Material& m, Notes* notes) {
    const brdf::Microfacet lobe = specular_lobe(m);
    const float aspect_squared = lobe.ay / lobe.ax;
    float anisotropic = (1.0f - aspect_squared) / 0.9f;
    if (anisotropic > 1.0f) {
        anisotropic = 1.0f;
        notes->add("specular_roughness_anisotropy", "beyond principled's strongest stretch (alpha_y / alpha_x 0.1): written as its strongest");
    }
    add_float(bsdf, "roughness", std::sqrt(std::sqrt(lobe.ax * lobe.ay)));
    add_float(bsdf, "anisotropic", std::max(anisotropic, 0.0f));
}

void write_bsdf(pugi::xml_node parent, const brdf::Material& m, const std::string& id, Notes* notes) {
    float base[3];
    for (int c = 0; c < 3; ++c) base[c] = m.base_weight * m.albedo[c];
    if (m.coat_weight > 0.0f || m.fuzz_weight > 0.0f) {
        pugi::xml_node bsdf = new_bsdf(parent, "principled", id);
        add_rgb(bsdf, "base_color", base);
        add_float(bsdf, "metallic", m.metallic);
        add_principled_roughness(bsdf, m, notes);
        add_float(bsdf, "eta", std::max(m.ior, 1.001f));
        add_float(bsdf, "spec_trans", m.weight_transmission);
        add_float(bsdf, "clearcoat", m.coat_weight);
        add_float(bsdf, "clearcoat_gloss", 1.0f - m.coat_roughness);
        add_float(bsdf, "sheen", m.fuzz_weight);
        if (m.coat_weight > 0.0f)
            notes->add("coat_weight", "principled's clearcoat: a GTR1 lobe of index 1.5 scaled by a quarter, its gloss 1 - coat_roughness; "
                                      "not OpenPBR's dielectric layer (no darkening, colour or index of its own)");
        if (m.fuzz_weight > 0.0f) notes->add("fuzz_weight", "principled's sheen: Disney's Schlick-shaped sheen, white; not the Charlie lobe, its colour and roughness dropped");
        if (m.metallic < 1.0f && m.weight_transmission < 1.0f)
            notes->add("base_color", "principled's diffuse is Disney's retro-reflective lobe, not OpenPBR's Lambert or EON");
        if (!is_grey(m.specular_color, 1.0f)) notes->add("specular_color", "principled has no specular tint of its own: dropped");
        if (m.ior == 1.0f) notes->add("specular_ior", "principled takes an index above 1: written as 1.001");
        return;
    }
    BaseMix mix;
    if (split_base_mix(m, &mix)) {
        pugi::xml_node bsdf = new_bsdf(parent, "blendbsdf", id);
        add_float(bsdf, "weight", mix.weight);
        write_bsdf(bsdf, mix.first, "", notes);
        write_bsdf(bsdf, mix.second, "", notes);
        return;
    }
    const brdf::Microfacet lobe = specular_lobe(m);
    const bool smooth = m.roughness == 0.0f;
    if (m.metallic == 1.0f) {
        // principled's metal is Schlick's Fresnel of base_color: the lab's F82 curve with a white tint
        pugi::xml_node bsdf = new_bsdf(parent, "principled", id);
        add_rgb(bsdf, "base_color", base);
        add_float(bsdf, "metallic", 1.0f);
        add_principled_roughness(bsdf, m, notes);
        if (!is_grey(m.specular_color, 1.0f)) notes->add("specular_color", "the metal's F82 edge tint: principled's metal is Schlick's Fresnel without a tint");
        if (m.specular_weight != 1.0f) notes->add("specular_weight", "principled does not scale the metal's Fresnel: dropped");
        return;
    }
    if (m.weight_transmission == 1.0f) {
        pugi::xml_node bsdf = new_bsdf(parent, smooth ? "dielectric" : "roughdielectric", id);
        if (!smooth) {
            add_value(bsdf, "string", "distribution", "ggx");
            add_float(bsdf, "alpha_u", lobe.ax);
            add_float(bsdf, "alpha_v", lobe.ay);
        }
        add_float(bsdf, "int_ior", m.ior);
        add_float(bsdf, "ext_ior", 1.0f);
        if (!is_grey(m.specular_color, 1.0f)) add_rgb(bsdf, "specular_reflectance", m.specular_color);
        if (!is_grey(m.transmission_color, 1.0f)) add_rgb(bsdf, "specular_transmittance", m.transmission_color);
        if (m.specular_weight != 1.0f) notes->add("specular_weight", "Mitsuba's dielectric has no specular weight: dropped");
        return;
    }
    if (m.specular_weight == 0.0f) {
        pugi::xml_node bsdf = new_bsdf(parent, "diffuse", id);
        add_rgb(bsdf, "reflectance", base);
    } else {
        pugi::xml_node bsdf = new_bsdf(parent, smooth ? "plastic" : "roughplastic", id);
        if (!smooth) {
            add_value(bsdf, "string", "distribution", "ggx");
            add_float(bsdf, "alpha", std::sqrt(lobe.ax * lobe.ay));
            if (m.anisotropic != 0.0f) notes->add("specular_roughness_anisotropy", "Mitsuba's rough plastic is isotropic: written with the geometric mean of the two alphas");
        }
        add_float(bsdf, "int_ior", m.ior);
        add_float(bsdf, "ext_ior", 1.0f);
        add_rgb(bsdf, "diffuse_reflectance", base);
        if (!is_grey(m.specular_color, 1.0f)) add_rgb(bsdf, "specular_reflectance", m.specular_color);
        add_value(bsdf, "boolean", "nonlinear", "false");
        if (m.specular_weight != 1.0f) notes->add("specular_weight", "Mitsuba's plastic has no specular weight: dropped");
    }
    if (m.base_diffuse_roughness != 0.0f) notes->add("base_diffuse_roughness", "Mitsuba's diffuse and plastic are Lambert: dropped");
}

}  // namespace

std::string mitsuba_text(const brdf::Preset& preset, Notes* notes) {
    require_openpbr(preset);
    const brdf::Material& m = preset.material;
    pugi::xml_document doc;
    pugi::xml_node scene = doc.append_child("scene");
    scene.append_attribute("version") = "3.0.0";
    write_bsdf(scene, m, identifier(preset.name), notes);
    if (m.subsurface != 0.0f) notes->add("subsurface_weight", "no subsurface lobe among Mitsuba's surface BSDFs: dropped");
    if (m.thin_film_weight != 0.0f) notes->add("thin_film_weight", "Mitsuba has no thin-film BSDF: dropped");
    if (m.emission_luminance != 0.0f) notes->add("emission_luminance", "Mitsuba's emission is an area emitter on the shape, not a BSDF: dropped");
    if (m.coat_weight > 0.0f && m.coat_roughness_anisotropy != 0.0f) notes->add("coat_roughness_anisotropy", "principled's clearcoat is isotropic: dropped");
    std::ostringstream out;
    doc.save(out, "  ");
    return out.str();
}

}  // namespace interchange
