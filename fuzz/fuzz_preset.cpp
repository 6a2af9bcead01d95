// Fuzzes the preset loader (brdf/host/preset.cpp) with arbitrary text. Invariant: every input is
// either refused with lab::InputError or accepted, and an accepted preset survives save_preset and
// load_preset unchanged: the same name, description and every field of the material, bit for bit.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "brdf/host/preset.hpp"
#include "common/input_error.hpp"
#include "fuzz/fuzz_check.hpp"

namespace {

bool same_material(const brdf::Material& a, const brdf::Material& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    brdf::Preset preset;
    try {
        preset = brdf::parse_preset_text(text, "fuzz.json");
    } catch (const lab::InputError&) {
        return 0;
    }
    static const std::string saved =
        (std::filesystem::temp_directory_path() / ("dtoadq-fuzz-preset-" + std::to_string(::getpid()) + ".json")).string();
    brdf::save_preset(preset, saved);
    const brdf::Preset loaded = brdf::load_preset(saved);
    std::filesystem::remove(saved);
    FUZZ_REQUIRE(loaded.name == preset.name, "the name changed in a save/load round trip");
    FUZZ_REQUIRE(loaded.description == preset.description, "the description changed in a save/load round trip");
    FUZZ_REQUIRE(same_material(loaded.material, preset.material), "the material changed in a save/load round trip");
    return 0;
}
