// The Mitsuba 3 and pbrt-v4 writers (interchange/mitsuba_writer, interchange/pbrt_writer): what they
// write is parsed back here and its values checked per material class against the lab's own
// parameters and lobes (brdf::openpbr_microfacet); what the formats cannot carry is noted.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <sstream>

#include <pugixml.hpp>

#include "brdf/brdf.hpp"
#include "interchange/mitsuba_writer.hpp"
#include "interchange/pbrt_writer.hpp"
#include "tests/interchange_checks.hpp"

namespace writer_tests {

brdf::Preset material(const std::string& name) {
    brdf::Preset p;
    p.name = name;
    p.source = "test";
    p.material = brdf::default_material(BRDF_MODEL_OPENPBR);
    p.material.albedo[0] = 0.6f;
    p.material.albedo[1] = 0.3f;
    p.material.albedo[2] = 0.2f;
    return p;
}

// --- Mitsuba: the <bsdf> elements, their values by name -------------------------------------------
struct MitsubaBsdf {
    std::string type;
    std::map<std::string, std::vector<float>> values;
    std::map<std::string, std::string> words;
    std::vector<MitsubaBsdf> children;
};

MitsubaBsdf read_bsdf(const pugi::xml_node& node) {
    MitsubaBsdf out;
    out.type = node.attribute("type").value();
    for (const pugi::xml_node& child : node.children()) {
        const std::string kind = child.name(), name = child.attribute("name").value();
        if (kind == "bsdf") {
            out.children.push_back(read_bsdf(child));
        } else if (kind == "float" || kind == "rgb") {
            std::stringstream in(child.attribute("value").value());
            std::string part;
            while (std::getline(in, part, ',')) out.values[name].push_back(std::stof(part));
        } else {
            out.words[name] = child.attribute("value").value();
        }
    }
    return out;
}

MitsubaBsdf mitsuba(const brdf::Preset& p, interchange::Notes* notes) {
    const std::string text = interchange::mitsuba_text(p, notes);
    pugi::xml_document doc;
    REQUIRE(doc.load_string(text.c_str()));
    const pugi::xml_node bsdf = doc.child("scene").child("bsdf");
    CHECK(std::string(bsdf.attribute("id").value()) == interchange::identifier(p.name));
    return read_bsdf(bsdf);
}

TEST_CASE("Mitsuba: a Lambert material is diffuse of the base colour times its weight", "[interchange][mitsuba]") {
    brdf::Preset p = material("lambert");
    p.material.specular_weight = 0.0f;
    p.material.base_weight = 0.5f;
    interchange::Notes notes;
    MitsubaBsdf b = mitsuba(p, &notes);
    CHECK(b.type == "diffuse");
    CHECK(b.values["reflectance"] == std::vector<float>{0.5f * 0.6f, 0.5f * 0.3f, 0.5f * 0.2f});
    CHECK(notes.items.empty());
}

TEST_CASE("Mitsuba: a metal is principled with metallic 1 and the lab's two alphas under Disney's stretch", "[interchange][mitsuba]") {
    for (float anisotropy : {0.0f, 0.5f}) {
        brdf::Preset p = material("metal");
        p.material.metallic = 1.0f;
        p.material.roughness = 0.35f;
        p.material.anisotropic = anisotropy;
        interchange::Notes notes;
        MitsubaBsdf b = mitsuba(p, &notes);
        CHECK(b.type == "principled");
        CHECK(b.values["metallic"][0] == 1.0f);
        CHECK(b.values["base_color"] == std::vector<float>{0.6f, 0.3f, 0.2f});
        // Disney's stretch of Mitsuba's principled: alpha_x = r^2 / aspect, alpha_y = r^2 aspect
        const float r = b.values["roughness"][0], aspect = std::sqrt(1.0f - 0.9f * b.values["anisotropic"][0]);
        const brdf::Microfacet lobe = brdf::openpbr_microfacet(0.35f, anisotropy);
        CHECK(r * r / aspect == Approx(lobe.ax).epsilon(1e-6));
        CHECK(r * r * aspect == Approx(lobe.ay).epsilon(1e-6));
        CHECK(notes.items.empty());
    }
}

TEST_CASE("Mitsuba: glass is a rough dielectric of the lab's alphas and index, its tints as Mitsuba's", "[interchange][mitsuba]") {
    brdf::Preset p = material("glass");
    p.material.weight_transmission = 1.0f;
    p.material.roughness = 0.2f;
    p.material.ior = 1.45f;
    p.material.transmission_color[1] = 0.9f;
    interchange::Notes notes;
    MitsubaBsdf b = mitsuba(p, &notes);
    CHECK(b.type == "roughdielectric");
    CHECK(b.words["distribution"] == "ggx");
    CHECK(b.values["alpha_u"][0] == brdf::openpbr_microfacet(0.2f, 0.0f).ax);
    CHECK(b.values["alpha_v"][0] == brdf::openpbr_microfacet(0.2f, 0.0f).ay);
    CHECK(b.values["int_ior"][0] == 1.45f);
    CHECK(b.values["specular_transmittance"] == std::vector<float>{1.0f, 0.9f, 1.0f});
    p.material.roughness = 0.0f;
    CHECK(mitsuba(p, &notes).type == "dielectric");
    CHECK(notes.items.empty());
}

TEST_CASE("Mitsuba: an opaque dielectric is a rough plastic; partial metal and transmission blend pure parts", "[interchange][mitsuba]") {
    brdf::Preset p = material("plastic");
    p.material.roughness = 0.4f;
    interchange::Notes notes;
    MitsubaBsdf b = mitsuba(p, &notes);
    CHECK(b.type == "roughplastic");
    CHECK(b.values["alpha"][0] == Approx(0.16f).epsilon(1e-6));
    CHECK(b.values["int_ior"][0] == 1.5f);
    CHECK(b.values["diffuse_reflectance"] == std::vector<float>{0.6f, 0.3f, 0.2f});
    CHECK(b.words["nonlinear"] == "false");
    p.material.metallic = 0.3f;
    p.material.weight_transmission = 0.25f;
    b = mitsuba(p, &notes);
    REQUIRE(b.type == "blendbsdf");
    CHECK(b.values["weight"][0] == 0.3f);
    REQUIRE(b.children.size() == 2);
    CHECK(b.children[1].type == "principled");
    CHECK(b.children[1].values["metallic"][0] == 1.0f);
    REQUIRE(b.children[0].type == "blendbsdf");  // the dielectric: opaque and transmissive
    CHECK(b.children[0].values["weight"][0] == 0.25f);
    CHECK(b.children[0].children.at(0).type == "roughplastic");
    CHECK(b.children[0].children.at(1).type == "roughdielectric");
    CHECK(notes.items.empty());
}

TEST_CASE("Mitsuba: a coat or fuzz takes principled, and what it approximates or drops is noted", "[interchange][mitsuba]") {
    for (const brdf::Preset& p : interchange_checks::openpbr_presets()) {
        if (p.name != "car_paint") continue;
        interchange::Notes notes;
        MitsubaBsdf b = mitsuba(p, &notes);
        CHECK(b.type == "principled");
        CHECK(b.values["clearcoat"][0] == 1.0f);
        CHECK(b.values["clearcoat_gloss"][0] == 1.0f - 0.03f);
        CHECK(notes.names("coat_weight"));
        CHECK(notes.names("specular_color"));  // the F82 tint
    }
    brdf::Preset p = material("dropped");
    p.material.subsurface = 0.5f;
    p.material.thin_film_weight = 1.0f;
    p.material.emission_luminance = 2.0f;
    interchange::Notes notes;
    mitsuba(p, &notes);
    for (const char* key : {"subsurface_weight", "thin_film_weight", "emission_luminance"}) {
        INFO(key);
        CHECK(notes.names(key));
    }
}

// --- pbrt: the MakeNamedMaterial blocks, their parameters by "type name" -------------------------
struct PbrtMaterialRead {
    std::map<std::string, std::vector<std::string>> values;  // "float eta" -> {"1.5"}
};

std::map<std::string, PbrtMaterialRead> pbrt(const brdf::Preset& p, interchange::Notes* notes) {
    std::stringstream in(interchange::pbrt_text(p, notes));
    std::map<std::string, PbrtMaterialRead> out;
    std::string token, current, key;
    std::vector<std::string> tokens;
    while (in >> std::ws && in.peek() != EOF) {
        if (in.peek() == '#') {
            std::getline(in, token);
            continue;
        }
        if (in.peek() == '"') {
            in.get();
            std::getline(in, token, '"');
            tokens.push_back("\"" + token);
        } else {
            in >> token;
            tokens.push_back(token);
        }
    }
    for (size_t k = 0; k < tokens.size(); ++k) {
        if (tokens[k] == "MakeNamedMaterial") {
            current = tokens.at(++k).substr(1);
            out[current];
        } else if (tokens[k][0] == '"' && tokens[k].find(' ') != std::string::npos) {
            key = tokens[k].substr(1);
            out[current].values[key];
        } else if (tokens[k] != "[" && tokens[k] != "]") {
            out[current].values[key].push_back(tokens[k][0] == '"' ? tokens[k].substr(1) : tokens[k]);
        }
    }
    return out;
}

float number(const PbrtMaterialRead& m, const std::string& key, size_t k = 0) { return std::stof(m.values.at(key).at(k)); }

TEST_CASE("pbrt: diffuse, conductor and dielectric carry the base colour, the lab's alphas and index", "[interchange][pbrt]") {
    brdf::Preset p = material("lambert");
    p.material.specular_weight = 0.0f;
    interchange::Notes notes;
    auto out = pbrt(p, &notes);
    CHECK(out["lambert"].values["string type"].at(0) == "diffuse");
    CHECK(number(out["lambert"], "rgb reflectance", 2) == 0.2f);
    CHECK(notes.items.empty());

    p = material("metal");
    p.material.metallic = 1.0f;
    p.material.roughness = 0.3f;
    p.material.anisotropic = 0.6f;
    out = pbrt(p, &notes);
    const brdf::Microfacet lobe = brdf::openpbr_microfacet(0.3f, 0.6f);
    CHECK(out["metal"].values["string type"].at(0) == "conductor");
    CHECK(number(out["metal"], "float uroughness") == lobe.ax);
    CHECK(number(out["metal"], "float vroughness") == lobe.ay);
    CHECK(out["metal"].values["bool remaproughness"].at(0) == "false");
    CHECK(number(out["metal"], "rgb reflectance", 0) == 0.6f);
    CHECK(notes.names("base_color"));  // pbrt's conductor Fresnel is not Schlick's

    p = material("glass");
    p.material.weight_transmission = 1.0f;
    p.material.ior = 1.7f;
    out = pbrt(p, &notes);
    CHECK(out["glass"].values["string type"].at(0) == "dielectric");
    CHECK(number(out["glass"], "float eta") == 1.7f);
    CHECK(number(out["glass"], "float uroughness") == brdf::openpbr_microfacet(0.3f, 0.0f).ax);
}

TEST_CASE("pbrt: coated materials and mixes", "[interchange][pbrt]") {
    brdf::Preset p = material("coated");
    p.material.metallic = 1.0f;
    p.material.coat_weight = 1.0f;
    p.material.coat_ior = 1.5f;
    p.material.coat_roughness = 0.1f;
    interchange::Notes notes;
    auto out = pbrt(p, &notes);
    CHECK(out["coated"].values["string type"].at(0) == "coatedconductor");
    CHECK(number(out["coated"], "float interface.eta") == 1.5f);
    CHECK(number(out["coated"], "float interface.uroughness") == brdf::openpbr_microfacet(0.1f, 0.0f).ax);
    CHECK(number(out["coated"], "float conductor.uroughness") == brdf::openpbr_microfacet(0.3f, 0.0f).ax);
    CHECK(notes.names("coat_roughness"));  // OpenPBR's roughening of the specular below

    p = material("plastic");
    p.material.metallic = 0.4f;
    notes = {};
    out = pbrt(p, &notes);
    CHECK(out["plastic"].values["string type"].at(0) == "mix");
    CHECK(out["plastic"].values["string materials"] == std::vector<std::string>{"plastic_a", "plastic_b"});
    CHECK(number(out["plastic"], "float amount") == 0.4f);
    CHECK(out["plastic_a"].values["string type"].at(0) == "coateddiffuse");
    CHECK(number(out["plastic_a"], "float eta") == 1.5f);
    CHECK(out["plastic_b"].values["string type"].at(0) == "conductor");

    p = material("dropped");
    p.material.fuzz_weight = 1.0f;
    p.material.thin_film_weight = 1.0f;
    p.material.subsurface = 1.0f;
    notes = {};
    pbrt(p, &notes);
    for (const char* key : {"fuzz_weight", "thin_film_weight", "subsurface_weight"}) {
        INFO(key);
        CHECK(notes.names(key));
    }
}

}  // namespace writer_tests
