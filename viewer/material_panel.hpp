// The material panel: every parameter of brdf's parameter table with a slider, a numeric entry and
// a reset to the preset's value (ranges and units from the table, brdf/host/parameters.hpp); the
// albedo as a colour picker that edits sRGB and stores linear; model, distribution and energy
// compensation.
#pragma once

#include "brdf/brdf.hpp"

namespace lab::viewer {

// Draws the panel's widgets into the current ImGui window; returns whether `m` changed.
bool material_panel(brdf::Material* m, const brdf::Material& preset);

}  // namespace lab::viewer
