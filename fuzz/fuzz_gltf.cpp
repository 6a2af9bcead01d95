// Fuzzes the glTF reader (interchange/gltf_reader.cpp) with arbitrary text. Invariant: every input
// is either refused with lab::InputError or accepted as an openpbr material within the lab's
// ranges; written back as glTF and read again, every parameter is the same or named in the
// writer's notes, the anisotropic roughness within float rounding (1e-5).
#include <cmath>
#include <cstdint>
#include <string>

#include "common/input_error.hpp"
#include "fuzz/fuzz_check.hpp"
#include "fuzz/openpbr_ranges.hpp"
#include "interchange/gltf_reader.hpp"
#include "interchange/gltf_writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    interchange::Imported in;
    try {
        in = interchange::parse_gltf_text(text, "fuzz.gltf");
    } catch (const lab::InputError&) {
        return 0;
    }
    const brdf::Material& m = in.preset.material;
    FUZZ_REQUIRE(openpbr_parameters_within_ranges(m), "a parameter outside its range");
    interchange::Notes notes;
    const std::string written = interchange::gltf_text(in.preset, &notes);
    const interchange::Imported back = interchange::parse_gltf_text(written, "written.gltf");
    const std::vector<std::string> changes =
        interchange::silent_changes(m, back.preset.material, notes, {"specular_roughness", "specular_roughness_anisotropy"});
    FUZZ_REQUIRE(changes.empty(), "a parameter changed in a write/read round trip without a note");
    if (m.anisotropic == 0.0f) {
        FUZZ_REQUIRE(back.preset.material.roughness == m.roughness && back.preset.material.anisotropic == 0.0f,
                     "an isotropic roughness changed in a write/read round trip");
    } else if (!notes.names("specular_roughness_anisotropy")) {
        FUZZ_REQUIRE(std::fabs(back.preset.material.roughness - m.roughness) <= 1e-5f, "the specular roughness changed in a write/read round trip");
        FUZZ_REQUIRE(std::fabs(back.preset.material.anisotropic - m.anisotropic) <= 1e-5f, "the anisotropy changed in a write/read round trip");
    }
    return 0;
}
