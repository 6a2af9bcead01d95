#include "viewer/validation_badges.hpp"

#include <cstdio>

#include <imgui.h>

namespace lab::viewer {

namespace {

// Fewer chi-square samples than the command's default (1e6): a run takes about a second on two
// cores, so the badges follow the sliders. The test's power is lower; `dtoadq validate` is the record.
validation::ValidationOptions badge_options() {
    validation::ValidationOptions o;
    o.chi_square_samples = 100000;
    o.reciprocity_pairs = 50000;
    o.threads = 1;  // the render worker has the other core
    return o;
}

struct Badge {
    bool passed;
    std::string text;
};

void badges(const validation::MaterialValidation& v, Badge out[3]) {
    char figure[128];
    if (v.continuous)
        std::snprintf(figure, sizeof figure, "chi-square (smallest p %.3g)", v.smallest_p_value);
    else
        std::snprintf(figure, sizeof figure, "chi-square (delta lobes only)");
    out[0] = {v.chi_square_passed(), figure};
    if (v.reciprocity_by_design())  // openpbr: albedo scaling's departure, by design
        std::snprintf(figure, sizeof figure, "reciprocity (worst %.2g: albedo scaling, by design)", v.reciprocity_error);
    else
        std::snprintf(figure, sizeof figure, "reciprocity (worst %.2g, limit %.0e)", v.reciprocity_error, v.reciprocity_tolerance);
    out[1] = {v.reciprocity_passed(), figure};
    std::snprintf(figure, sizeof figure, "energy (albedo %.4f at %.0f deg)", v.albedo.albedo, v.albedo.theta_deg);
    out[2] = {v.energy_passed(), figure};
}

}  // namespace

void ValidationBadges::set_material(const brdf::Preset& preset) {
    job_.submit([this, preset](const LatestJob::Cancelled& cancelled) {
        validation::ValidationOptions options = badge_options();
        options.cancelled = cancelled;
        auto v = std::make_shared<validation::MaterialValidation>(validation::validate_material(preset, options));
        std::lock_guard<std::mutex> lock(mutex_);
        if (v->cancelled) {
            ++cancelled_runs_;  // a newer edit is on its way; keep showing the last complete run
            return;
        }
        result_ = std::move(v);
    });
}

std::string ValidationBadges::summary() {
    std::shared_ptr<const validation::MaterialValidation> v;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        v = result_;
    }
    if (!v) return "running";
    Badge b[3];
    badges(*v, b);
    std::string out;
    for (const Badge& x : b) out += (out.empty() ? "" : ", ") + std::string(x.passed ? "PASS " : "FAIL ") + x.text;
    return out;
}

void ValidationBadges::draw() {
    std::shared_ptr<const validation::MaterialValidation> v;
    int cancelled = 0;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        v = result_;
        cancelled = cancelled_runs_;
    }
    ImGui::Text("%s   (%d stale runs cancelled)", job_.busy() ? "checking..." : "up to date", cancelled);
    if (!v) return;
    Badge b[3];
    badges(*v, b);
    for (const Badge& x : b) {
        ImGui::PushStyleColor(ImGuiCol_Button, x.passed ? ImVec4(0.1f, 0.5f, 0.2f, 1.0f) : ImVec4(0.7f, 0.15f, 0.15f, 1.0f));
        ImGui::SmallButton(x.passed ? "PASS" : "FAIL");
        ImGui::PopStyleColor();
        ImGui::SameLine();
        ImGui::TextUnformatted(x.text.c_str());
    }
    if (!v->chi_square_failure.empty()) ImGui::TextWrapped("%s", v->chi_square_failure.c_str());
}

}  // namespace lab::viewer
