#include "interchange/mtlx_writer.hpp"

#include <sstream>

#include <pugixml.hpp>

namespace interchange {

std::string mtlx_text(const brdf::Preset& preset, Notes* notes) {
    require_openpbr(preset);
    const brdf::Material& m = preset.material;
    if (!m.energy_compensation)
        notes->add("energy_compensation", "OpenPBR has no switch for it: the lab's single-scattering lobes (false) are written as OpenPBR's full model");
    const std::string material_name = identifier(preset.name);
    const std::string shader_name = "SR_" + material_name;
    pugi::xml_document doc;
    pugi::xml_node root = doc.append_child("materialx");
    root.append_attribute("version") = "1.39";
    root.append_attribute("colorspace") = "lin_rec709";
    pugi::xml_node shader = root.append_child("open_pbr_surface");
    shader.append_attribute("name") = shader_name.c_str();
    shader.append_attribute("type") = "surfaceshader";
    for (const brdf::ScalarParameter& p : brdf::openpbr_parameters()) {
        const std::array<float, 3> v = parameter_value(m, p);
        std::string text = float_text(v[0]);
        if (!p.field) text += ", " + float_text(v[1]) + ", " + float_text(v[2]);
        pugi::xml_node input = shader.append_child("input");
        input.append_attribute("name") = p.key;
        input.append_attribute("type") = p.field ? "float" : "color3";
        input.append_attribute("value") = text.c_str();
    }
    pugi::xml_node material = root.append_child("surfacematerial");
    material.append_attribute("name") = material_name.c_str();
    material.append_attribute("type") = "material";
    if (!preset.description.empty()) material.append_attribute("doc") = preset.description.c_str();
    pugi::xml_node input = material.append_child("input");
    input.append_attribute("name") = "surfaceshader";
    input.append_attribute("type") = "surfaceshader";
    input.append_attribute("nodename") = shader_name.c_str();
    std::ostringstream out;
    doc.save(out, "  ");
    return out.str();
}

}  // namespace interchange
