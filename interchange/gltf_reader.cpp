#include "interchange/gltf_reader.hpp"

#include <set>

#include <nlohmann/json.hpp>

#include "common/input_error.hpp"
#include "common/read_text_file.hpp"
#include "interchange/gltf_mapping.hpp"

namespace interchange {
namespace {

using lab::InputError;
using nlohmann::json;

// A glTF document is a few levels deep; nothing legitimate comes near this.
constexpr int kMaxGltfNesting = 64;

const std::set<std::string> kExtensionsRead = {"KHR_materials_clearcoat", "KHR_materials_sheen", "KHR_materials_iridescence",
                                                "KHR_materials_specular", "KHR_materials_ior", "KHR_materials_transmission",
                                                "KHR_materials_anisotropy", "KHR_materials_emissive_strength"};

// Reads one glTF object's fields, each checked for type and for the lab's range of the parameter it
// becomes; a field it does not know is noted (a texture, extras) rather than dropped silently.
class Fields {
public:
    Fields(const json& object, std::string path, std::string source, Notes* notes)
        : object_(object), path_(std::move(path)), source_(std::move(source)), notes_(notes) {
        if (!object_.is_object()) throw InputError(source_, path_, std::string("expected an object, got ") + object_.type_name());
    }
    std::string field(const std::string& key) const { return path_ + "." + key; }
    bool has(const std::string& key) const { return object_.contains(key); }
    // a number in [lo, hi], or `fallback` when absent
    float number(const std::string& key, float lo, float hi, float fallback) {
        known_.insert(key);
        if (!has(key)) return fallback;
        const json& v = object_.at(key);
        if (!v.is_number()) throw InputError(source_, field(key), std::string("expected a number, got ") + v.type_name());
        return brdf::checked_parameter_value(v.get<double>(), source_, field(key), lo, hi);
    }
    // an array of n numbers, each in [lo, hi]
    std::vector<float> numbers(const std::string& key, size_t n, float lo, float hi, std::vector<float> fallback) {
        known_.insert(key);
        if (!has(key)) return fallback;
        const json& v = object_.at(key);
        if (!v.is_array() || v.size() != n) throw InputError(source_, field(key), "expected an array of " + std::to_string(n) + " numbers");
        std::vector<float> out;
        for (size_t k = 0; k < n; ++k) {
            const std::string f = field(key) + "[" + std::to_string(k) + "]";
            if (!v.at(k).is_number()) throw InputError(source_, f, std::string("expected a number, got ") + v.at(k).type_name());
            out.push_back(brdf::checked_parameter_value(v.at(k).get<double>(), source_, f, lo, hi));
        }
        return out;
    }
    const json* object(const std::string& key) {
        known_.insert(key);
        if (!has(key)) return nullptr;
        if (!object_.at(key).is_object()) throw InputError(source_, field(key), std::string("expected an object, got ") + object_.at(key).type_name());
        return &object_.at(key);
    }
    void ignore(const std::string& key) { known_.insert(key); }
    // every field not read: one note each
    void note_the_rest() {
        for (auto it = object_.begin(); it != object_.end(); ++it) {
            if (known_.count(it.key())) continue;
            const bool texture = it.key().size() > 7 && it.key().compare(it.key().size() - 7, 7, "Texture") == 0;
            notes_->add(field(it.key()), texture ? "a texture: not converted (the factor alone is)" : "not converted");
        }
    }

private:
    const json& object_;
    std::string path_, source_;
    Notes* notes_;
    std::set<std::string> known_;
};

json parse_json(const std::string& text, const std::string& source) {
    std::string last_key;
    try {
        return json::parse(text, [&last_key, &source](int depth, json::parse_event_t event, json& value) {
            if (event == json::parse_event_t::key) last_key = value.get<std::string>();
            if (depth > kMaxGltfNesting) throw InputError(source, last_key, "nested more than " + std::to_string(kMaxGltfNesting) + " levels deep");
            return true;
        });
    } catch (const json::exception& e) {
        std::string what = e.what();
        auto pos = what.find("] ");
        throw InputError(source, last_key, "malformed JSON: " + (pos == std::string::npos ? what : what.substr(pos + 2)));
    }
}

const brdf::ScalarParameter& parameter(const char* key) { return *lab_openpbr_parameter(key); }

}  // namespace

Imported parse_gltf_text(const std::string& text, const std::string& source, const std::string& wanted) {
    const json doc = parse_json(text, source);
    if (!doc.is_object()) throw InputError(source, "", "a glTF document must be a JSON object");
    if (!doc.contains("asset") || !doc.at("asset").is_object()) throw InputError(source, "asset", "missing: not a glTF document");
    const json& asset = doc.at("asset");
    if (!asset.contains("version") || !asset.at("version").is_string()) throw InputError(source, "asset.version", "missing or not a string");
    const std::string version = asset.at("version").get<std::string>();
    if (version.rfind("2.", 0) != 0) throw InputError(source, "asset.version", "glTF \"" + version + "\": the lab reads glTF 2.0");
    if (!doc.contains("materials")) throw InputError(source, "materials", "missing material: the document holds no materials");
    const json& materials = doc.at("materials");
    if (!materials.is_array()) throw InputError(source, "materials", std::string("expected an array, got ") + materials.type_name());
    if (materials.empty()) throw InputError(source, "materials", "missing material: the array is empty");

    Imported out;
    Notes* notes = &out.notes;
    if (doc.contains("extensionsRequired") && doc.at("extensionsRequired").is_array())
        for (const json& name : doc.at("extensionsRequired"))
            if (!name.is_string() || !kExtensionsRead.count(name.get<std::string>()))
                notes->add("extensionsRequired", "requires " + name.dump() + ", which the lab does not read: the material is converted without it");
    size_t chosen = 0;
    if (!wanted.empty()) {
        std::string names;
        for (chosen = 0; chosen < materials.size(); ++chosen) {
            const json& named = materials.at(chosen);
            const std::string name = named.is_object() && named.contains("name") && named.at("name").is_string() ? named.at("name").get<std::string>() : "";
            if (name == wanted || std::to_string(chosen) == wanted) break;
            names += (names.empty() ? "" : ", ") + (name.empty() ? std::to_string(chosen) : name);
        }
        if (chosen == materials.size()) throw InputError(source, "materials", "no material named or numbered \"" + wanted + "\" (the document holds " + names + ")");
    }
    for (size_t k = 0; k < materials.size(); ++k)
        if (k != chosen)
            notes->add("materials[" + std::to_string(k) + "]", "a further material: not converted (materials[" + std::to_string(chosen) + "] is; --material chooses)");
    brdf::Material& m = out.preset.material;
    m = brdf::default_material(BRDF_MODEL_OPENPBR);
    out.preset.source = source;
    const std::string path = "materials[" + std::to_string(chosen) + "]";
    const json& chosen_material = materials.at(chosen);
    Fields material(chosen_material, path, source, notes);
    out.preset.name = "material";
    material.ignore("name");
    if (material.has("name")) {
        if (!chosen_material.at("name").is_string()) throw InputError(source, material.field("name"), "expected a string");
        out.preset.name = chosen_material.at("name").get<std::string>();
    }
    auto range = [](const char* key) { return std::pair<float, float>{parameter(key).min, parameter(key).max}; };
    float gltf_roughness = 1.0f;
    if (const json* pbr_object = material.object("pbrMetallicRoughness")) {
        Fields pbr(*pbr_object, material.field("pbrMetallicRoughness"), source, notes);
        const std::vector<float> base = pbr.numbers("baseColorFactor", 4, 0.0f, 1.0f, {1, 1, 1, 1});
        for (int c = 0; c < 3; ++c) m.albedo[c] = base[c];
        if (base[3] != 1.0f) notes->add(pbr.field("baseColorFactor") + "[3]", "alpha (coverage): not converted, the lab's surfaces are opaque");
        m.metallic = pbr.number("metallicFactor", 0.0f, 1.0f, 1.0f);
        gltf_roughness = pbr.number("roughnessFactor", 0.0f, 1.0f, 1.0f);
        pbr.note_the_rest();
    } else {
        m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
        m.metallic = 1.0f;
    }
    m.roughness = gltf_roughness;
    m.base_weight = 1.0f;

    const std::vector<float> emissive = material.numbers("emissiveFactor", 3, 0.0f, 1.0f, {0, 0, 0});
    const bool emits = emissive[0] > 0.0f || emissive[1] > 0.0f || emissive[2] > 0.0f;
    for (const char* key : {"alphaMode", "alphaCutoff", "doubleSided"}) {
        material.ignore(key);
        if (!material.has(key)) continue;
        const json& v = chosen_material.at(key);
        const bool fallback = (std::string(key) == "alphaMode" && v == "OPAQUE") || (std::string(key) == "doubleSided" && v == false);
        if (!fallback) notes->add(material.field(key), "not converted: the lab's surfaces are opaque and bound solids");
    }

    if (const json* extensions_object = material.object("extensions")) {
        Fields ext(*extensions_object, material.field("extensions"), source, notes);
        for (auto it = extensions_object->begin(); it != extensions_object->end(); ++it)
            if (!kExtensionsRead.count(it.key())) {
                ext.ignore(it.key());
                notes->add(ext.field(it.key()), "an extension the lab does not read: not converted");
            }
        if (const json* o = ext.object("KHR_materials_specular")) {
            Fields f(*o, ext.field("KHR_materials_specular"), source, notes);
            m.specular_weight = f.number("specularFactor", range("specular_weight").first, range("specular_weight").second, 1.0f);
            const std::vector<float> color = f.numbers("specularColorFactor", 3, 0.0f, 1.0f, {1, 1, 1});
            for (int c = 0; c < 3; ++c) m.specular_color[c] = color[c];
            if (m.metallic > 0.0f && color != std::vector<float>{1, 1, 1})
                notes->add(f.field("specularColorFactor"), "becomes specular_color, which OpenPBR applies to the metal too, as its F82 edge tint (glTF does not)");
            f.note_the_rest();
        }
        if (const json* o = ext.object("KHR_materials_ior")) {
            Fields f(*o, ext.field("KHR_materials_ior"), source, notes);
            m.ior = f.number("ior", range("specular_ior").first, range("specular_ior").second, 1.5f);
            f.note_the_rest();
        }
        if (const json* o = ext.object("KHR_materials_transmission")) {
            Fields f(*o, ext.field("KHR_materials_transmission"), source, notes);
            m.weight_transmission = f.number("transmissionFactor", 0.0f, 1.0f, 0.0f);
            // glTF's transmitted light takes the base colour's tint: OpenPBR's transmission_color
            if (m.weight_transmission > 0.0f)
                for (int c = 0; c < 3; ++c) m.transmission_color[c] = m.albedo[c];
            f.note_the_rest();
        }
        if (const json* o = ext.object("KHR_materials_clearcoat")) {
            Fields f(*o, ext.field("KHR_materials_clearcoat"), source, notes);
            m.coat_weight = f.number("clearcoatFactor", 0.0f, 1.0f, 0.0f);
            m.coat_roughness = f.number("clearcoatRoughnessFactor", 0.0f, 1.0f, 0.0f);
            if (m.coat_weight > 0.0f) m.coat_ior = 1.5f;  // glTF's clearcoat index
            f.note_the_rest();
        }
        if (const json* o = ext.object("KHR_materials_sheen")) {
            Fields f(*o, ext.field("KHR_materials_sheen"), source, notes);
            const std::vector<float> color = f.numbers("sheenColorFactor", 3, 0.0f, 1.0f, {0, 0, 0});
            m.fuzz_roughness = f.number("sheenRoughnessFactor", 0.0f, 1.0f, 0.0f);
            if (color[0] > 0.0f || color[1] > 0.0f || color[2] > 0.0f) {
                m.fuzz_weight = 1.0f;
                for (int c = 0; c < 3; ++c) m.fuzz_color[c] = color[c];
            }
            f.note_the_rest();
        }
        if (const json* o = ext.object("KHR_materials_iridescence")) {
            Fields f(*o, ext.field("KHR_materials_iridescence"), source, notes);
            m.thin_film_weight = f.number("iridescenceFactor", 0.0f, 1.0f, 0.0f);
            m.thin_film_ior = f.number("iridescenceIor", range("thin_film_ior").first, range("thin_film_ior").second, 1.3f);
            const float max_nm = range("thin_film_thickness").second * kNanometresPerMicrometre;
            const float minimum = f.number("iridescenceThicknessMinimum", 0.0f, max_nm, 100.0f);
            const float maximum = f.number("iridescenceThicknessMaximum", 0.0f, max_nm, 400.0f);
            // without a thickness texture glTF's film is the maximum thickness throughout
            m.thin_film_thickness = float(double(maximum) / kNanometresPerMicrometre);
            if (minimum != maximum && f.has("iridescenceThicknessTexture"))
                notes->add(f.field("iridescenceThicknessMinimum"), "a thickness range over a texture: the film takes the maximum");
            f.note_the_rest();
        }
        if (const json* o = ext.object("KHR_materials_anisotropy")) {
            Fields f(*o, ext.field("KHR_materials_anisotropy"), source, notes);
            const float strength = f.number("anisotropyStrength", 0.0f, 1.0f, 0.0f);
            if (f.number("anisotropyRotation", -1e6f, 1e6f, 0.0f) != 0.0f)
                notes->add(f.field("anisotropyRotation"), "not converted: OpenPBR's tangent is the surface's (geometry_tangent)");
            if (strength > 0.0f) openpbr_anisotropy_of({gltf_roughness, strength}, &m.roughness, &m.anisotropic);
            f.note_the_rest();
        }
        if (const json* o = ext.object("KHR_materials_emissive_strength")) {
            Fields f(*o, ext.field("KHR_materials_emissive_strength"), source, notes);
            m.emission_luminance = f.number("emissiveStrength", 0.0f, range("emission_luminance").second, 1.0f);
            f.note_the_rest();
        } else {
            m.emission_luminance = 1.0f;
        }
        ext.note_the_rest();
    } else {
        m.emission_luminance = 1.0f;
    }
    if (emits) {
        for (int c = 0; c < 3; ++c) m.emission_color[c] = emissive[c];
    } else {
        m.emission_luminance = 0.0f;
    }
    material.note_the_rest();
    return out;
}

Imported read_gltf(const std::string& path, const std::string& material) {
    return parse_gltf_text(lab::read_text_file(path, kMaxMaterialFileBytes, "glTF"), path, material);
}

}  // namespace interchange
