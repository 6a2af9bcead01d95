#include "viewer/material_export.hpp"

#include "common/input_error.hpp"
#include "interchange/export_material.hpp"

namespace lab::viewer {

bool is_material_file_target(const std::string& target) {
    try {
        return interchange::format_of_file(target) != interchange::Format::preset;
    } catch (const InputError&) {
        return false;
    }
}

std::vector<std::string> export_material_file(const brdf::Preset& preset, const std::string& path) {
    const interchange::Format format = interchange::format_of_file(path);
    if (format == interchange::Format::preset) throw InputError(path, "", "a preset is saved with \"save preset\" (--save-preset)");
    const interchange::Notes notes = interchange::export_material(preset, format, path, lab::fit::FitOptions{});
    std::vector<std::string> lines;
    for (const interchange::Note& n : notes.items) lines.push_back(interchange::note_line(path, n));
    return lines;
}

}  // namespace lab::viewer
