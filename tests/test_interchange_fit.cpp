// Lab materials carried to openpbr by fitting (interchange/fit_to_openpbr): a GGX conductor, which
// openpbr's metal expresses exactly (F82 with a white tint is Schlick's curve), is found; what a
// reflectance fit cannot hold is refused. On a coarse grid of pairs and few starts, to stay cheap.
#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "brdf/brdf.hpp"
#include "brdf/host/merl_file.hpp"
#include "brdf/host/parameters.hpp"
#include "brdf/host/preset.hpp"
#include "common/input_error.hpp"
#include "fit/fit_metric.hpp"
#include "fit/fit_space.hpp"
#include "interchange/fit_to_openpbr.hpp"
#include "tests/interchange_checks.hpp"

namespace fit_tests {

brdf::Preset lab_conductor() {
    brdf::Preset p;
    p.name = "conductor";
    p.source = "conductor.json";
    p.material = brdf::default_material(BRDF_MODEL_LAB);
    p.material.albedo[0] = 0.95f;
    p.material.albedo[1] = 0.64f;
    p.material.albedo[2] = 0.54f;
    p.material.roughness = 0.35f;
    p.material.metallic = 1.0f;
    p.material.weight_diffuse = 0.0f;
    p.material.weight_glossy = 1.0f;
    return p;
}

TEST_CASE("a lab GGX conductor fits openpbr's metal at least as well as its exact counterpart", "[interchange][fit]") {
    const brdf::Preset lab = lab_conductor();
    lab::fit::FitOptions options;
    options.starts = 2;
    options.max_evaluations = 600;
    const lab::fit::PairGrid grid{6, 6, 20, 1};
    const interchange::OpenpbrFit fit = interchange::fit_to_openpbr(lab, options, grid);
    CHECK(fit.preset.material.model == BRDF_MODEL_OPENPBR);
    CHECK(fit.preset.name == "conductor");
    CHECK(fit.report.at("model") == "openpbr");
    CHECK(fit.report.at("fitted_from") == "lab (ggx)");
    // the counterpart: openpbr's metal of the same colour and roughness, on the same pairs
    brdf::Material counterpart = brdf::default_material(BRDF_MODEL_OPENPBR);
    for (int c = 0; c < 3; ++c) counterpart.albedo[c] = lab.material.albedo[c];
    counterpart.roughness = 0.35f;
    counterpart.metallic = 1.0f;
    brdf::MeasuredTable directions;
    directions.rgb.assign(3 * std::size_t(MERL_ENTRY_COUNT), 0.0f);
    std::vector<lab::fit::FitPair> pairs = lab::fit::fit_pairs(directions, grid);
    for (lab::fit::FitPair& p : pairs) p.measured = lab::fit::model_value(lab.material, p);
    const double floor = lab::fit::fit_error(counterpart, pairs);
    INFO("fit error " << fit.error << ", counterpart's " << floor);
    // the fit report's own margin for starts that found the same floor (fit/fit_report.hpp)
    CHECK(fit.error <= std::max(1.01 * floor, floor + 1e-4));
    CHECK(fit.report.at("error").at("total").get<double>() == Approx(fit.error).epsilon(1e-12));
    // and it is a fit, not the default: the default metal of grey 0.8 is far off
    brdf::Material grey = counterpart;
    grey.albedo[0] = grey.albedo[1] = grey.albedo[2] = 0.8f;
    CHECK(lab::fit::fit_error(grey, pairs) > 100.0 * std::max(fit.error, 1e-4));
}

TEST_CASE("a measured material fits from its table's entries; the report names the file", "[interchange][fit]") {
    // a MERL file made from the lab conductor (brdf::tabulate_merl), as the project makes its own
    const brdf::Preset lab = lab_conductor();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "dtoadq-interchange-fit";
    std::filesystem::create_directories(dir);
    brdf::write_merl_file((dir / "conductor.binary").string(),
                          brdf::tabulate_merl([&](brdf::float3 wo, brdf::float3 wi) { return brdf::bsdf_eval(&lab.material, wo, wi); }, "conductor"));
    std::ofstream(dir / "measured.json") << R"({"name": "measured conductor", "measured": "conductor.binary"})";
    const brdf::Preset measured = brdf::load_preset((dir / "measured.json").string());
    lab::fit::FitOptions options;
    options.starts = 2;
    options.max_evaluations = 600;
    const interchange::OpenpbrFit fit = interchange::fit_to_openpbr(measured, options, lab::fit::PairGrid{6, 6, 20, 1});
    const interchange::OpenpbrFit from_lab = interchange::fit_to_openpbr(lab, options, lab::fit::PairGrid{6, 6, 20, 1});
    std::filesystem::remove_all(dir);
    CHECK(fit.report.at("fitted_from") == "measured");
    CHECK(fit.report.at("measured") == (dir / "conductor.binary").string());
    // the table holds the lab material's values at the same bin centres, in doubles of float
    // values: the same pairs and targets up to MERL's scaling, so the same floor
    INFO("measured " << fit.error << ", lab " << from_lab.error);
    CHECK(fit.error <= std::max(1.01 * from_lab.error, from_lab.error + 1e-4));
    CHECK(fit.preset.name == "measured conductor");
}

TEST_CASE("the openpbr fit space maps a material to its vector and back exactly", "[interchange][fit]") {
    for (bool anisotropic : {false, true}) {
        lab::fit::FitSpace space;
        space.openpbr = true;
        space.anisotropic = anisotropic;
        brdf::Material m = brdf::default_material(BRDF_MODEL_OPENPBR);
        m.albedo[0] = 0.3f;
        m.albedo[1] = 0.6f;
        m.albedo[2] = 0.9f;
        m.roughness = 0.45f;
        m.metallic = 0.7f;
        m.ior = 1.8f;
        m.anisotropic = anisotropic ? 0.6f : 0.0f;
        const std::vector<double> x = lab::fit::parameters_from_material(space, m);
        REQUIRE(x.size() == lab::fit::fit_parameters(space).size());
        const brdf::Material back = lab::fit::material_from_parameters(space, x);
        CHECK(std::memcmp(&back, &m, sizeof m) == 0);
        for (size_t k = 0; k < x.size(); ++k) {
            INFO(lab::fit::fit_parameters(space)[k].name);
            CHECK(x[k] >= lab::fit::fit_parameters(space)[k].min);
            CHECK(x[k] <= lab::fit::fit_parameters(space)[k].max);
        }
    }
}

TEST_CASE("a lab material with a mirror or transmission lobe is refused by the fit, naming the preset", "[interchange][fit]") {
    brdf::Preset glass = lab_conductor();
    glass.material.weight_transmission = 1.0f;
    const std::string error = interchange_checks::input_error_of(
        [&] { interchange::fit_to_openpbr(glass, lab::fit::FitOptions{}, lab::fit::PairGrid{6, 6, 20, 1}); });
    CHECK(error.rfind("conductor.json: lobes: a mirror or transmission lobe cannot be fitted", 0) == 0);
}

}  // namespace fit_tests
