// glTF 2.0 materials both ways (interchange/gltf_reader, interchange/gltf_writer): every bundled
// openpbr preset round-trips, each parameter exactly or named in a note; a material that sets
// every parameter glTF expresses comes back exactly; what glTF cannot carry is noted, and bad
// documents name the file and the element.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>

#include <nlohmann/json.hpp>

#include "brdf/brdf.hpp"
#include "common/input_error.hpp"
#include "interchange/gltf_mapping.hpp"
#include "interchange/gltf_reader.hpp"
#include "interchange/gltf_writer.hpp"
#include "tests/interchange_checks.hpp"

namespace gltf_tests {

using nlohmann::json;

std::string error_of(const std::string& text) {
    return interchange_checks::input_error_of([&] { interchange::parse_gltf_text(text, "mine.gltf"); });
}

std::string error_of_material(const std::string& text, const std::string& material) {
    return interchange_checks::input_error_of([&] { interchange::parse_gltf_text(text, "m.gltf", material); });
}

std::string with_material(const std::string& material) { return R"({"asset": {"version": "2.0"}, "materials": [)" + material + "]}"; }

// Every parameter glTF expresses set away from its default, with the rest at values glTF carries
// (a white base, so the transmission's tint is the same in both).
brdf::Preset every_expressible_parameter() {
    brdf::Preset p;
    p.name = "everything";
    p.source = "test";
    brdf::Material& m = p.material;
    m = brdf::default_material(BRDF_MODEL_OPENPBR);
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
    m.metallic = 0.25f;
    m.roughness = 0.4f;
    m.ior = 1.7f;
    m.specular_weight = 1.0f;
    m.weight_transmission = 0.6f;
    m.coat_weight = 0.8f;
    m.coat_roughness = 0.15f;
    m.coat_ior = 1.5f;
    m.fuzz_weight = 1.0f;
    m.fuzz_color[0] = 0.3f;
    m.fuzz_color[1] = 0.2f;
    m.fuzz_color[2] = 0.1f;
    m.fuzz_roughness = 0.45f;
    m.thin_film_weight = 0.9f;
    m.thin_film_thickness = 0.35f;
    m.thin_film_ior = 1.8f;
    m.emission_luminance = 12.5f;
    m.emission_color[0] = 1.0f;
    m.emission_color[1] = 0.5f;
    m.emission_color[2] = 0.25f;
    return p;
}

TEST_CASE("every bundled openpbr preset round-trips through glTF: each parameter exact or noted", "[interchange][gltf]") {
    int exact_presets = 0;
    for (const brdf::Preset& p : interchange_checks::openpbr_presets()) {
        INFO(p.source);
        interchange::Notes notes;
        const std::string text = interchange::gltf_text(p, &notes);
        for (const interchange::Note& n : notes.items) INFO("note: " << n.field << ": " << n.text);
        const interchange::Imported back = interchange::parse_gltf_text(text, "roundtrip.gltf");
        if (notes.items.empty()) CHECK(back.notes.items.empty());
        CHECK(back.preset.name == p.name);
        const std::vector<std::string> changes =
            interchange::silent_changes(p.material, back.preset.material, notes, {"specular_roughness", "specular_roughness_anisotropy"});
        for (const std::string& c : changes) INFO(c);
        CHECK(changes.empty());
        // the anisotropic roughness goes through glTF's two alphas: exact up to the few roundings of
        // the mapping and its inverse (about ten float operations of 2^-24 each: 1e-6 holds them)
        if (p.material.anisotropic != 0.0f) {
            CHECK(back.preset.material.roughness == Approx(p.material.roughness).epsilon(1e-6));
            CHECK(back.preset.material.anisotropic == Approx(p.material.anisotropic).margin(1e-6));
        } else {
            CHECK(back.preset.material.roughness == p.material.roughness);
            CHECK(back.preset.material.anisotropic == 0.0f);
        }
        if (notes.items.empty()) ++exact_presets;
    }
    CHECK(exact_presets >= 2);  // glowing_coated_panel and oil_slick carry everything
}

TEST_CASE("a material setting every parameter glTF expresses comes back exactly, without a note", "[interchange][gltf]") {
    const brdf::Preset p = every_expressible_parameter();
    interchange::Notes notes;
    const json doc = interchange::gltf_document(p, &notes);
    CHECK(notes.items.empty());
    CHECK(doc.at("extensionsUsed").size() == 6);  // clearcoat, emissive_strength, ior, iridescence, sheen, transmission
    const interchange::Imported back = interchange::parse_gltf_text(doc.dump(), "everything.gltf");
    CHECK(back.notes.items.empty());
    CHECK(interchange::silent_changes(p.material, back.preset.material, notes).empty());
    CHECK(std::memcmp(&p.material, &back.preset.material, sizeof p.material) == 0);
}

TEST_CASE("a glTF value changed on the way back is caught by the round trip's comparison", "[interchange][gltf]") {
    const brdf::Preset p = every_expressible_parameter();
    interchange::Notes notes;
    json doc = interchange::gltf_document(p, &notes);
    json& coat = doc["materials"][0]["extensions"]["KHR_materials_clearcoat"];
    coat["clearcoatRoughnessFactor"] = double(std::nextafter(p.material.coat_roughness, 1.0f));
    const interchange::Imported back = interchange::parse_gltf_text(doc.dump(), "changed.gltf");
    const auto changes = interchange::silent_changes(p.material, back.preset.material, notes);
    REQUIRE(changes.size() == 1);
    CHECK(changes[0].rfind("coat_roughness:", 0) == 0);
}

TEST_CASE("OpenPBR's anisotropy becomes glTF's with the same two alphas", "[interchange][gltf]") {
    for (float r : {0.1f, 0.35f, 0.6f})
        for (float a : {0.2f, 0.8f, 1.0f}) {
            INFO("roughness " << r << ", anisotropy " << a);
            interchange::GltfAnisotropy g = interchange::gltf_anisotropy_of(r, a);
            const brdf::Microfacet lobe = brdf::openpbr_microfacet(r, a);
            const float alpha_b = g.roughness * g.roughness;
            CHECK(alpha_b == Approx(std::max(lobe.ay, 1e-4f)).epsilon(1e-6));
            CHECK(alpha_b + (1.0f - alpha_b) * g.strength * g.strength == Approx(lobe.ax).epsilon(1e-6));
        }
}

TEST_CASE("what glTF cannot express is noted by the writer, one line each", "[interchange][gltf]") {
    brdf::Preset p = every_expressible_parameter();
    brdf::Material& m = p.material;
    m.base_weight = 0.5f;
    m.base_diffuse_roughness = 0.3f;
    m.subsurface = 0.2f;
    m.coat_color[1] = 0.9f;
    m.coat_ior = 1.6f;
    m.coat_darkening = 0.5f;
    m.coat_roughness_anisotropy = 0.3f;
    m.transmission_color[0] = 0.5f;
    m.fuzz_weight = 0.5f;
    m.energy_compensation = 0;
    interchange::Notes notes;
    interchange::gltf_text(p, &notes);
    for (const char* key : {"base_weight", "base_diffuse_roughness", "subsurface_weight", "coat_color", "coat_ior", "coat_darkening",
                            "coat_roughness_anisotropy", "transmission_color", "fuzz_weight", "energy_compensation"}) {
        INFO(key);
        CHECK(notes.names(key));
    }
    CHECK(notes.items.size() == 10);
}

TEST_CASE("what a glTF material holds beyond the lab's parameters is noted, one line each", "[interchange][gltf]") {
    const interchange::Imported in = interchange::parse_gltf_text(
        with_material(R"({"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.5, 1], "baseColorTexture": {"index": 0}},
                          "normalTexture": {"index": 1}, "alphaMode": "BLEND", "doubleSided": false,
                          "extensions": {"KHR_materials_volume": {"thicknessFactor": 1}}}, {"name": "second"})"),
        "notes.gltf");
    CHECK(in.notes.names("materials[0].pbrMetallicRoughness.baseColorTexture"));
    CHECK(in.notes.names("materials[0].normalTexture"));
    CHECK(in.notes.names("materials[0].alphaMode"));
    CHECK(in.notes.names("materials[0].extensions.KHR_materials_volume"));
    CHECK(in.notes.names("materials[1]"));
    CHECK(in.notes.items.size() == 5);
    CHECK(in.preset.material.albedo[1] == 0.5f);
    CHECK(in.preset.material.metallic == 1.0f);  // glTF's default
    const interchange::Imported required = interchange::parse_gltf_text(
        R"({"asset": {"version": "2.0"}, "extensionsRequired": ["KHR_texture_transform", "KHR_materials_ior"], "materials": [{}]})", "r.gltf");
    CHECK(required.notes.names("extensionsRequired"));
    CHECK(required.notes.items.size() == 1);
}

TEST_CASE("glTF's transmission takes the base colour's tint, read as OpenPBR's transmission_color", "[interchange][gltf]") {
    const interchange::Imported green = interchange::parse_gltf_text(
        with_material(R"({"pbrMetallicRoughness": {"baseColorFactor": [0.5, 1, 0.5, 1], "metallicFactor": 0, "roughnessFactor": 0},
                          "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1}}})"),
        "green.gltf");
    CHECK(green.notes.items.empty());
    CHECK(green.preset.material.weight_transmission == 1.0f);
    CHECK(green.preset.material.transmission_color[0] == 0.5f);
    CHECK(green.preset.material.transmission_color[1] == 1.0f);
    // and a lab glass whose tint is its base colour goes out and back without a note
    brdf::Preset glass = every_expressible_parameter();
    glass.material.albedo[0] = glass.material.transmission_color[0] = 0.7f;
    interchange::Notes notes;
    const std::string text = interchange::gltf_text(glass, &notes);
    CHECK(notes.items.empty());
    const brdf::Material back = interchange::parse_gltf_text(text, "glass.gltf").preset.material;
    CHECK(std::memcmp(&back, &glass.material, sizeof back) == 0);
}

TEST_CASE("a glTF material is chosen by name or index; the others are noted", "[interchange][gltf]") {
    const std::string doc = with_material(R"({"name": "a", "pbrMetallicRoughness": {"metallicFactor": 0.25}},
                                             {"name": "b", "pbrMetallicRoughness": {"metallicFactor": 0.5}},
                                             {"pbrMetallicRoughness": {"metallicFactor": 0.75}})");
    const interchange::Imported b = interchange::parse_gltf_text(doc, "m.gltf", "b");
    CHECK(b.preset.name == "b");
    CHECK(b.preset.material.metallic == 0.5f);
    CHECK(b.notes.names("materials[0]"));
    CHECK(b.notes.names("materials[2]"));
    CHECK(interchange::parse_gltf_text(doc, "m.gltf", "2").preset.material.metallic == 0.75f);
    CHECK(error_of_material(doc, "c") == "m.gltf: materials: no material named or numbered \"c\" (the document holds a, b, 2)");
}

TEST_CASE("bad glTF documents name the file, the element and the problem", "[interchange][gltf]") {
    CHECK(error_of(with_material("{}")).empty());
    CHECK(error_of("{\"asset\": ").rfind("mine.gltf: asset: malformed JSON: ", 0) == 0);
    CHECK(error_of("[]") == "mine.gltf: a glTF document must be a JSON object");
    CHECK(error_of("{\"materials\": [{}]}") == "mine.gltf: asset: missing: not a glTF document");
    CHECK(error_of("{\"asset\": {\"version\": \"1.0\"}, \"materials\": [{}]}") == "mine.gltf: asset.version: glTF \"1.0\": the lab reads glTF 2.0");
    CHECK(error_of("{\"asset\": {\"version\": \"2.0\"}}") == "mine.gltf: materials: missing material: the document holds no materials");
    CHECK(error_of(with_material("")) == "mine.gltf: materials: missing material: the array is empty");
    CHECK(error_of(with_material(R"({"pbrMetallicRoughness": {"roughnessFactor": "0.5"}})")) ==
          "mine.gltf: materials[0].pbrMetallicRoughness.roughnessFactor: expected a number, got string");
    CHECK(error_of(with_material(R"({"pbrMetallicRoughness": {"metallicFactor": 1.5}})")) ==
          "mine.gltf: materials[0].pbrMetallicRoughness.metallicFactor: value 1.5 is out of range [0, 1]");
    CHECK(error_of(with_material(R"({"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1]}})")) ==
          "mine.gltf: materials[0].pbrMetallicRoughness.baseColorFactor: expected an array of 4 numbers");
    CHECK(error_of(with_material(R"({"extensions": {"KHR_materials_ior": {"ior": 3.5}}})")) ==
          "mine.gltf: materials[0].extensions.KHR_materials_ior.ior: value 3.5 is out of range [1, 3]");
    CHECK(error_of(with_material(R"({"extensions": {"KHR_materials_sheen": []}})")) ==
          "mine.gltf: materials[0].extensions.KHR_materials_sheen: expected an object, got array");
    CHECK(error_of(with_material("3")) == "mine.gltf: materials[0]: expected an object, got number");
    std::string deep(100, '[');
    CHECK(error_of(deep) == "mine.gltf: nested more than 64 levels deep");
}

}  // namespace gltf_tests
