#include "report/atlas_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "plots/curve_chart.hpp"
#include "plots/heatmap_chart.hpp"
#include "render/camera_setup.hpp"
#include "render/host_kernels.hpp"
#include "render/render_settings.hpp"
#include "scene/compile.hpp"
#include "scene/load_scene.hpp"
#include "common/parallel_for.hpp"

namespace lab::report {

namespace fs = std::filesystem;
namespace hk = render::host_kernels;

namespace {

// The scene as the renderer sees it with `--geometry march`: every object and emitter sphere-traced.
struct MarchedScene {
    scene::Scene scene;
    scene::CompiledScene compiled;
};

MarchedScene march_everything(const scene::Scene& input) {
    scene::CompileOptions options;
    options.march_everything = true;
    MarchedScene m;
    m.scene = scene::apply_options(input, options);
    m.compiled = scene::compile_scene(m.scene, options);
    return m;
}

// The march the renderer runs on a compiled scene (render/renderer.cpp's kernel settings): the
// scene's bound (at least 1), render::RenderSettings' steps, distance and over-relaxation, and the
// surface box; the hit threshold is march_settings_default's.
hk::MarchSettings renderer_march(const scene::CompiledScene& compiled) {
    const render::RenderSettings defaults;
    hk::MarchSettings s = hk::march_settings_default(std::max(compiled.lipschitz, 1.0f));
    s.max_steps = defaults.max_steps;
    s.max_distance = defaults.max_distance;
    s.over_relaxation = defaults.over_relaxation;
    for (int i = 0; i < 3; ++i) {
        s.surface_lo[i] = compiled.surface_lo[i];
        s.surface_hi[i] = compiled.surface_hi[i];
    }
    return s;
}

}  // namespace

MarchSweep sweep_march_settings(const scene::Scene& input, const std::vector<double>& bound_factors, const std::vector<double>& omegas,
                                int width, int height) {
    const MarchedScene m = march_everything(input);
    const hk::MarchSettings base = renderer_march(m.compiled);
    const kernel::Camera camera = render::make_camera(m.compiled.camera, width, height, m.compiled.file);
    const size_t n = size_t(width) * size_t(height), w = size_t(width);
    std::vector<hk::float3> origins(n), directions(n);
    for (size_t k = 0; k < n; ++k)
        hk::camera_generate_ray(&camera, float(k % w) + 0.5f, float(k / w) + 0.5f, hk::make_float2(0.5f, 0.5f), &origins[k], &directions[k]);
    // The reference steps half as far as the scene's bound allows and never over-relaxes; a quarter
    // of the hit threshold keeps its hit test (|field| < bound × threshold) tighter than the march's
    // at factor 1, and 16 times the steps let it finish grazing rays.
    hk::MarchSettings conservative = base;
    conservative.lipschitz = 2.0f * base.lipschitz;
    conservative.over_relaxation = 1.0f;
    conservative.epsilon_relative *= 0.25f;
    conservative.epsilon_min *= 0.25f;
    conservative.max_steps *= 16;
    std::vector<hk::MarchResult> reference(n);
    lab::parallel_for(height, hardware_threads(), [&](int row) {
        const render::HostSceneScope scope(m.scene);
        for (size_t k = size_t(row) * w; k < size_t(row + 1) * w; ++k) reference[k] = hk::march(origins[k], directions[k], 0.0f, conservative);
    });

    MarchSweep sweep;
    sweep.scene = input.file;
    sweep.lipschitz = base.lipschitz;
    for (const hk::MarchResult& r : reference) sweep.reference_unsettled += r.status == MARCH_OUT_OF_STEPS;
    sweep.cells.resize(bound_factors.size() * omegas.size());
    lab::parallel_for(int(sweep.cells.size()), hardware_threads(), [&](int c) {
        const render::HostSceneScope scope(m.scene);
        MarchCell cell;
        cell.bound_factor = bound_factors[size_t(c) / omegas.size()];
        cell.over_relaxation = omegas[size_t(c) % omegas.size()];
        hk::MarchSettings s = base;
        s.lipschitz = float(cell.bound_factor * base.lipschitz);
        s.over_relaxation = float(cell.over_relaxation);
        long steps = 0;
        for (size_t k = 0; k < n; ++k) {
            const hk::MarchResult& ref = reference[k];
            if (ref.status == MARCH_OUT_OF_STEPS) continue;
            const hk::MarchResult r = hk::march(origins[k], directions[k], 0.0f, s);
            ++cell.rays;
            steps += r.steps;
            if (r.status == MARCH_OUT_OF_STEPS)
                ++cell.out_of_steps;
            else if (r.status == MARCH_HIT && (ref.status != MARCH_HIT || std::fabs(double(r.t) - double(ref.t)) > 0.01 * double(ref.t)))
                ++cell.wrong_surface;
            else if (r.status == MARCH_MISS && ref.status == MARCH_HIT)
                ++cell.missed;
        }
        cell.mean_steps = cell.rays > 0 ? double(steps) / cell.rays : 0.0;
        sweep.cells[size_t(c)] = cell;
    });
    return sweep;
}

PrecisionSample sample_precision(double distance, int rays_per_side, double threshold_scale) {
    const double along[3] = {0.6, 0.48, 0.64};  // a unit vector with no zero component: every coordinate grows with the distance
    PrecisionSample sample;
    sample.distance = distance;
    for (int i = 0; i < 3; ++i) {
        sample.centre[i] = float(distance * along[i]);
        sample.origin[i] = float(double(sample.centre[i]) - 3.0 * along[i]);
    }
    // the scene file's numbers print back to the same floats (9 significant digits)
    char text[640];
    std::snprintf(text, sizeof text,
                  R"({"camera": {"type": "pinhole", "position": [%.9g, %.9g, %.9g], "look_at": [%.9g, %.9g, %.9g], "fov_degrees": 40},)"
                  R"( "materials": {"grey": {"albedo": [0.5, 0.5, 0.5]}},)"
                  R"( "objects": [{"name": "ball", "material": "grey", "shape": {"type": "translate", "offset": [%.9g, %.9g, %.9g],)"
                  R"( "child": {"type": "sphere", "radius": 1}}}]})",
                  sample.origin[0], sample.origin[1], sample.origin[2], sample.centre[0], sample.centre[1], sample.centre[2], sample.centre[0],
                  sample.centre[1], sample.centre[2]);
    const MarchedScene m = march_everything(scene::parse_scene(text, "precision_sphere.json"));
    hk::MarchSettings s = renderer_march(m.compiled);
    s.epsilon_relative *= float(threshold_scale);
    s.epsilon_min *= float(threshold_scale);
    // two unit directions across the line of sight from the origin to the centre (along · (0.64, 0, -0.6) = 0)
    const double across = std::sqrt(0.64 * 0.64 + 0.6 * 0.6);
    const double e1[3] = {0.64 / across, 0.0, -0.6 / across};
    const double e2[3] = {along[1] * e1[2] - along[2] * e1[1], along[2] * e1[0] - along[0] * e1[2], along[0] * e1[1] - along[1] * e1[0]};
    const hk::float3 o(sample.origin[0], sample.origin[1], sample.origin[2]);
    const render::HostSceneScope scope(m.scene);
    for (int a = 0; a < rays_per_side; ++a)
        for (int b = 0; b < rays_per_side; ++b) {
            const double u = 0.85 * (2.0 * (a + 0.5) / rays_per_side - 1.0), w = 0.85 * (2.0 * (b + 0.5) / rays_per_side - 1.0);
            if (u * u + w * w > 0.85 * 0.85) continue;
            // towards the point (u, w) of the plane through the centre across the line of sight, relative to the origin
            double v[3], length = 0.0;
            for (int i = 0; i < 3; ++i) {
                v[i] = 3.0 * along[i] + u * e1[i] + w * e2[i];
                length += v[i] * v[i];
            }
            PrecisionRay ray;
            for (int i = 0; i < 3; ++i) ray.direction[i] = float(v[i] / std::sqrt(length));
            const hk::float3 d(ray.direction[0], ray.direction[1], ray.direction[2]);
            const hk::MarchResult r = hk::march(o, d, 0.0f, s);
            ray.hit = r.status == MARCH_HIT;
            ray.steps = r.steps;
            ray.t = r.t;
            ray.threshold = double(s.lipschitz) * double(hk::march_epsilon(s, r.t));
            // |o + t d - c|^2 = 1 for the float ray, in double: the nearer root, in the form without cancellation
            double dd = 0.0, od = 0.0, oo = 0.0;
            for (int i = 0; i < 3; ++i) {
                const double oc = double(sample.origin[i]) - double(sample.centre[i]);
                dd += double(ray.direction[i]) * ray.direction[i];
                od += oc * ray.direction[i];
                oo += oc * oc;
            }
            const double half_b = od, c = oo - 1.0, root = std::sqrt(std::max(half_b * half_b - dd * c, 0.0));
            ray.t_exact = c / (-half_b + root);
            sample.rays.push_back(ray);
        }
    return sample;
}

// docs/scenes.md's displacement example alone, framed so that about half the rays meet it; its
// steepest slope is about 1.53 (docs/scenes.md, "The Lipschitz bound"), below the declared 1.64.
const char* atlas_displaced_sphere() {
    return R"({
  "description": "A sine-displaced sphere alone: Lipschitz bound 1.64.",
  "camera": {"type": "pinhole", "position": [0, 0.8, 2.4], "look_at": [0, 0, 0], "fov_degrees": 40},
  "materials": {"grey": {"albedo": [0.5, 0.5, 0.5]}},
  "objects": [{"name": "bumpy", "material": "grey",
               "shape": {"type": "displace", "amplitude": 0.08, "frequency": 8, "child": {"type": "sphere", "radius": 0.8}}}]
})";
}

namespace {

// The sphere-tracing grid: bound factors from a bound 3.3 times too small to 3 times too large, and
// over-relaxation from plain to nearly 2 (the renderer's 1.5 among them).
const std::vector<double> kBoundFactors = {0.3, 0.35, 0.4, 0.45, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0};
const std::vector<double> kOmegas = {1.0, 1.2, 1.35, 1.5, 1.65, 1.8, 1.95};
constexpr int kRaysWide = 64, kRaysHigh = 48;
constexpr double kTolerableLoss = 0.01;  // the share of rays a setting may lose and still count as agreeing with the reference

const MarchCell& cell_at(const MarchSweep& sweep, double factor, double omega) {
    for (const MarchCell& c : sweep.cells)
        if (c.bound_factor == factor && c.over_relaxation == omega) return c;
    throw std::logic_error("atlas: no sphere-tracing cell at factor " + std::to_string(factor) + ", ω " + std::to_string(omega));
}

// The smallest factor from which on (at this ω) no setting loses more than kTolerableLoss; 0 when even the largest does.
double safe_factor(const MarchSweep& sweep, double omega) {
    double safe = 0.0;
    for (auto f = kBoundFactors.rbegin(); f != kBoundFactors.rend(); ++f) {
        if (cell_at(sweep, *f, omega).lost_fraction() > kTolerableLoss) break;
        safe = *f;
    }
    return safe;
}

std::string factor_text(double factor) { return factor > 0.0 ? number_text(factor, 3) : "none"; }

// The sweep's name on the page: the scene file's stem.
std::string scene_name(const MarchSweep& sweep) { return fs::path(sweep.scene).stem().string(); }

AtlasEntry lost_rays_entry(const fs::path& folder, const std::vector<MarchSweep>& sweeps) {
    AtlasEntry entry{"Sphere tracing: rays lost over the Lipschitz bound the march trusts and its over-relaxation", "atlas_march_lost.png",
                     "atlas_march_lost.csv", "", "", {}};
    std::vector<plots::HeatmapPanel> panels;
    entry.table.header = {"scene", "ω", "lost at factor 1", "at factor 0.5", "losing at most 1 % from factor", "most lost", "at factor",
                          "there: wrong surface", "missed", "out of steps"};
    std::string finding;
    for (const MarchSweep& sweep : sweeps) {
        plots::HeatmapPanel panel{scene_name(sweep) + " (bound " + number_text(sweep.lipschitz, 3) + ")", {}};
        for (const MarchCell& c : sweep.cells) panel.values.push_back(100.0 * c.lost_fraction());
        panels.push_back(std::move(panel));
        for (double omega : kOmegas) {
            const MarchCell* most = &cell_at(sweep, kBoundFactors.front(), omega);
            for (double f : kBoundFactors)
                if (cell_at(sweep, f, omega).lost_fraction() > most->lost_fraction()) most = &cell_at(sweep, f, omega);
            entry.table.rows.push_back({text_cell(scene_name(sweep)), number_cell(omega, 3), text_cell(percent_text(cell_at(sweep, 1.0, omega).lost_fraction(), 2)),
                                        text_cell(percent_text(cell_at(sweep, 0.5, omega).lost_fraction(), 2)), text_cell(factor_text(safe_factor(sweep, omega))),
                                        text_cell(percent_text(most->lost_fraction(), 2)), number_cell(most->bound_factor, 3),
                                        number_cell(most->wrong_surface, 6), number_cell(most->missed, 6), number_cell(most->out_of_steps, 6)});
        }
        double worst_from_one = 0.0;  // over every setting with a bound at least the scene's
        for (const MarchCell& c : sweep.cells)
            if (c.bound_factor >= 1.0) worst_from_one = std::max(worst_from_one, c.lost_fraction());
        const MarchCell& plain_small = cell_at(sweep, 0.4, 1.0);
        const MarchCell& relaxed_small = cell_at(sweep, 0.4, kOmegas.back());
        const char* how_lost = plain_small.wrong_surface >= std::max(plain_small.missed, plain_small.out_of_steps) ? "on the wrong surface"
                               : plain_small.missed >= plain_small.out_of_steps                                  ? "missed"
                                                                                                               : "out of steps";
        char line[480];
        std::snprintf(line, sizeof line,
                      "%s%s: with plain steps (ω 1) every factor from %s up loses at most 1 %% of the rays (%s at 0.5); at 0.4 %s are lost, "
                      "most %s, and %s with ω %.3g; from factor 1 up no setting loses more than %s",
                      finding.empty() ? "" : "; ", scene_name(sweep).c_str(), factor_text(safe_factor(sweep, 1.0)).c_str(),
                      percent_text(cell_at(sweep, 0.5, 1.0).lost_fraction(), 2).c_str(), percent_text(plain_small.lost_fraction(), 2).c_str(), how_lost,
                      percent_text(relaxed_small.lost_fraction(), 2).c_str(), kOmegas.back(), percent_text(worst_from_one, 2).c_str());
        finding += line;
    }
    plots::write_heatmap_chart(panels, kBoundFactors, kOmegas, "bound factor (× the scene's Lipschitz bound)", "over-relaxation ω",
                               "rays lost (%)", 0.0, "Sphere tracing: where a too-small bound loses rays (red)", (folder / entry.image).string(),
                               (folder / entry.csv).string(), true);
    entry.finding = "Rays lost against a conservative march: " + finding + ".";
    entry.how = "Each cell marches one ray through the centre of each of " + std::to_string(kRaysWide) + " × " + std::to_string(kRaysHigh) +
                " pixels of the scene's camera, everything sphere-traced (--geometry march), with the renderer's march (" +
                std::to_string(render::RenderSettings{}.max_steps) + " steps, the default hit threshold) but distances divided by the bound "
                "factor times the scene's Lipschitz bound (below 1: the march trusts a bound smaller than the field's slope and steps too "
                "far) and over-relaxed by ω. A ray is lost when it hits where the reference misses or more than 1 % of the reference's "
                "distance away from its hit (wrong surface), misses where the reference hits, or runs out of steps; the reference marches "
                "with twice the bound, ω = 1, a quarter of the hit threshold and 16 times the steps. The few rays lost at factor 1 and above "
                "pass a silhouette within the hit threshold, which the march takes for a hit (it tests |field| against factor × bound × "
                "threshold, looser with the factor) and the reference's tighter threshold passes. The factor axis is logarithmic.";
    return entry;
}

AtlasEntry steps_entry(const fs::path& folder, const std::vector<MarchSweep>& sweeps) {
    AtlasEntry entry{"Sphere tracing: steps per ray over the Lipschitz bound and over-relaxation", "atlas_march_steps.png",
                     "atlas_march_steps.csv", "", "", {}};
    std::vector<plots::HeatmapPanel> panels;
    entry.table.header = {"scene", "ω", "mean steps at factor 0.5", "at factor 1", "at factor 2", "at factor 3", "fewest losing at most 1 %",
                          "at factor"};
    std::string finding;
    for (const MarchSweep& sweep : sweeps) {
        const double baseline = cell_at(sweep, 1.0, 1.0).mean_steps;
        plots::HeatmapPanel panel{scene_name(sweep) + " (" + number_text(baseline, 3) + " steps at factor 1, ω 1)", {}};
        for (const MarchCell& c : sweep.cells) panel.values.push_back(std::log2(c.mean_steps / baseline));
        panels.push_back(std::move(panel));
        for (double omega : kOmegas) {
            const MarchCell* fewest = nullptr;
            for (double f : kBoundFactors) {
                const MarchCell& c = cell_at(sweep, f, omega);
                if (c.lost_fraction() <= kTolerableLoss && (!fewest || c.mean_steps < fewest->mean_steps)) fewest = &c;
            }
            entry.table.rows.push_back({text_cell(scene_name(sweep)), number_cell(omega, 3), number_cell(cell_at(sweep, 0.5, omega).mean_steps, 3),
                                        number_cell(cell_at(sweep, 1.0, omega).mean_steps, 3), number_cell(cell_at(sweep, 2.0, omega).mean_steps, 3),
                                        number_cell(cell_at(sweep, 3.0, omega).mean_steps, 3),
                                        fewest ? number_cell(fewest->mean_steps, 3) : text_cell("-"),
                                        fewest ? number_cell(fewest->bound_factor, 3) : text_cell("-")});
        }
        const MarchCell* best = &cell_at(sweep, 1.0, 1.0);
        for (double omega : kOmegas)
            if (cell_at(sweep, 1.0, omega).mean_steps < best->mean_steps) best = &cell_at(sweep, 1.0, omega);
        char line[320];
        std::snprintf(line, sizeof line,
                      "%s%s: %.3g steps per ray at factor 1 with plain steps, %.2f× as many at factor 2 and %.2f× at 3; at factor 1 "
                      "ω %.3g takes the fewest (%.0f %% fewer), ω %.3g %.0f %% %s",
                      finding.empty() ? "" : "; ", scene_name(sweep).c_str(), baseline, cell_at(sweep, 2.0, 1.0).mean_steps / baseline,
                      cell_at(sweep, 3.0, 1.0).mean_steps / baseline, best->over_relaxation, 100.0 * (1.0 - best->mean_steps / baseline),
                      kOmegas.back(), 100.0 * std::fabs(cell_at(sweep, 1.0, kOmegas.back()).mean_steps / baseline - 1.0),
                      cell_at(sweep, 1.0, kOmegas.back()).mean_steps > baseline ? "more" : "fewer");
        finding += line;
    }
    plots::write_heatmap_chart(panels, kBoundFactors, kOmegas, "bound factor (× the scene's Lipschitz bound)", "over-relaxation ω",
                               "log2(mean steps / mean steps at factor 1, ω 1)", 0.0,
                               "Sphere tracing: what the bound costs in steps (red: more, blue: fewer)", (folder / entry.image).string(),
                               (folder / entry.csv).string(), true);
    entry.finding = "What the bound costs: " + finding + ".";
    entry.how = "The same marches as the lost rays' entry: each cell is log2 of the mean number of distance evaluations per ray (lost "
                "rays included) over its value at factor 1 with plain steps, on a scale diverging at 0. The table gives the mean steps and, "
                "per ω, the fewest of a factor that loses at most 1 % of the rays.";
    return entry;
}

// The precision entry's distances, 1 to 1e5 at four per decade, and its rays: a 20 × 20 grid over
// the disc, about 300 rays per distance.
constexpr int kPrecisionSteps = 20, kPrecisionRaysPerSide = 20;
constexpr double kErrorFloor = 1e-9;  // below float's resolution near the sphere: shown as 1e-9 on the log axis

// One distance's figures.
struct PrecisionFigures {
    double distance = 0.0;
    int rays = 0, lost = 0;
    double largest = 0.0, median = 0.0;  // |t - t_exact| / radius over the hits
    double threshold = 0.0;              // the hits' mean stopping threshold / radius
    double mean_t = 0.0;                 // the hits' mean distance along the ray
    double spacing = 0.0;                // float's spacing at the sphere's farthest coordinate / radius
    double mean_steps = 0.0;
};

PrecisionFigures precision_figures(const PrecisionSample& sample) {
    PrecisionFigures f;
    f.distance = sample.distance;
    f.rays = int(sample.rays.size());
    std::vector<double> errors;
    double thresholds = 0.0, steps = 0.0, ts = 0.0;
    for (const PrecisionRay& r : sample.rays) {
        steps += r.steps;
        if (!r.hit) {
            ++f.lost;
            continue;
        }
        errors.push_back(std::fabs(r.t - r.t_exact));
        thresholds += r.threshold;
        ts += r.t;
    }
    f.mean_steps = f.rays > 0 ? steps / f.rays : 0.0;
    if (!errors.empty()) {
        std::sort(errors.begin(), errors.end());
        f.largest = errors.back();
        f.median = errors[errors.size() / 2];
        f.threshold = thresholds / double(errors.size());
        f.mean_t = ts / double(errors.size());
    }
    float farthest = 0.0f;
    for (float c : sample.centre) farthest = std::max(farthest, std::fabs(c) + 1.0f);
    f.spacing = double(std::nextafter(farthest, INFINITY)) - double(farthest);
    return f;
}

// A distance rounded to two significant digits, in plain digits ("5600", "18000").
std::string distance_text(double d) {
    const double unit = std::pow(10.0, std::floor(std::log10(d)) - 1.0);
    char text[32];
    std::snprintf(text, sizeof text, "%.0f", std::max(std::round(d / unit) * unit, 1.0));
    return text;
}

AtlasEntry precision_entry(const fs::path& folder) {
    std::vector<PrecisionFigures> figures;
    for (int k = 0; k <= kPrecisionSteps; ++k) figures.push_back(precision_figures(sample_precision(std::pow(10.0, 5.0 * k / kPrecisionSteps), kPrecisionRaysPerSide)));
    AtlasEntry entry{"Precision: the float march's hit error against the distance from the origin", "atlas_precision.png", "atlas_precision.csv",
                     "", "", {}};
    plots::Curve largest{"largest hit error", {}, {}}, median{"median hit error", {}, {}};
    plots::Curve threshold{"the march's hit threshold", {}, {}, true}, spacing{"float spacing at the surface", {}, {}, true},
        thousandth{"1e-3 of the radius", {}, {}, true};
    entry.table.header = {"distance from the origin", "largest hit error", "median hit error", "hit threshold", "float spacing", "rays lost",
                          "mean steps"};
    const PrecisionFigures* first_large = nullptr;  // the first distance whose largest error exceeds 1e-3 of the radius
    const PrecisionFigures* first_lost = nullptr;
    const PrecisionFigures* last_sound = nullptr;    // the last distance before either
    const PrecisionFigures* first_coarse = nullptr;  // the first distance whose float spacing exceeds the hit threshold
    for (const PrecisionFigures& f : figures) {
        if (f.lost < f.rays) {
            largest.x.push_back(f.distance), largest.y.push_back(std::max(f.largest, kErrorFloor));
            median.x.push_back(f.distance), median.y.push_back(std::max(f.median, kErrorFloor));
            threshold.x.push_back(f.distance), threshold.y.push_back(f.threshold);
        }
        spacing.x.push_back(f.distance), spacing.y.push_back(f.spacing);
        thousandth.x.push_back(f.distance), thousandth.y.push_back(1e-3);
        if (!first_large && f.largest > 1e-3) first_large = &f;
        if (!first_lost && f.lost > 0) first_lost = &f;
        if (!first_large && !first_lost) last_sound = &f;
        if (!first_coarse && f.lost < f.rays && f.spacing > f.threshold) first_coarse = &f;
        const bool any_hit = f.lost < f.rays;
        entry.table.rows.push_back({number_cell(f.distance, 3), any_hit ? number_cell(f.largest, 3) : text_cell("-"),
                                    any_hit ? number_cell(f.median, 3) : text_cell("-"), any_hit ? number_cell(f.threshold, 3) : text_cell("-"),
                                    number_cell(f.spacing, 3), text_cell(percent_text(double(f.lost) / f.rays, 2)), number_cell(f.mean_steps, 3)});
    }
    plots::write_curve_chart({largest, median, threshold, spacing, thousandth}, "distance of the sphere's centre from the origin",
                             "hit error / radius", "Float precision: the hit error of a unit sphere far from the origin",
                             (folder / entry.image).string(), (folder / entry.csv).string());
    const PrecisionFigures& near = figures.front();
    const PrecisionFigures& far = figures.back();
    char finding[700];
    std::snprintf(finding, sizeof finding,
                  "Near the origin the hit error is the hit threshold's (largest %.2g, median %.2g of the radius, threshold %.2g); float's "
                  "spacing at the surface exceeds the threshold from %s, the largest error exceeds 1e-3 of the radius from %s and rays are "
                  "lost (out of steps: no float point along them lies within the threshold of the surface) from %s, %s of them at %s. "
                  "Seen from about %.2g units, surfaces farther than about %s from the origin must be recentred (docs/scenes.md, "
                  "\"Far from the origin\").",
                  near.largest, near.median, near.threshold, first_coarse ? distance_text(first_coarse->distance).c_str() : "nowhere up to 1e5",
                  first_large ? distance_text(first_large->distance).c_str() : "nowhere up to 1e5",
                  first_lost ? distance_text(first_lost->distance).c_str() : "nowhere up to 1e5", percent_text(double(far.lost) / far.rays, 2).c_str(),
                  distance_text(far.distance).c_str(), near.mean_t, last_sound ? distance_text(last_sound->distance).c_str() : "1");
    entry.finding = finding;
    entry.how = "A sphere of radius 1 centred at each distance (1 to 1e5, four per decade) from the origin along (0.6, 0.48, 0.64), "
                "sphere-traced in float as a kernel does (the scene's translation and sphere evaluated by the same single-source code, "
                "the renderer's march and hit threshold), one ray from a point 3 radii nearer the origin towards each of a " +
                std::to_string(kPrecisionRaysPerSide) + " × " + std::to_string(kPrecisionRaysPerSide) +
                " grid of points across the sphere (those within 0.85 radii of its centre), so that only the absolute position changes; "
                "each hit's distance is compared with the exact intersection of the same float ray, computed in double. Dashed: the hit "
                "threshold (1e-4 of the distance along the ray), float's spacing at the sphere's largest coordinate, and 1e-3 of the "
                "radius. Errors are shown no lower than 1e-9.";
    return entry;
}

}  // namespace

std::vector<AtlasEntry> write_geometry_atlas(const fs::path& folder, const std::string& metaballs_scene) {
    const std::vector<MarchSweep> sweeps = {
        sweep_march_settings(scene::load_scene(metaballs_scene), kBoundFactors, kOmegas, kRaysWide, kRaysHigh),
        sweep_march_settings(scene::parse_scene(atlas_displaced_sphere(), "displaced_sphere.json"), kBoundFactors, kOmegas, kRaysWide, kRaysHigh)};
    return {lost_rays_entry(folder, sweeps), steps_entry(folder, sweeps), precision_entry(folder)};
}

}  // namespace lab::report
