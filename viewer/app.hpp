// The viewer's window and its frame loop: a GLFW window with Dear ImGui, the progressive render
// (RenderWorker) shown through an OpenGL texture, and the panels. The same loop runs the headless
// automation (--frames, --set, --screenshot, --save-preset, --export-to, --stats).
#pragma once

#include "viewer/viewer_config.hpp"

namespace lab::viewer {

// Runs until the window closes (or the script ends); returns the exit status. Throws
// lab::InputError for a scripted change or an output the viewer cannot apply or write, and
// std::runtime_error when no window can be opened.
int run_viewer(const ViewerConfig& config);

}  // namespace lab::viewer
