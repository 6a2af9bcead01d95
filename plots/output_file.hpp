// Output files of the plots: checked before any work is done, so a bad path fails fast with one
// line naming it, and written only once the content exists.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace lab::plots {

// Throws lab::InputError("PATH", field, reason) when PATH cannot be created or overwritten
// (missing folder, no permission, a folder in the way). Leaves no file behind.
void require_writable(const std::string& path, const std::string& field);

// Opens PATH for writing, or throws lab::InputError naming it.
std::ofstream open_output(const std::string& path, const std::string& field);

// Copies a finished file (e.g. a PNG drawn in a temporary folder) to PATH, or throws naming PATH.
void install_output(const std::filesystem::path& from, const std::string& path, const std::string& field);

// CSV text field, quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text);

// A number as CSV text: 7 significant digits (a float's); "nan", "inf" and "-inf" as numpy's
// and Python's float() read them, so an infinite value is not mistaken for a missing one.
std::string csv_number(double v);

}  // namespace lab::plots
