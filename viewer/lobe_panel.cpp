#include "viewer/lobe_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "analysis/luminance.hpp"
#include "common/angles.hpp"

namespace lab::viewer {

namespace {

const ImU32 kColour[2] = {IM_COL32(255, 170, 60, 255), IM_COL32(90, 200, 255, 255)};  // A orange, B blue

// Fewer points than the command's plots: the panel redraws while the user drags.
analysis::LobeResolution panel_resolution() {
    analysis::LobeResolution r;
    r.grid_theta_step_deg = 5.0f;
    r.plane_step_deg = 1.0f;
    return r;
}

analysis::AlbedoCurveOptions panel_albedo_options() {
    analysis::AlbedoCurveOptions o;
    o.angles = 19;
    o.strata = 24;
    return o;
}

ImVec2 canvas(float height, const char* id, bool* dragging, ImVec2* drag_delta, ImVec2* mouse) {
    ImVec2 origin = ImGui::GetCursorScreenPos();
    ImVec2 size(ImGui::GetContentRegionAvail().x, height);
    ImGui::InvisibleButton(id, size);
    *dragging = ImGui::IsItemActive() && ImGui::IsMouseDown(0);
    *drag_delta = ImGui::GetIO().MouseDelta;
    *mouse = ImGui::GetIO().MousePos;
    ImGui::GetWindowDrawList()->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(25, 25, 30, 255));
    return origin;
}

}  // namespace

void LobePanel::set_materials(const brdf::Preset& a, const brdf::Preset& b) {
    a_ = a;
    b_ = b;
    recompute();
}

void LobePanel::recompute() {
    brdf::Preset a = a_, b = b_;
    float theta = theta_in_, phi = phi_in_;
    job_.submit([this, a, b, theta, phi](const LatestJob::Cancelled& cancelled) {
        auto r = std::make_shared<Result>();
        const brdf::Preset* presets[2] = {&a, &b};
        for (int k = 0; k < 2; ++k) {
            if (cancelled()) return;
            r->lobe[k] = analysis::compute_lobe(*presets[k], theta, phi, panel_resolution());
            r->albedo[k] = analysis::albedo_curve(presets[k]->material, panel_albedo_options());
        }
        std::lock_guard<std::mutex> lock(mutex_);
        result_ = std::move(r);
    });
}

void LobePanel::draw() {
    std::shared_ptr<const Result> r;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        r = result_;
    }
    bool changed = ImGui::SliderFloat("theta in", &theta_in_, 0.0f, 89.0f, "%.1f deg");
    changed |= ImGui::SliderFloat("phi in", &phi_in_, 0.0f, 360.0f, "%.1f deg");
    ImGui::TextColored(ImColor(kColour[0]), "A: %s", a_.name.c_str());
    ImGui::SameLine();
    ImGui::TextColored(ImColor(kColour[1]), "  B: %s", b_.name.c_str());
    if (!r) {
        ImGui::TextUnformatted("computing...");
    } else {
        draw_polar(*r);
        draw_3d(*r);
        draw_albedo(*r);
    }
    if (changed) recompute();
}

// The plane of incidence: the normal up, the incident side left, f cos on a linear radius shared
// by A and B (one peak over both, so their sizes compare; the caption gives it). A delta lobe has no
// finite value: its direction is drawn at full length. Dragging sets theta in from the mouse's
// angle to the normal.
void LobePanel::draw_polar(const Result& r) {
    bool dragging;
    ImVec2 delta, mouse;
    const bool below = r.lobe[0].transmits || r.lobe[1].transmits;
    const float height = below ? 220.0f : 130.0f;
    ImVec2 o = canvas(height, "polar", &dragging, &delta, &mouse);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float width = ImGui::GetContentRegionAvail().x;
    const ImVec2 centre(o.x + width * 0.5f, o.y + (below ? height * 0.5f : height - 8.0f));
    const float radius = std::min(width * 0.5f, below ? height * 0.5f : height - 8.0f) - 6.0f;
    dl->AddLine(ImVec2(centre.x - radius, centre.y), ImVec2(centre.x + radius, centre.y), IM_COL32(120, 120, 120, 255));
    dl->AddLine(centre, ImVec2(centre.x, centre.y - radius), IM_COL32(70, 70, 70, 255));
    float peak = 0.0f;
    for (const analysis::LobeData& l : r.lobe)
        for (const analysis::PlaneSample& s : l.plane) peak = std::max(peak, std::isfinite(s.value) ? s.value : 0.0f);
    if (peak > 0.0f) {
        for (int k = 1; k >= 0; --k) {
            std::vector<ImVec2> points;
            for (const analysis::PlaneSample& s : r.lobe[k].plane) {
                float rr = std::isfinite(s.value) ? s.value / peak * radius : 0.0f;
                points.emplace_back(centre.x + std::sin(s.angle_deg * kRadiansPerDegree) * rr, centre.y - std::cos(s.angle_deg * kRadiansPerDegree) * rr);
            }
            dl->AddPolyline(points.data(), int(points.size()), kColour[k], 0, 1.5f);
            for (const analysis::DeltaLobe& d : r.lobe[k].deltas)
                if (d.in_plane)
                    dl->AddLine(centre, ImVec2(centre.x + std::sin(d.plane_angle_deg * kRadiansPerDegree) * radius,
                                               centre.y - std::cos(d.plane_angle_deg * kRadiansPerDegree) * radius), kColour[k], 2.5f);
        }
    }
    const float t = theta_in_ * kRadiansPerDegree;
    dl->AddLine(centre, ImVec2(centre.x - std::sin(t) * radius, centre.y - std::cos(t) * radius), IM_COL32(255, 255, 255, 255), 2.0f);
    char caption[160];
    std::snprintf(caption, sizeof caption, "plane of incidence (drag: theta in)\nf cos, one scale for A and B: rim %.3g /sr%s", peak,
                  r.lobe[0].deltas.empty() && r.lobe[1].deltas.empty() ? "" : "\ndelta lobes: full length, not to scale");
    dl->AddText(ImVec2(o.x + 4, o.y + 2), IM_COL32(200, 200, 200, 255), caption);
    if (dragging) {
        float dx = mouse.x - centre.x, dy = centre.y - mouse.y;
        float theta = std::atan2(std::fabs(dx), std::max(dy, 0.0f)) / kRadiansPerDegree;
        theta_in_ = std::min(std::max(theta, 0.0f), 89.0f);
        recompute();
    }
}

// The lobe as a surface over the outgoing hemisphere(s): radius f cos along each direction, drawn as
// its theta rings and phi meridians, turned by dragging; one scale for A and B, as the polar plot.
void LobePanel::draw_3d(const Result& r) {
    bool dragging;
    ImVec2 delta, mouse;
    ImVec2 o = canvas(200.0f, "lobe3d", &dragging, &delta, &mouse);
    if (dragging) {
        yaw_ += delta.x * 0.5f;
        pitch_ = std::min(std::max(pitch_ + delta.y * 0.5f, -89.0f), 89.0f);
    }
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float width = ImGui::GetContentRegionAvail().x;
    const ImVec2 centre(o.x + width * 0.5f, o.y + 130.0f);
    const float scale = 100.0f;
    float peak = 0.0f;
    for (const analysis::LobeData& l : r.lobe)
        for (const analysis::LobeSample& s : l.grid) {
            float v = analysis::luminance(s.f) * std::fabs(std::cos(s.theta_deg * kRadiansPerDegree));
            if (std::isfinite(v)) peak = std::max(peak, v);
        }
    const float cy = std::cos(yaw_ * kRadiansPerDegree), sy = std::sin(yaw_ * kRadiansPerDegree);
    const float cp = std::cos(pitch_ * kRadiansPerDegree), sp = std::sin(pitch_ * kRadiansPerDegree);
    auto project = [&](const analysis::LobeSample& s) {
        float v = analysis::luminance(s.f) * std::fabs(std::cos(s.theta_deg * kRadiansPerDegree));
        float rr = (peak > 0.0f && std::isfinite(v)) ? v / peak : 0.0f;
        float st = std::sin(s.theta_deg * kRadiansPerDegree), ct = std::cos(s.theta_deg * kRadiansPerDegree);
        float x = rr * st * std::cos(s.phi_deg * kRadiansPerDegree), y = rr * st * std::sin(s.phi_deg * kRadiansPerDegree), z = rr * ct;
        float x1 = cy * x - sy * y, y1 = sy * x + cy * y;  // yaw about the normal
        float up = cp * z - sp * y1;                         // pitch towards the viewer
        return ImVec2(centre.x + x1 * scale, centre.y - up * scale);
    };
    for (int k = 1; k >= 0; --k) {
        const analysis::LobeData& l = r.lobe[k];
        if (l.theta_count == 0 || l.phi_count == 0) continue;
        const ImU32 colour = (kColour[k] & 0x00FFFFFF) | 0xA0000000;
        std::vector<ImVec2> line;
        for (int i = 0; i < l.theta_count; i += 2) {
            line.clear();
            for (int j = 0; j < l.phi_count; ++j) line.push_back(project(l.grid[size_t(i * l.phi_count + j)]));
            dl->AddPolyline(line.data(), int(line.size()), colour, ImDrawFlags_Closed, 1.0f);
        }
        for (int j = 0; j < l.phi_count; j += 3) {
            line.clear();
            for (int i = 0; i < l.theta_count; ++i) line.push_back(project(l.grid[size_t(i * l.phi_count + j)]));
            dl->AddPolyline(line.data(), int(line.size()), colour, 0, 1.0f);
        }
    }
    char caption[96];
    std::snprintf(caption, sizeof caption, "3D lobe (drag: turn), one scale for A and B: peak %.3g /sr", peak);
    dl->AddText(ImVec2(o.x + 4, o.y + 2), IM_COL32(200, 200, 200, 255), caption);
}

// Directional albedo against theta in: A per channel, B's luminance, 0..1 (1 dotted).
void LobePanel::draw_albedo(const Result& r) {
    bool dragging;
    ImVec2 delta, mouse;
    const float height = 110.0f;
    ImVec2 o = canvas(height, "albedo", &dragging, &delta, &mouse);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const float width = ImGui::GetContentRegionAvail().x - 8.0f;
    auto at = [&](float theta, float albedo) {
        return ImVec2(o.x + 4.0f + theta / 90.0f * width, o.y + height - 6.0f - std::min(albedo, 1.15f) / 1.15f * (height - 20.0f));
    };
    dl->AddLine(at(0, 1), at(90, 1), IM_COL32(90, 90, 90, 255));
    const ImU32 channel[3] = {IM_COL32(255, 80, 80, 255), IM_COL32(80, 220, 80, 255), IM_COL32(100, 140, 255, 255)};
    std::vector<ImVec2> line;
    for (int c = 0; c < 3; ++c) {
        line.clear();
        for (const analysis::AlbedoPoint& p : r.albedo[0]) line.push_back(at(p.theta_deg, p.estimate.value[c]));
        dl->AddPolyline(line.data(), int(line.size()), channel[c], 0, 1.5f);
    }
    line.clear();
    for (const analysis::AlbedoPoint& p : r.albedo[1]) line.push_back(at(p.theta_deg, analysis::luminance(p.estimate.value)));
    dl->AddPolyline(line.data(), int(line.size()), kColour[1], 0, 1.5f);
    dl->AddText(ImVec2(o.x + 4, o.y + 2), IM_COL32(200, 200, 200, 255), "directional albedo vs theta in (A: r g b, B: luminance)");
}

}  // namespace lab::viewer
