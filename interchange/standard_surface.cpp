#include "interchange/standard_surface.hpp"

#include <cmath>

namespace interchange {

const std::vector<NodeInput>& standard_surface_inputs() {
    static const std::vector<NodeInput> table{
        {"base", "float", {0.8f, 0, 0}},
        {"base_color", "color3", {1, 1, 1}},
        {"diffuse_roughness", "float", {0, 0, 0}},
        {"metalness", "float", {0, 0, 0}},
        {"specular", "float", {1, 0, 0}},
        {"specular_color", "color3", {1, 1, 1}},
        {"specular_roughness", "float", {0.2f, 0, 0}},
        {"specular_IOR", "float", {1.5f, 0, 0}},
        {"specular_anisotropy", "float", {0, 0, 0}},
        {"specular_rotation", "float", {0, 0, 0}},
        {"transmission", "float", {0, 0, 0}},
        {"transmission_color", "color3", {1, 1, 1}},
        {"transmission_depth", "float", {0, 0, 0}},
        {"transmission_scatter", "color3", {0, 0, 0}},
        {"transmission_scatter_anisotropy", "float", {0, 0, 0}},
        {"transmission_dispersion", "float", {0, 0, 0}},
        {"transmission_extra_roughness", "float", {0, 0, 0}},
        {"subsurface", "float", {0, 0, 0}},
        {"subsurface_color", "color3", {1, 1, 1}},
        {"subsurface_radius", "color3", {1, 1, 1}},
        {"subsurface_scale", "float", {1, 0, 0}},
        {"subsurface_anisotropy", "float", {0, 0, 0}},
        {"sheen", "float", {0, 0, 0}},
        {"sheen_color", "color3", {1, 1, 1}},
        {"sheen_roughness", "float", {0.3f, 0, 0}},
        {"coat", "float", {0, 0, 0}},
        {"coat_color", "color3", {1, 1, 1}},
        {"coat_roughness", "float", {0.1f, 0, 0}},
        {"coat_anisotropy", "float", {0, 0, 0}},
        {"coat_rotation", "float", {0, 0, 0}},
        {"coat_IOR", "float", {1.5f, 0, 0}},
        {"coat_normal", "vector3", {0, 0, 0}},
        {"coat_affect_color", "float", {0, 0, 0}},
        {"coat_affect_roughness", "float", {0, 0, 0}},
        {"thin_film_thickness", "float", {0, 0, 0}},
        {"thin_film_IOR", "float", {1.5f, 0, 0}},
        {"emission", "float", {0, 0, 0}},
        {"emission_color", "color3", {1, 1, 1}},
        {"opacity", "color3", {1, 1, 1}},
        {"thin_walled", "boolean", {0, 0, 0}},
        {"normal", "vector3", {0, 0, 0}},
        {"tangent", "vector3", {0, 0, 0}},
    };
    return table;
}

std::map<std::string, std::array<float, 3>> standard_surface_to_openpbr(const std::map<std::string, std::array<float, 3>>& s,
                                                                         const std::string& element, Notes* notes) {
    auto f = [&s](const char* name) { return s.at(name)[0]; };
    auto c = [&s](const char* name) { return s.at(name); };
    auto scalar = [](float v) { return std::array<float, 3>{v, 0.0f, 0.0f}; };
    std::map<std::string, std::array<float, 3>> o;
    // base: the coat's colour tints the base (Standard Surface's coat colours what is under it)
    o["base_weight"] = scalar(f("base"));
    const float coat = f("coat");
    for (int k = 0; k < 3; ++k) o["base_color"][k] = c("base_color")[k] * (coat * c("coat_color")[k] + (1.0f - coat) * 1.0f);
    o["base_diffuse_roughness"] = scalar(f("diffuse_roughness"));
    o["base_metalness"] = scalar(f("metalness"));
    // specular: OpenPBR's specular_weight also scales the metal, Standard Surface's does not
    o["specular_weight"] = scalar(f("metalness") > 0.0f ? 1.0f : f("specular"));
    const std::array<float, 3> spec = c("specular_color");
    o["specular_color"] = spec[0] + spec[1] + spec[2] == 0.0f ? std::array<float, 3>{1, 1, 1} : spec;
    o["specular_roughness"] = scalar(f("specular_roughness"));
    o["specular_ior"] = scalar(f("specular_IOR"));
    o["specular_roughness_anisotropy"] = scalar(f("specular_anisotropy"));
    o["transmission_weight"] = scalar(f("transmission"));
    o["transmission_color"] = c("transmission_color");
    o["transmission_depth"] = scalar(f("transmission_depth"));
    o["transmission_scatter"] = c("transmission_scatter");
    o["transmission_scatter_anisotropy"] = scalar(f("transmission_scatter_anisotropy"));
    o["transmission_dispersion_scale"] = scalar(f("transmission_dispersion"));
    o["subsurface_weight"] = scalar(f("subsurface"));
    o["subsurface_color"] = c("subsurface_color");
    o["subsurface_radius"] = scalar(f("subsurface_scale"));
    o["subsurface_radius_scale"] = c("subsurface_radius");
    o["subsurface_scatter_anisotropy"] = scalar(f("subsurface_anisotropy"));
    o["fuzz_weight"] = scalar(f("sheen"));
    o["fuzz_color"] = c("sheen_color");
    // the graph's own approximation, fitted by eye
    o["fuzz_roughness"] = scalar(std::pow(f("sheen_roughness"), 0.4f));
    // a coated metal's coat was its tint (in base_color above), so no coat is added on top
    o["coat_weight"] = scalar(coat * f("metalness") > 0.0f ? 0.0f : coat);
    o["coat_color"] = c("coat_color");
    o["coat_roughness"] = scalar(f("coat_roughness"));
    o["coat_roughness_anisotropy"] = scalar(f("coat_anisotropy"));
    o["coat_ior"] = scalar(f("coat_IOR"));
    o["coat_darkening"] = scalar(f("coat_affect_roughness"));
    const float thickness = f("thin_film_thickness") * 0.001f;  // nanometres to micrometres
    o["thin_film_weight"] = scalar(thickness > 0.0f ? 1.0f : 0.0f);
    o["thin_film_thickness"] = scalar(thickness);
    o["thin_film_ior"] = scalar(f("thin_film_IOR"));
    o["emission_luminance"] = scalar(f("emission"));
    o["emission_color"] = c("emission_color");
    o["geometry_opacity"] = scalar(c("opacity")[0]);
    o["geometry_thin_walled"] = scalar(f("thin_walled"));
    // what the translation graph leaves out
    for (const char* name : {"specular_rotation", "transmission_extra_roughness", "coat_rotation", "coat_affect_color"}) {
        for (const NodeInput& in : standard_surface_inputs())
            if (std::string(in.name) == name && s.at(name) != in.fallback)
                notes->add(element + "/" + name, "not translated to OpenPBR (MaterialX's translation graph has no counterpart); left out");
    }
    return o;
}

}  // namespace interchange
