// MaterialX both ways (interchange/mtlx_reader, interchange/mtlx_writer): every bundled openpbr
// preset round-trips exactly, standard_surface is translated as MaterialX's graph does, what is not
// converted is noted, and bad documents name the file and the element.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "common/input_error.hpp"
#include "interchange/mtlx_reader.hpp"
#include "interchange/mtlx_writer.hpp"
#include "tests/interchange_checks.hpp"

namespace mtlx_tests {

std::string error_of(const std::string& text) {
    return interchange_checks::input_error_of([&] { interchange::parse_mtlx_text(text, "mine.mtlx"); });
}

std::string document(const std::string& shader, const std::string& inputs, const std::string& extra = "") {
    return "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n  <" + shader + " name=\"SR_a\" type=\"surfaceshader\">\n" + inputs +
           "  </" + shader + ">\n  <surfacematerial name=\"a\" type=\"material\">\n"
           "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"SR_a\" />\n  </surfacematerial>\n" + extra + "</materialx>\n";
}

TEST_CASE("every bundled openpbr preset round-trips through MaterialX exactly", "[interchange][mtlx]") {
    const std::vector<brdf::Preset> presets = interchange_checks::openpbr_presets();
    REQUIRE(presets.size() >= 7);
    for (const brdf::Preset& p : presets) {
        INFO(p.source);
        interchange::Notes notes;
        const std::string text = interchange::mtlx_text(p, &notes);
        CHECK(notes.items.empty());
        const interchange::Imported back = interchange::parse_mtlx_text(text, "roundtrip.mtlx");
        CHECK(back.notes.items.empty());
        CHECK(back.preset.name == interchange::identifier(p.name));
        CHECK(back.preset.description == p.description);
        CHECK(interchange::silent_changes(p.material, back.preset.material, interchange::Notes{}).empty());
        CHECK(std::memcmp(&p.material, &back.preset.material, sizeof p.material) == 0);
    }
}

TEST_CASE("a MaterialX value changed on the way back is caught by the round trip's comparison", "[interchange][mtlx]") {
    const brdf::Preset p = interchange_checks::openpbr_presets().front();
    interchange::Notes notes;
    std::string text = interchange::mtlx_text(p, &notes);
    // the written specular_roughness one float step away
    const std::string key = "name=\"specular_roughness\" type=\"float\" value=\"";
    const size_t at = text.find(key) + key.size();
    const size_t end = text.find('"', at);
    const float moved = std::nextafter(p.material.roughness, 2.0f);
    text.replace(at, end - at, interchange::float_text(moved));
    const interchange::Imported back = interchange::parse_mtlx_text(text, "changed.mtlx");
    const auto changes = interchange::silent_changes(p.material, back.preset.material, notes);
    REQUIRE(changes.size() == 1);
    CHECK(changes[0].rfind("specular_roughness:", 0) == 0);
}

TEST_CASE("the lab's energy_compensation off is noted in MaterialX, which has no switch for it", "[interchange][mtlx]") {
    brdf::Preset p = interchange_checks::openpbr_presets().front();
    p.material.energy_compensation = 0;
    interchange::Notes notes;
    interchange::mtlx_text(p, &notes);
    CHECK(notes.names("energy_compensation"));
}

TEST_CASE("standard_surface is translated to OpenPBR by MaterialX's translation graph", "[interchange][mtlx]") {
    const std::string inputs =
        "    <input name=\"base\" type=\"float\" value=\"0.5\" />\n"
        "    <input name=\"base_color\" type=\"color3\" value=\"1, 0.5, 0.25\" />\n"
        "    <input name=\"specular\" type=\"float\" value=\"0.7\" />\n"
        "    <input name=\"specular_color\" type=\"color3\" value=\"0, 0, 0\" />\n"
        "    <input name=\"coat\" type=\"float\" value=\"0.5\" />\n"
        "    <input name=\"coat_color\" type=\"color3\" value=\"0.5, 1, 1\" />\n"
        "    <input name=\"coat_affect_roughness\" type=\"float\" value=\"0.25\" />\n"
        "    <input name=\"sheen\" type=\"float\" value=\"1\" />\n"
        "    <input name=\"sheen_roughness\" type=\"float\" value=\"0.3\" />\n"
        "    <input name=\"thin_film_thickness\" type=\"float\" value=\"350\" />\n"
        "    <input name=\"specular_rotation\" type=\"float\" value=\"0.25\" />\n";
    const interchange::Imported in = interchange::parse_mtlx_text(document("standard_surface", inputs), "ss.mtlx");
    const brdf::Material& m = in.preset.material;
    CHECK(m.base_weight == 0.5f);
    // base_color times mix(1, coat_color, coat): (1, 0.5, 0.25) (0.75, 1, 1)
    CHECK(m.albedo[0] == 0.75f);
    CHECK(m.albedo[1] == 0.5f);
    CHECK(m.albedo[2] == 0.25f);
    CHECK(m.specular_weight == 0.7f);  // a dielectric keeps Standard Surface's specular
    CHECK(m.specular_color[0] == 1.0f);  // a black specular colour becomes white
    CHECK(m.coat_weight == 0.5f);
    CHECK(m.coat_darkening == 0.25f);  // the graph's coat_affect_roughness
    CHECK(m.coat_roughness == 0.1f);   // Standard Surface's default
    CHECK(m.fuzz_weight == 1.0f);
    CHECK(m.fuzz_roughness == std::pow(0.3f, 0.4f));
    CHECK(m.thin_film_weight == 1.0f);
    CHECK(m.thin_film_thickness == 350.0f * 0.001f);
    CHECK(m.roughness == 0.2f);
    CHECK(in.notes.names("SR_a/specular_rotation"));
    CHECK(in.notes.items.size() == 1);
    // a coated metal: the coat tints the base and is not added on top; the specular weight is 1
    const interchange::Imported metal = interchange::parse_mtlx_text(
        document("standard_surface", "    <input name=\"metalness\" type=\"float\" value=\"1\" />\n"
                                     "    <input name=\"specular\" type=\"float\" value=\"0.3\" />\n"
                                     "    <input name=\"coat\" type=\"float\" value=\"1\" />\n"
                                     "    <input name=\"coat_color\" type=\"color3\" value=\"1, 0.5, 0.5\" />\n"),
        "metal.mtlx");
    CHECK(metal.preset.material.coat_weight == 0.0f);
    CHECK(metal.preset.material.specular_weight == 1.0f);
    CHECK(metal.preset.material.albedo[1] == 0.5f);
}

TEST_CASE("what a MaterialX document holds beyond the lab's inputs is noted, one line each", "[interchange][mtlx]") {
    const std::string inputs =
        "    <input name=\"base_color\" type=\"color3\" nodename=\"tex\" />\n"
        "    <input name=\"transmission_weight\" type=\"float\" value=\"1\" />\n"
        "    <input name=\"transmission_depth\" type=\"float\" value=\"2\" />\n"
        "    <input name=\"subsurface_radius\" type=\"float\" value=\"2\" />\n"
        "    <input name=\"geometry_thin_walled\" type=\"boolean\" value=\"true\" />\n"
        "    <input name=\"coat_weight\" type=\"float\" value=\"0.5\" />\n";
    const std::string extra =
        "  <image name=\"tex\" type=\"color3\"><input name=\"file\" type=\"filename\" value=\"a.png\" /></image>\n"
        "  <surfacematerial name=\"b\" type=\"material\" />\n";
    const interchange::Imported in = interchange::parse_mtlx_text(document("open_pbr_surface", inputs, extra), "notes.mtlx");
    CHECK(in.notes.names("SR_a/base_color"));
    CHECK(in.notes.names("SR_a/transmission_depth"));
    CHECK(in.notes.names("SR_a/geometry_thin_walled"));
    CHECK(!in.notes.names("SR_a/subsurface_radius"));  // no effect with subsurface_weight 0
    CHECK(in.notes.names("tex"));
    CHECK(in.notes.names("b"));
    CHECK(in.notes.items.size() == 5);
    CHECK(in.preset.material.coat_weight == 0.5f);
    CHECK(in.preset.material.albedo[0] == 0.8f);  // the connected input keeps its default
}

TEST_CASE("a MaterialX material is chosen by name; the others are noted", "[interchange][mtlx]") {
    const std::string extra =
        "  <open_pbr_surface name=\"SR_b\" type=\"surfaceshader\"><input name=\"coat_weight\" type=\"float\" value=\"0.5\"/></open_pbr_surface>\n"
        "  <surfacematerial name=\"b\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"SR_b\"/></surfacematerial>\n";
    const std::string doc = document("open_pbr_surface", "", extra);
    const interchange::Imported b = interchange::parse_mtlx_text(doc, "m.mtlx", "b");
    CHECK(b.preset.name == "b");
    CHECK(b.preset.material.coat_weight == 0.5f);
    CHECK(b.notes.names("a"));
    CHECK(b.notes.names("SR_a"));  // the other material's shader node, not converted
    CHECK(interchange_checks::input_error_of([&] { interchange::parse_mtlx_text(doc, "m.mtlx", "c"); }) ==
          "m.mtlx: c: no <surfacematerial> of that name (the document holds a, b)");
}

TEST_CASE("a material's empty input carries nothing and is not noted; a connected one is", "[interchange][mtlx]") {
    auto with_input = [](const std::string& input) {
        return "<materialx version=\"1.39\"><open_pbr_surface name=\"SR_a\" type=\"surfaceshader\"/>"
               "<surfacematerial name=\"a\" type=\"material\"><input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"SR_a\"/>" +
               input + "</surfacematerial></materialx>";
    };
    CHECK(interchange::parse_mtlx_text(with_input("<input name=\"displacementshader\" type=\"displacementshader\" value=\"\"/>"), "a.mtlx")
              .notes.items.empty());
    CHECK(interchange::parse_mtlx_text(with_input("<input name=\"displacementshader\" type=\"displacementshader\" nodename=\"SR_a\"/>"), "a.mtlx")
              .notes.names("a/displacementshader"));
}

TEST_CASE("bad MaterialX documents name the file, the element and the problem", "[interchange][mtlx]") {
    const std::string ok = "    <input name=\"coat_weight\" type=\"float\" value=\"0.5\" />\n";
    CHECK(error_of(document("open_pbr_surface", ok)).empty());
    CHECK(error_of("<materialx><open_pbr_surface") == "mine.mtlx: malformed XML: Error parsing start element tag at byte 27");
    CHECK(error_of("<gltf/>") == "mine.mtlx: <gltf>: not a MaterialX document (its root element is not <materialx>)");
    CHECK(error_of("<materialx version=\"1.39\"/>") == "mine.mtlx: materialx: missing material: the document holds no <surfacematerial>");
    CHECK(error_of("<materialx xmlns:xi=\"http://www.w3.org/2001/XInclude\"><xi:include href=\"a.mtlx\"/></materialx>") ==
          "mine.mtlx: materialx: missing material: the document holds no <surfacematerial> (it includes other documents, xi:include, which the lab does not follow)");
    CHECK(error_of(document("gltf_pbr", ok)) == "mine.mtlx: SR_a: unknown node <gltf_pbr> (the lab converts open_pbr_surface and standard_surface)");
    CHECK(error_of(document("open_pbr_surface", "    <input name=\"coat_wieght\" type=\"float\" value=\"1\" />\n")) ==
          "mine.mtlx: SR_a/coat_wieght: unknown input of open_pbr_surface");
    CHECK(error_of(document("open_pbr_surface", "    <input name=\"coat_weight\" type=\"color3\" value=\"1, 1, 1\" />\n")) ==
          "mine.mtlx: SR_a/coat_weight: wrong type \"color3\" (open_pbr_surface's coat_weight is float)");
    CHECK(error_of(document("open_pbr_surface", "    <input name=\"specular_ior\" type=\"float\" value=\"4\" />\n")) ==
          "mine.mtlx: SR_a/specular_ior: value 4 is out of range [1, 3]");
    CHECK(error_of(document("open_pbr_surface", "    <input name=\"base_color\" type=\"color3\" value=\"0.5, -1, 0\" />\n")) ==
          "mine.mtlx: SR_a/base_color[1]: value -1 is out of range [0, 1]");
    CHECK(error_of(document("open_pbr_surface", "    <input name=\"base_color\" type=\"color3\" value=\"0.5, 1\" />\n")) ==
          "mine.mtlx: SR_a/base_color: expected 3 number(s) for type color3, got \"0.5, 1\"");
    CHECK(error_of(document("open_pbr_surface", "    <input name=\"coat_weight\" type=\"float\" value=\"nan\" />\n")) ==
          "mine.mtlx: SR_a/coat_weight: not a finite number: \"nan\"");
    CHECK(error_of(document("open_pbr_surface", "    <input name=\"coat_weight\" type=\"float\" value=\"half\" />\n")) ==
          "mine.mtlx: SR_a/coat_weight: expected a number, got \"half\"");
    CHECK(error_of(document("open_pbr_surface", "    <input name=\"coat_weight\" type=\"float\" />\n")) ==
          "mine.mtlx: SR_a/coat_weight: has neither a value nor a connection");
    CHECK(error_of("<materialx><surfacematerial name=\"a\" type=\"material\">"
                   "<input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"SR_x\"/></surfacematerial></materialx>") ==
          "mine.mtlx: a/surfaceshader: names node \"SR_x\", which the document does not hold");
}

TEST_CASE("a MaterialX file larger than the reader takes is refused before it is read", "[interchange][mtlx]") {
    const std::string path = (std::filesystem::temp_directory_path() / "dtoadq-too-large.mtlx").string();
    { std::ofstream(path) << "<materialx/>"; }
    std::filesystem::resize_file(path, interchange::kMaxMaterialFileBytes + 1);
    const std::string error = interchange_checks::input_error_of([&] { interchange::read_mtlx(path); });
    std::filesystem::remove(path);
    CHECK(error == path + ": is 8388609 bytes, more than the 8388608 a MaterialX file may hold");
}

}  // namespace mtlx_tests
