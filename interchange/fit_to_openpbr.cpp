#include "interchange/fit_to_openpbr.hpp"

#include <filesystem>

#include "brdf/host/merl_file.hpp"
#include "common/input_error.hpp"
#include "fit/fit_metric.hpp"
#include "fit/fit_report.hpp"
#include "fit/fit_space.hpp"

namespace interchange {

OpenpbrFit fit_to_openpbr(const brdf::Preset& preset, const lab::fit::FitOptions& options, const lab::fit::PairGrid& grid) {
    const brdf::Material& m = preset.material;
    if (m.model == BRDF_MODEL_OPENPBR) throw lab::InputError(preset.source, "model", "already openpbr: nothing to fit");
    lab::fit::FitSpace space;
    space.openpbr = true;
    lab::fit::PairGrid pair_grid = grid;
    std::vector<lab::fit::FitPair> pairs;
    std::string input = preset.source;
    if (m.model == BRDF_MODEL_MEASURED) {
        std::filesystem::path file(preset.measured);
        if (file.is_relative()) file = std::filesystem::path(preset.source).parent_path() / file;
        input = file.string();
        pair_grid.phi_h_count = 1;  // an isotropic table
        pairs = lab::fit::fit_pairs(brdf::read_merl_file(input), pair_grid);
    } else {
        if (m.weight_specular > 0.0f || m.weight_transmission > 0.0f)
            throw lab::InputError(preset.source, "lobes",
                                  "a mirror or transmission lobe cannot be fitted from reflectance at direction pairs: convert the material as an openpbr preset");
        space.anisotropic = m.anisotropic > 0.0f;
        pair_grid.phi_h_count = space.anisotropic ? 4 : 1;
        // the directions of the grid's pairs; their values are the material's own
        brdf::MeasuredTable directions;
        directions.rgb.assign(3 * std::size_t(MERL_ENTRY_COUNT), 0.0f);
        pairs = lab::fit::fit_pairs(directions, pair_grid);
        for (lab::fit::FitPair& p : pairs) p.measured = lab::fit::model_value(m, p);
    }
    const lab::fit::FitResult result = lab::fit::fit_material(pairs, space, options);
    OpenpbrFit out;
    out.preset.name = preset.name;
    out.preset.description = preset.description;
    out.preset.source = preset.source;
    out.preset.material = result.material;
    out.error = result.error;
    out.report = lab::fit::fit_report(input, space, result, lab::fit::error_breakdown(result.material, pairs));
    out.report["model"] = "openpbr";
    out.report["fitted_from"] = std::string(brdf::model_name(m.model)) + (m.model == BRDF_MODEL_LAB ? std::string(" (") + brdf::distribution_name(m.distribution) + ")" : "");
    return out;
}

}  // namespace interchange
