// The view menu beside the render (ImGui): which view of viewer/view_modes shows, the relative
// error view's threshold, and the false-colour view's legend.
#pragma once

#include "viewer/view_modes.hpp"

namespace lab::viewer {

// Draws the menu; returns whether the view or its threshold changed.
bool view_menu(ViewMode* mode, float* relative_error_threshold);

// The "save EXR" row (viewer/view_export): the file's path and its layers (as --aov lists them);
// returns whether the button was pressed.
bool save_exr_controls(char* path, size_t path_size, char* layers, size_t layers_size);

}  // namespace lab::viewer
