// The view menu beside the render (ImGui): which view of viewer/view_modes shows, the relative
// error view's threshold, and the false-colour view's legend.
#pragma once

#include "viewer/view_modes.hpp"

namespace lab::viewer {

// Draws the menu; returns whether the view or its threshold changed.
bool view_menu(ViewMode* mode, float* relative_error_threshold);

}  // namespace lab::viewer
