// The stability atlas's geometry entries (report/stability_atlas.hpp): where sphere tracing fails.
// Lost rays and cost over the Lipschitz bound the march trusts and its over-relaxation, on a scene
// as the renderer marches it; and the hit error of the float march against the distance of the
// surface from the origin. Both run the kernels' march compiled for the host (render/host_kernels.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "report/stability_atlas.hpp"
#include "scene/scene.hpp"

namespace lab::report {

// One march setting's outcome on a scene's camera rays, each against a conservative reference march.
struct MarchCell {
    double bound_factor = 1.0;     // the march divides distances by this × the scene's Lipschitz bound
    double over_relaxation = 1.0;  // ω
    int rays = 0;                  // rays whose reference hit or missed (not out of steps)
    int wrong_surface = 0;         // a hit where the reference misses, or more than 1 % of t off the reference's
    int missed = 0;                // the reference hits, the march misses
    int out_of_steps = 0;
    double mean_steps = 0.0;       // distance evaluations per ray, over `rays`
    double lost_fraction() const { return rays > 0 ? double(wrong_surface + missed + out_of_steps) / rays : 0.0; }
};

struct MarchSweep {
    std::string scene;
    float lipschitz = 1.0f;           // the compiled scene's bound, as the renderer uses it (at least 1)
    int reference_unsettled = 0;      // rays the reference ran out of steps on, left out of every cell
    std::vector<MarchCell> cells;     // cells[i * omegas.size() + j] at (bound_factors[i], omegas[j])
};

// The displaced sphere the sphere-tracing entries march beside the metaballs, as a scene file's text:
// radius 0.8 plus 0.08 sin(8x) sin(8y) sin(8z), declared bound 1 + 0.08 × 8 = 1.64.
const char* atlas_displaced_sphere();

// The march of render::RenderSettings' defaults (steps, distance; the hit threshold of
// march_settings_default; the compiled scene's surface box) on `scene` with everything sphere-traced
// (scene::CompileOptions::march_everything), for every bound factor × over-relaxation, on the camera
// rays through the centres of width × height pixels; the reference marches with
// twice the bound, ω = 1, a quarter of the hit threshold and 16 times the steps. The cells are
// computed on the machine's threads; they do not depend on how many.
MarchSweep sweep_march_settings(const scene::Scene& scene, const std::vector<double>& bound_factors, const std::vector<double>& omegas,
                                int width, int height);

// The float march of a sphere of radius 1 whose centre lies `distance` from the origin along
// (0.6, 0.48, 0.64), each ray from a point 3 radii nearer the origin towards a grid of points over
// the sphere's disc (every ray meets the sphere), against the ray's exact intersection computed in
// double for the same float ray, so that only the absolute position changes with the distance.
struct PrecisionRay {
    float direction[3] = {0.0f, 0.0f, 0.0f};  // as marched (unit in float)
    bool hit = false;           // else missed or out of steps: lost
    int steps = 0;
    double t = 0.0;             // the march's
    double t_exact = 0.0;       // the float ray's first intersection, in double
    double threshold = 0.0;     // where the march stops: |field| below this (the hit threshold at t times the bound)
};

struct PrecisionSample {
    double distance = 0.0;
    float centre[3] = {0.0f, 0.0f, 0.0f};  // as the scene holds it
    float origin[3] = {0.0f, 0.0f, 0.0f};  // every ray's
    std::vector<PrecisionRay> rays;
};

// `rays_per_side`² grid points, those within 0.85 radii of the centre's line of sight kept. The march
// is the renderer's (render::RenderSettings' steps, distance and over-relaxation, the compiled
// scene's bound and surface box) with march_settings_default's hit threshold times `threshold_scale`.
PrecisionSample sample_precision(double distance, int rays_per_side, double threshold_scale = 1.0);

// The sphere-tracing entries (lost rays, and steps, over bound factor × over-relaxation on the
// metaballs of `metaballs_scene` and a displaced sphere) and the precision entry; writes their
// charts and CSV into `folder`.
std::vector<AtlasEntry> write_geometry_atlas(const std::filesystem::path& folder, const std::string& metaballs_scene);

}  // namespace lab::report
