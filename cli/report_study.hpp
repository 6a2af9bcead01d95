// The report's speed-against-accuracy study: for the preview's environment-sampling strategies on
// two presets, and for the integrators on two scenes, each run's relative RMSE against a reference
// as render time goes on, all on this machine in this run (report/convergence.hpp). The references
// are kept in the report folder (report/reference_cache.hpp), so a second report reuses them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "report/convergence.hpp"

namespace lab::cli {

// How long each run and each reference renders: `quick` (the main job's) or `full`.
struct StudyBudget {
    std::string name;
    double run_seconds = 0.0;
    double reference_seconds = 0.0;
};

// Throws lab::InputError("--budget", ...) for a name other than quick and full.
StudyBudget study_budget(const std::string& name);

struct StudyOptions {
    StudyBudget budget;
    std::string size = "128x128";
    std::string env;                   // of the presets' previews
    std::vector<std::string> presets;  // compared by environment-sampling strategy
    std::vector<std::string> scenes;   // compared by integrator
    std::string march_scene;           // its sphere-tracing settings compared; empty: none
    std::string device;
};

// One chart: the runs of one preset or scene against its reference.
struct StudyComparison {
    std::string subject;   // the preset or the scene
    std::string varies;    // what the runs differ in
    std::string baseline;  // the run the others are compared with
    std::string reference_description;
    std::string image, csv;  // the chart and its points, in the report folder
    int reference_spp = 0;
    double reference_relative_noise = 0.0;
    bool reference_reused = false;
    std::vector<report::EqualTimeResult> results;
};

// A sphere-tracing setting: its over-relaxation and normal estimator, what one sample per pixel
// costs with it, and the error it causes against the conservative reference.
struct MarchSetting {
    std::string name;
    double seconds_per_sample = 0.0;  // per sample per pixel
    double error = 0.0;      // relative, against the conservative setting (report::paired_relative_error)
    double noise = 0.0;      // the level below which that error is not told from noise
    double lost_rays = 0.0;  // the share of marches that ran out of steps
};

struct MarchSettingsStudy {
    std::string scene;
    std::string image, csv;
    std::string baseline_description;  // the conservative setting
    int samples_per_pixel = 0;         // of every setting, in each of two halves
    double noise_level = 0.0;          // the largest of the settings' noise
    std::vector<MarchSetting> settings;
};

struct StudyResults {
    std::vector<StudyComparison> comparisons;
    std::optional<MarchSettingsStudy> march;
};

// Runs the study, writing charts, their CSV and the references into `folder`. *device: the device's description.
StudyResults run_speed_accuracy_study(const StudyOptions& options, const std::filesystem::path& folder, std::string* device);

}  // namespace lab::cli
