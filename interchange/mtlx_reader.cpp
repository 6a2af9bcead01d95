#include "interchange/mtlx_reader.hpp"

#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

#include <pugixml.hpp>

#include "common/input_error.hpp"
#include "common/read_text_file.hpp"
#include "interchange/standard_surface.hpp"

namespace interchange {
namespace {

using lab::InputError;

// The inputs a shader node of `category` takes: the lab's OpenPBR parameters and those it leaves
// out, or Standard Surface's.
std::vector<NodeInput> inputs_of(const std::string& category) {
    if (category == "standard_surface") return standard_surface_inputs();
    std::vector<NodeInput> inputs;
    for (const brdf::ScalarParameter& p : brdf::openpbr_parameters())
        inputs.push_back({p.key, p.field ? "float" : "color3", {p.fallback, p.field ? 0.0f : p.fallback, p.field ? 0.0f : p.fallback}});
    for (const LeftOutInput& in : openpbr_inputs_left_out()) inputs.push_back({in.name, in.type, in.fallback});
    return inputs;
}

int components(const std::string& type) { return type == "color3" || type == "vector3" ? 3 : 1; }

// A MaterialX value string: one number (float), three separated by commas (color3, vector3), or
// true/false (boolean).
std::array<float, 3> parse_value(const std::string& text, const std::string& type, const std::string& source, const std::string& field) {
    std::array<float, 3> out{0, 0, 0};
    if (type == "boolean") {
        if (text == "true") return {1, 0, 0};
        if (text == "false") return {0, 0, 0};
        throw InputError(source, field, "expected true or false, got \"" + text + "\"");
    }
    const int n = components(type);
    std::stringstream in(text);
    std::string part;
    int k = 0;
    while (std::getline(in, part, ',')) {
        if (k == n) throw InputError(source, field, "expected " + std::to_string(n) + " number(s) for type " + type + ", got \"" + text + "\"");
        const char* begin = part.c_str();
        char* end = nullptr;
        const double v = std::strtod(begin, &end);
        while (*end == ' ' || *end == '\t') ++end;
        if (end == begin || *end != '\0')
            throw InputError(source, field, "expected a number, got \"" + part + "\"");
        if (!std::isfinite(v) || std::fabs(v) > 3.4e38) throw InputError(source, field, "not a finite number: \"" + part + "\"");
        out[k++] = float(v);
    }
    if (k != n) throw InputError(source, field, "expected " + std::to_string(n) + " number(s) for type " + type + ", got \"" + text + "\"");
    return out;
}

const char* connection_of(const pugi::xml_node& input) {
    for (const char* attribute : {"nodename", "nodegraph", "output", "interfacename", "defaultgeomprop"})
        if (input.attribute(attribute)) return attribute;
    return nullptr;
}

// The given inputs of a shader node, checked against its table; connected ones noted and left out.
std::map<std::string, std::array<float, 3>> read_inputs(const pugi::xml_node& shader, const std::string& category, const std::string& source,
                                                        Notes* notes) {
    const std::string element = shader.attribute("name").value();
    const std::vector<NodeInput> table = inputs_of(category);
    std::map<std::string, std::array<float, 3>> values;
    for (const NodeInput& in : table) values[in.name] = in.fallback;
    std::set<std::string> seen;
    for (const pugi::xml_node& child : shader.children()) {
        if (child.type() != pugi::node_element) continue;
        const std::string name = child.attribute("name").value();
        if (std::string(child.name()) != "input") {
            notes->add(element + "/" + name, std::string("<") + child.name() + "> inside a shader node: not converted");
            continue;
        }
        const std::string field = element + "/" + name;
        const NodeInput* spec = nullptr;
        for (const NodeInput& in : table)
            if (name == in.name) spec = &in;
        if (!spec) throw InputError(source, field, "unknown input of " + category);
        if (!seen.insert(name).second) throw InputError(source, field, "input given twice");
        const std::string type = child.attribute("type").value();
        if (type != spec->type) throw InputError(source, field, "wrong type \"" + type + "\" (" + category + "'s " + name + " is " + spec->type + ")");
        if (const char* connection = connection_of(child)) {
            notes->add(field, std::string("connected (") + connection + "=\"" + child.attribute(connection).value() +
                                  "\"): textures and node graphs are not converted; the input keeps its default");
            continue;
        }
        if (!child.attribute("value")) throw InputError(source, field, "has neither a value nor a connection");
        if (child.attribute("colorspace") && std::string(child.attribute("colorspace").value()) != "lin_rec709")
            notes->add(field, std::string("colour space \"") + child.attribute("colorspace").value() + "\" is read as lin_rec709, unconverted");
        values[name] = parse_value(child.attribute("value").value(), type, source, field);
    }
    return values;
}

// OpenPBR input values onto an openpbr material: the lab's parameters range-checked, the inputs it
// leaves out noted when they are not at their defaults.
void apply_openpbr(const std::map<std::string, std::array<float, 3>>& values, const std::string& element, const std::string& source,
                   brdf::Material* m, Notes* notes) {
    for (const brdf::ScalarParameter& p : brdf::openpbr_parameters()) {
        std::array<float, 3> v = values.at(p.key);
        for (int c = 0; c < parameter_components(p); ++c) {
            const std::string field = element + "/" + p.key + (p.field ? "" : "[" + std::to_string(c) + "]");
            v[c] = brdf::checked_parameter_value(v[c], source, field, p.min, p.max);
        }
        set_parameter_value(m, p, v);
    }
    for (const LeftOutInput& in : openpbr_inputs_left_out()) {
        auto it = values.find(in.name);
        if (it == values.end() || it->second == in.fallback) continue;
        if (in.layer_weight && values.at(in.layer_weight)[0] == 0.0f) continue;  // its layer is off
        notes->add(element + "/" + in.name, std::string("not converted: ") + in.why);
    }
}

}  // namespace

Imported parse_mtlx_text(const std::string& text, const std::string& source, const std::string& wanted) {
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!parsed)
        throw InputError(source, "", std::string("malformed XML: ") + parsed.description() + " at byte " + std::to_string(parsed.offset));
    const pugi::xml_node root = doc.document_element();
    if (std::string(root.name()) != "materialx")
        throw InputError(source, std::string("<") + root.name() + ">", "not a MaterialX document (its root element is not <materialx>)");
    std::vector<pugi::xml_node> materials;
    for (const pugi::xml_node& child : root.children("surfacematerial")) materials.push_back(child);
    if (materials.empty()) {
        const bool includes = root.child("xi:include");
        throw InputError(source, "materialx", std::string("missing material: the document holds no <surfacematerial>") +
                                                  (includes ? " (it includes other documents, xi:include, which the lab does not follow)" : ""));
    }
    size_t chosen = 0;
    if (!wanted.empty()) {
        std::string names;
        for (chosen = 0; chosen < materials.size() && wanted != materials[chosen].attribute("name").value(); ++chosen)
            names += (names.empty() ? "" : ", ") + std::string(materials[chosen].attribute("name").value());
        if (chosen == materials.size()) throw InputError(source, wanted, "no <surfacematerial> of that name (the document holds " + names + ")");
    }
    const pugi::xml_node material = materials[chosen];
    const std::string material_name = material.attribute("name").value();
    Imported out;
    for (size_t k = 0; k < materials.size(); ++k)
        if (k != chosen)
            out.notes.add(materials[k].attribute("name").value(), "a further material: not converted (\"" + material_name + "\" is; --material chooses)");
    std::string shader_name;
    for (const pugi::xml_node& input : material.children()) {
        if (input.type() != pugi::node_element) continue;
        const std::string name = input.attribute("name").value();
        if (std::string(input.name()) == "input" && name == "surfaceshader") {
            if (std::string(input.attribute("type").value()) != "surfaceshader")
                throw InputError(source, material_name + "/surfaceshader", std::string("wrong type \"") + input.attribute("type").value() + "\" (expected surfaceshader)");
            shader_name = input.attribute("nodename").value();
            if (shader_name.empty())
                throw InputError(source, material_name + "/surfaceshader", "names no shader node (nodename): a node graph's shader is not converted");
        } else if (connection_of(input) || !std::string(input.attribute("value").value()).empty()) {
            // an input left empty (MaterialX writes displacementshader value="") carries nothing
            out.notes.add(material_name + "/" + name, std::string("<") + input.name() + "> of the material: not converted");
        }
    }
    if (shader_name.empty()) throw InputError(source, material_name, "missing surfaceshader input: the material names no shader");
    pugi::xml_node shader;
    for (const pugi::xml_node& child : root.children())
        if (child.type() == pugi::node_element && shader_name == child.attribute("name").value()) shader = child;
    if (!shader) throw InputError(source, material_name + "/surfaceshader", "names node \"" + shader_name + "\", which the document does not hold");
    const std::string category = shader.name();
    if (category != "open_pbr_surface" && category != "standard_surface")
        throw InputError(source, shader_name, "unknown node <" + category + "> (the lab converts open_pbr_surface and standard_surface)");
    if (std::string(shader.attribute("type").value()) != "surfaceshader")
        throw InputError(source, shader_name, std::string("wrong type \"") + shader.attribute("type").value() + "\" (expected surfaceshader)");
    if (root.attribute("colorspace") && std::string(root.attribute("colorspace").value()) != "lin_rec709")
        out.notes.add("materialx", std::string("colour space \"") + root.attribute("colorspace").value() + "\" is read as lin_rec709, unconverted");

    std::map<std::string, std::array<float, 3>> values = read_inputs(shader, category, source, &out.notes);
    if (category == "standard_surface") values = standard_surface_to_openpbr(values, shader_name, &out.notes);
    out.preset.source = source;
    out.preset.material = brdf::default_material(BRDF_MODEL_OPENPBR);
    out.preset.name = material_name;
    out.preset.description = material.attribute("doc").value();
    apply_openpbr(values, shader_name, source, &out.preset.material, &out.notes);
    for (const pugi::xml_node& child : root.children()) {
        if (child.type() != pugi::node_element || child == shader || child == material) continue;
        if (std::string(child.name()) == "surfacematerial") continue;  // noted above
        out.notes.add(child.attribute("name").value(), std::string("<") + child.name() + ">: not converted");
    }
    return out;
}

Imported read_mtlx(const std::string& path, const std::string& material) {
    return parse_mtlx_text(lab::read_text_file(path, kMaxMaterialFileBytes, "MaterialX"), path, material);
}

}  // namespace interchange
