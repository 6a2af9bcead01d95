#include "viewer/window_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "common/input_error.hpp"

namespace lab::viewer {

DisplaySizing parse_display_sizing(const std::string& text) {
    if (text == "render") return DisplaySizing::Render;
    if (text == "scale") return DisplaySizing::Scale;
    throw InputError("--display", "", "unknown value \"" + text + "\" (render, scale)");
}

bool overlap(const Rect& a, const Rect& b) {
    return a.x < b.right() && b.x < a.right() && a.y < b.bottom() && b.y < a.bottom();
}

namespace {

// A render smaller than this a side is not worth a restart: the display scales it instead.
constexpr int kMinRenderSide = 8;

}  // namespace

WindowLayout layout_window(const LayoutRequest& r) {
    WindowLayout l;
    l.columns = r.window_width >= 2 * kPanelColumnWidth + kMinRenderAreaWidth ? 2 : 1;
    const float panel_width = float(l.columns * kPanelColumnWidth);
    const float area_width = std::max(0.0f, float(r.window_width) - panel_width);
    l.render_area = Rect{0.0f, 0.0f, area_width, float(r.window_height)};
    l.panel = Rect{area_width, 0.0f, float(r.window_width) - area_width, float(r.window_height)};

    // The largest rectangle of the render's aspect in the area, in whole pixels.
    const double fit = std::min(double(area_width) / double(r.aspect_width), double(r.window_height) / double(r.aspect_height));
    const int fit_width = std::max(1, int(std::floor(fit * double(r.aspect_width))));
    const int fit_height = std::max(1, int(std::floor(fit * double(r.aspect_height))));
    l.image = Rect{std::floor(0.5f * (area_width - float(fit_width))), 0.0f, float(fit_width), float(fit_height)};

    if (r.sizing == DisplaySizing::Scale) {
        l.render_width = r.fixed_width;
        l.render_height = r.fixed_height;
        return l;
    }
    // One render pixel per screen pixel, within the budget; beyond it the same aspect, scaled down.
    double shrink = 1.0;
    if (double(fit_width) * double(fit_height) > double(r.max_render_pixels))
        shrink = std::sqrt(double(r.max_render_pixels) / (double(fit_width) * double(fit_height)));
    l.render_width = std::max(kMinRenderSide, int(std::floor(double(fit_width) * shrink)));
    l.render_height = std::max(kMinRenderSide, int(std::floor(double(fit_height) * shrink)));
    return l;
}

std::string describe_layout(const WindowLayout& l, int window_width, int window_height) {
    char line[320];
    std::snprintf(line, sizeof line, "layout: window %dx%d, render area %.0fx%.0f, image %.0f,%.0f %.0fx%.0f, render %dx%d, panel %.0f,%.0f %.0fx%.0f, columns %d",
                  window_width, window_height, l.render_area.w, l.render_area.h, l.image.x, l.image.y, l.image.w, l.image.h, l.render_width,
                  l.render_height, l.panel.x, l.panel.y, l.panel.w, l.panel.h, l.columns);
    return line;
}

std::vector<float> share_heights(const std::vector<float>& wanted, float available, float min_height) {
    std::vector<size_t> order(wanted.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return wanted[a] < wanted[b]; });
    std::vector<float> heights(wanted.size(), 0.0f);
    float remaining = available;
    size_t left = wanted.size();
    // The smallest first: one that wants less than an equal share of what is left keeps all of it.
    for (size_t i : order) {
        const float share = remaining / float(left);
        heights[i] = std::max(min_height, std::min(wanted[i], share));
        remaining -= heights[i];
        --left;
    }
    return heights;
}

}  // namespace lab::viewer
