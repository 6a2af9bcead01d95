// The lobe panel: the polar plot in the plane of incidence, a 3D view of the lobe and the
// directional-albedo curve, for material A (the one being edited) with B overlaid, drawn with
// ImDrawList. The numbers are `dtoadq lobe`'s and `dtoadq albedo`'s (analysis::compute_lobe,
// analysis::albedo_curve), computed on a background thread whenever A, B or the incident direction
// changes; the panel draws the latest result it has.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "analysis/albedo_curve.hpp"
#include "analysis/lobe_data.hpp"
#include "brdf/host/preset.hpp"
#include "viewer/latest_job.hpp"

namespace lab::viewer {

class LobePanel {
public:
    // A or B changed: recompute (in the background).
    void set_materials(const brdf::Preset& a, const brdf::Preset& b);
    // Draws into the current ImGui window. Dragging on the polar plot sets the incident direction,
    // dragging on the 3D view turns it.
    void draw();

private:
    struct Result {
        analysis::LobeData lobe[2];
        std::vector<analysis::AlbedoPoint> albedo[2];
    };
    void recompute();
    void draw_polar(const Result& r);
    void draw_3d(const Result& r);
    void draw_albedo(const Result& r);

    brdf::Preset a_, b_;
    float theta_in_ = 30.0f, phi_in_ = 0.0f;
    float yaw_ = 35.0f, pitch_ = 20.0f;  // of the 3D view, degrees
    std::mutex mutex_;
    std::shared_ptr<const Result> result_;
    LatestJob job_;  // last, so that it stops before the rest goes
};

}  // namespace lab::viewer
