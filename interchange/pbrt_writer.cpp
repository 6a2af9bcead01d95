#include "interchange/pbrt_writer.hpp"

#include <sstream>

#include "interchange/base_mix.hpp"

namespace interchange {
namespace {


std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) out += (c == '"' || c == '\\') ? '_' : c;
    return out + "\"";
}

class PbrtMaterial {
public:
    PbrtMaterial(const std::string& name, const char* type) { text_ << "MakeNamedMaterial " << quoted(name) << "\n    \"string type\" \"" << type << "\""; }
    void number(const std::string& name, float v) { text_ << "\n    \"float " << name << "\" " << float_text(v); }
    void rgb(const std::string& name, const float* c) {
        text_ << "\n    \"rgb " << name << "\" [ " << float_text(c[0]) << " " << float_text(c[1]) << " " << float_text(c[2]) << " ]";
    }
    void flag(const std::string& name, bool v) { text_ << "\n    \"bool " << name << "\" " << (v ? "true" : "false"); }
    void strings(const std::string& name, const std::string& a, const std::string& b) {
        text_ << "\n    \"string " << name << "\" [ " << quoted(a) << " " << quoted(b) << " ]";
    }
    // GGX alphas as pbrt takes them unremapped: u along the tangent, v across
    void alphas(const std::string& prefix, const brdf::Microfacet& lobe) {
        number(prefix + "uroughness", lobe.ax);
        number(prefix + "vroughness", lobe.ay);
    }
    std::string text() const { return text_.str() + "\n"; }

private:
    std::ostringstream text_;
};

// The named materials of `m` (its parts first, when it is a mix), the last one named `name`.
std::string write_material(const brdf::Material& m, const std::string& name, Notes* notes) {
    BaseMix mix;
    if (split_base_mix(m, &mix)) {
        std::string text = write_material(mix.first, name + "_a", notes) + write_material(mix.second, name + "_b", notes);
        PbrtMaterial out(name, "mix");
        out.strings("materials", name + "_a", name + "_b");
        out.number("amount", mix.weight);
        return text + out.text();
    }
    float base[3];
    for (int c = 0; c < 3; ++c) base[c] = m.base_weight * m.albedo[c];
    const brdf::Microfacet specular = brdf::openpbr_microfacet(m.roughness, m.anisotropic);
    const brdf::Microfacet coat = brdf::openpbr_microfacet(m.coat_roughness, m.coat_roughness_anisotropy);
    const bool coated = m.coat_weight > 0.0f;
    if (m.metallic == 1.0f) {
        PbrtMaterial out(name, coated ? "coatedconductor" : "conductor");
        if (coated) {
            out.number("interface.eta", m.coat_ior);
            out.alphas("interface.", coat);
            out.alphas("conductor.", specular);
        } else {
            out.alphas("", specular);
        }
        out.rgb("reflectance", base);
        out.flag("remaproughness", false);
        notes->add("base_color", "pbrt's conductor of this reflectance is the exact Fresnel of index 1 + i k with that F0, not the lab's Schlick (F82) curve");
        if (!is_grey(m.specular_color, 1.0f)) notes->add("specular_color", "the metal's F82 edge tint: pbrt's reflectance conductor has none");
        if (m.specular_weight != 1.0f) notes->add("specular_weight", "pbrt's conductor has no Fresnel weight: dropped");
        return out.text();
    }
    if (m.weight_transmission == 1.0f) {
        PbrtMaterial out(name, "dielectric");
        out.number("eta", m.ior);
        out.alphas("", specular);
        out.flag("remaproughness", false);
        if (!is_grey(m.transmission_color, 1.0f)) notes->add("transmission_color", "pbrt's dielectric is colourless: dropped");
        if (!is_grey(m.specular_color, 1.0f) || m.specular_weight != 1.0f) notes->add("specular_color", "pbrt's dielectric has no specular tint or weight: dropped");
        if (coated) notes->add("coat_weight", "pbrt's dielectric has no coat: dropped");
        return out.text();
    }
    if (m.specular_weight == 0.0f && !coated) {
        PbrtMaterial out(name, "diffuse");
        out.rgb("reflectance", base);
        if (m.base_diffuse_roughness != 0.0f) notes->add("base_diffuse_roughness", "pbrt's diffuse is Lambert: dropped");
        return out.text();
    }
    // a diffuse base under one dielectric interface: the coat where there is one, else the specular
    PbrtMaterial out(name, "coateddiffuse");
    out.rgb("reflectance", base);
    out.number("eta", coated ? m.coat_ior : m.ior);
    out.alphas("", coated ? coat : specular);
    out.flag("remaproughness", false);
    if (coated && m.specular_weight != 0.0f)
        notes->add("specular_roughness", "pbrt's coated diffuse has one interface: the coat's; the base's own specular is dropped");
    if (m.base_diffuse_roughness != 0.0f) notes->add("base_diffuse_roughness", "pbrt's coated diffuse base is Lambert: dropped");
    if (!is_grey(m.specular_color, 1.0f) || (!coated && m.specular_weight != 1.0f))
        notes->add("specular_color", "pbrt's coated diffuse interface has no tint or weight: dropped");
    return out.text();
}

}  // namespace

std::string pbrt_text(const brdf::Preset& preset, Notes* notes) {
    require_openpbr(preset);
    const brdf::Material& m = preset.material;
    std::string text = "# " + preset.name + " (dtoadq convert; docs/interchange.md)\n" + write_material(m, identifier(preset.name), notes);
    if (m.coat_weight > 0.0f) {
        if (m.coat_weight != 1.0f) notes->add("coat_weight", "pbrt's coated materials have a whole coat: written as 1");
        if (!is_grey(m.coat_color, 1.0f)) notes->add("coat_color", "pbrt's coat is clear (its albedo is a scattering medium's): dropped");
        if (m.coat_darkening != 1.0f) notes->add("coat_darkening", "pbrt's layers scatter between the interfaces, fully darkening: dropped");
        if (m.coat_roughness != 0.0f && m.metallic > 0.0f)
            notes->add("coat_roughness", "OpenPBR roughens the specular under a rough coat; the conductor below keeps its own roughness in pbrt");
    }
    if (m.subsurface != 0.0f) notes->add("subsurface_weight", "no subsurface lobe among these pbrt materials: dropped");
    if (m.fuzz_weight != 0.0f) notes->add("fuzz_weight", "pbrt-v4 has no sheen: dropped");
    if (m.thin_film_weight != 0.0f) notes->add("thin_film_weight", "pbrt-v4 has no thin-film material: dropped");
    if (m.emission_luminance != 0.0f) notes->add("emission_luminance", "pbrt's emission is an AreaLightSource on the shape, not a material: dropped");
    return text;
}

}  // namespace interchange
