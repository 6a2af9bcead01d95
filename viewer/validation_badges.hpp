// The validation badges: `dtoadq validate`'s checks (validation::validate_material: chi-square of
// the sampler, reciprocity, white furnace) of the edited material, on a background thread whenever
// it changes. A newer edit cancels the run of an older one (ValidationOptions::cancelled); each
// badge shows pass or fail with its figure.
#pragma once

#include <memory>
#include <mutex>
#include <string>

#include "brdf/host/preset.hpp"
#include "validation/report.hpp"
#include "viewer/latest_job.hpp"

namespace lab::viewer {

class ValidationBadges {
public:
    void set_material(const brdf::Preset& preset);
    void draw();
    // "chi-square PASS (p 0.33), reciprocity PASS (3.6e-07), energy PASS (0.9964 at 0 deg)", or
    // "running" before the first result.
    std::string summary();
    bool running() const { return job_.busy(); }

private:
    std::mutex mutex_;
    std::shared_ptr<const validation::MaterialValidation> result_;
    int cancelled_runs_ = 0;
    LatestJob job_;
};

}  // namespace lab::viewer
