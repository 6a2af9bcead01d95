// Writing a material out to another tool, whatever its model: an openpbr material as it is, a lab,
// dtoadq2017 or measured one fitted to openpbr first (interchange/fit_to_openpbr.hpp), the fit's
// report written beside the export. What `dtoadq convert` and the viewer's export call.
#pragma once

#include <string>

#include "fit/fit_optimizer.hpp"
#include "interchange/formats.hpp"

namespace interchange {

// The fit's report beside an export: car.mtlx -> car.fit.json.
std::string fit_report_path(const std::string& output);

// Writes `preset` to `path` in `format`. The notes name what the format could not carry and, for a
// fitted material, the fit ("model": its error and where the report is). Throws lab::InputError
// for a material that cannot be fitted or a file that cannot be written.
Notes export_material(const brdf::Preset& preset, Format format, const std::string& path, const lab::fit::FitOptions& options);

}  // namespace interchange
