// A contact sheet of preview renders: the PNGs side by side, each titled with its material, so a
// report shows every preset on the test model at a glance. Drawn by the embedded preview_sheet.py.
#pragma once

#include <string>
#include <vector>

namespace lab::plots {

struct SheetImage {
    std::string title;
    std::string png_path;  // an existing PNG
};

// Throws lab::InputError naming a path that cannot be written, std::invalid_argument for no
// images, std::runtime_error when no Python with matplotlib is found or the script fails.
void write_preview_sheet(const std::vector<SheetImage>& images, const std::string& title, const std::string& png_path);

}  // namespace lab::plots
