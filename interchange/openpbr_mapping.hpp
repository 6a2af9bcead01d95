// What every format's reader and writer share: the lab's openpbr parameters by OpenPBR's input
// names (brdf/host/parameters.hpp), the OpenPBR inputs the lab leaves out, the notes that name what
// a conversion could not carry exactly, and float text that reads back as the same float.
// docs/interchange.md gives each format's mapping.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "brdf/host/parameters.hpp"
#include "brdf/host/preset.hpp"

namespace interchange {

// One thing a conversion did not carry exactly: a parameter (`field`, the lab's or the format's
// name) approximated or dropped, or an element of the input left out. The command line prints each
// as one line; nothing is dropped without one.
struct Note {
    std::string field;
    std::string text;
};

// "FILE: FIELD: text", the line a note is printed as.
std::string note_line(const std::string& file, const Note& note);

struct Notes {
    std::vector<Note> items;
    // a note already made (the same field and text, as the parts of a mix give) is not repeated
    void add(const std::string& field, const std::string& text);
    // whether a note names `field`
    bool names(const std::string& field) const;
};

// A material read from another format, with what it did not carry.
struct Imported {
    brdf::Preset preset;
    Notes notes;
};

// The largest MaterialX or glTF file a reader takes: far beyond a document of materials (a few
// kilobytes each), refused with one line before it fills memory.
inline constexpr std::uintmax_t kMaxMaterialFileBytes = std::uintmax_t(8) << 20;

// The lab's parameter of OpenPBR input `name` (openpbr_parameters()), or null when the lab has none.
const brdf::ScalarParameter* lab_openpbr_parameter(const std::string& name);

// An OpenPBR Surface input the lab leaves out (docs/materials.md), with its default: a reader notes
// one given another value.
struct LeftOutInput {
    const char* name;
    const char* type;  // "float", "color3", "boolean", "vector3"
    std::array<float, 3> fallback;
    const char* why;
    const char* layer_weight;  // the lab parameter without which it has no effect (nothing to note at 0), or null
};
const std::vector<LeftOutInput>& openpbr_inputs_left_out();

// A parameter's value in a material: 1 float (scalar) or 3 (colour).
std::array<float, 3> parameter_value(const brdf::Material& m, const brdf::ScalarParameter& p);
void set_parameter_value(brdf::Material* m, const brdf::ScalarParameter& p, const std::array<float, 3>& value);
inline int parameter_components(const brdf::ScalarParameter& p) { return p.field ? 1 : 3; }
// Whether every channel of an RGB colour is v.
inline bool is_grey(const float* c, float v) { return c[0] == v && c[1] == v && c[2] == v; }

// The openpbr parameters whose value in `read` differs from `written` and that no note names, as
// "key: written -> read" lines (energy_compensation too); `skip` lists parameters the caller
// compares otherwise. What a round trip changed without saying so.
std::vector<std::string> silent_changes(const brdf::Material& written, const brdf::Material& read, const Notes& notes,
                                        const std::vector<std::string>& skip = {});

// The shortest decimal text that reads back as the same float (JSON writers take
// brdf::shortest_decimal, the same number as a double).
std::string float_text(float value);

// The preset a writer takes: an openpbr one. Throws lab::InputError naming the preset's file for a
// lab, dtoadq2017 or measured material, which have no OpenPBR inputs (interchange/fit_to_openpbr.hpp
// carries them to openpbr first).
void require_openpbr(const brdf::Preset& preset);

// A name usable as an identifier in MaterialX and pbrt: letters, digits and '_', not starting with a
// digit; anything else becomes '_'.
std::string identifier(const std::string& name);

}  // namespace interchange
