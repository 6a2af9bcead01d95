// The interchange formats by name and file extension, and reading or writing a material in any of
// them: what `dtoadq convert` and the viewer's export call (docs/interchange.md).
#pragma once

#include <string>

#include "interchange/openpbr_mapping.hpp"

namespace interchange {

enum class Format { preset, mtlx, gltf, mitsuba, pbrt };

// "mtlx", "gltf", "mitsuba", "pbrt", "preset"; throws lab::InputError(source, field, ...) for another name.
Format format_named(const std::string& name, const std::string& source, const std::string& field);
// By the file's extension: .mtlx, .gltf, .xml (Mitsuba 3), .pbrt, .json (a lab preset); throws lab::InputError(path, "", ...).
Format format_of_file(const std::string& path);
const char* format_name(Format format);

// A material file in any format the lab reads (preset, MaterialX, glTF), as an openpbr preset or,
// for a preset file, the preset as it is; Mitsuba and pbrt are written only (lab::InputError).
// `material` chooses one of a document's materials by name (glTF: or index); empty: the first.
Imported read_material(const std::string& path, Format format, const std::string& material = "");
// The text of a material in `format`; notes name what it could not carry exactly.
std::string material_text(const brdf::Preset& preset, Format format, Notes* notes);
// material_text written to `path`; throws lab::InputError(path, "", ...) when it cannot be written.
void write_material(const brdf::Preset& preset, Format format, const std::string& path, Notes* notes);

}  // namespace interchange
