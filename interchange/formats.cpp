#include "interchange/formats.hpp"

#include <fstream>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "common/input_error.hpp"
#include "interchange/gltf_reader.hpp"
#include "interchange/gltf_writer.hpp"
#include "interchange/mitsuba_writer.hpp"
#include "interchange/mtlx_reader.hpp"
#include "interchange/mtlx_writer.hpp"
#include "interchange/pbrt_writer.hpp"

namespace interchange {

namespace {

struct FormatEntry {
    Format format;
    const char* name;
    const char* extension;
};
constexpr FormatEntry kFormats[] = {
    {Format::preset, "preset", ".json"},
    {Format::mtlx, "mtlx", ".mtlx"},
    {Format::gltf, "gltf", ".gltf"},
    {Format::mitsuba, "mitsuba", ".xml"},
    {Format::pbrt, "pbrt", ".pbrt"},
};

std::string format_list() {
    std::string list;
    for (const FormatEntry& f : kFormats) list += (list.empty() ? "" : ", ") + std::string(f.name) + " (" + f.extension + ")";
    return list;
}

}  // namespace

Format format_named(const std::string& name, const std::string& source, const std::string& field) {
    for (const FormatEntry& f : kFormats)
        if (name == f.name) return f.format;
    throw lab::InputError(source, field, "unknown format \"" + name + "\" (expected " + format_list() + ")");
}

Format format_of_file(const std::string& path) {
    const std::string extension = std::filesystem::path(path).extension().string();
    for (const FormatEntry& f : kFormats)
        if (extension == f.extension) return f.format;
    throw lab::InputError(path, "", "unknown file extension \"" + extension + "\" (expected " + format_list() + "; or name the format with --to)");
}

const char* format_name(Format format) {
    for (const FormatEntry& f : kFormats)
        if (f.format == format) return f.name;
    return "?";
}

Imported read_material(const std::string& path, Format format, const std::string& material) {
    if (format == Format::mtlx) return read_mtlx(path, material);
    if (format == Format::gltf) return read_gltf(path, material);
    if (!material.empty()) throw lab::InputError("command line", "--material", "a preset file holds one material");
    if (format == Format::mitsuba || format == Format::pbrt)
        throw lab::InputError(path, "", std::string("the lab writes ") + format_name(format) + " but does not read it (it reads .json, .mtlx and .gltf)");
    Imported imported;
    imported.preset = brdf::load_preset(path);
    return imported;
}

std::string material_text(const brdf::Preset& preset, Format format, Notes* notes) {
    if (format == Format::mtlx) return mtlx_text(preset, notes);
    if (format == Format::gltf) return gltf_text(preset, notes);
    if (format == Format::mitsuba) return mitsuba_text(preset, notes);
    if (format == Format::pbrt) return pbrt_text(preset, notes);
    return brdf::preset_to_json(preset).dump(2) + "\n";
}

void write_material(const brdf::Preset& preset, Format format, const std::string& path, Notes* notes) {
    const std::string text = material_text(preset, format, notes);
    std::ofstream out(path, std::ios::binary);
    if (!out) throw lab::InputError(path, "", "cannot write");
    out << text;
    if (!out.flush()) throw lab::InputError(path, "", "cannot write");
}

}  // namespace interchange
