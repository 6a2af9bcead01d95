// Fuzzes the MaterialX reader (interchange/mtlx_reader.cpp) with arbitrary text. Invariant: every
// input is either refused with lab::InputError or accepted as an openpbr material within the lab's
// ranges, which the writer carries without a note and the reader gives back bit for bit.
#include <cstdint>
#include <cstring>
#include <string>

#include "common/input_error.hpp"
#include "fuzz/fuzz_check.hpp"
#include "fuzz/openpbr_ranges.hpp"
#include "interchange/mtlx_reader.hpp"
#include "interchange/mtlx_writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    interchange::Imported in;
    try {
        in = interchange::parse_mtlx_text(text, "fuzz.mtlx");
    } catch (const lab::InputError&) {
        return 0;
    }
    FUZZ_REQUIRE(openpbr_parameters_within_ranges(in.preset.material), "a parameter outside its range");
    interchange::Notes notes;
    const std::string written = interchange::mtlx_text(in.preset, &notes);
    FUZZ_REQUIRE(notes.items.empty(), "the writer noted a material read from MaterialX");
    const interchange::Imported back = interchange::parse_mtlx_text(written, "written.mtlx");
    FUZZ_REQUIRE(back.notes.items.empty(), "the reader noted what the writer wrote");
    FUZZ_REQUIRE(std::memcmp(&back.preset.material, &in.preset.material, sizeof in.preset.material) == 0,
                 "the material changed in a write/read round trip");
    return 0;
}
