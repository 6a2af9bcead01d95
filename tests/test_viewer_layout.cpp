// The viewer's window layout (viewer/window_layout): where the render and the panel go for a window
// size, the size the render takes, and how a panel column shares its height among open sections.
#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>

#include "viewer/window_layout.hpp"

// A named namespace keeps the using-directive to this file in its unity group (tests/CMakeLists.txt).
namespace viewer_layout_test {
using namespace lab::viewer;

namespace {

LayoutRequest request(int window_width, int window_height, int aspect_width = 384, int aspect_height = 384) {
    LayoutRequest r;
    r.window_width = window_width;
    r.window_height = window_height;
    r.aspect_width = r.fixed_width = aspect_width;
    r.aspect_height = r.fixed_height = aspect_height;
    return r;
}

// What every layout keeps: the area left of the panel, the panel right, both the whole height, the
// image inside the area at the render's aspect (to a pixel) and touching two of its sides.
void check_invariants(const LayoutRequest& r, const WindowLayout& l) {
    INFO(describe_layout(l, r.window_width, r.window_height));
    CHECK(l.render_area.x == 0.0f);
    CHECK(l.render_area.w + l.panel.w == float(r.window_width));
    CHECK(l.panel.x == l.render_area.right());
    CHECK(l.render_area.h == float(r.window_height));
    CHECK(l.panel.h == float(r.window_height));
    CHECK_FALSE(overlap(l.render_area, l.panel));
    CHECK(l.image.x >= l.render_area.x);
    CHECK(l.image.right() <= l.render_area.right());
    CHECK(l.image.y == 0.0f);
    CHECK(l.image.bottom() <= l.render_area.bottom());
    // as large as fits: it fills the area's width or its height, to the pixel rounding
    CHECK(std::max(l.render_area.w - l.image.w, l.render_area.h - l.image.h) >= 0.0f);
    CHECK(std::min(l.render_area.w - l.image.w, l.render_area.h - l.image.h) < 1.0f);
    CHECK(std::fabs(l.image.w * float(r.aspect_height) - l.image.h * float(r.aspect_width)) <= float(std::max(r.aspect_width, r.aspect_height)));
}

}  // namespace

TEST_CASE("Viewer layout: the default window shows the render at one pixel per screen pixel, top left", "[viewer][layout]") {
    // The window the viewer opens by default: the render's size and one panel column, at least 560 high.
    LayoutRequest r = request(384 + kPanelColumnWidth, 560);
    WindowLayout l = layout_window(r);
    check_invariants(r, l);
    CHECK(l.columns == 1);
    CHECK(l.image.x == 0.0f);
    CHECK(l.image.w == 384.0f);
    CHECK(l.image.h == 384.0f);
    CHECK(l.render_width == 384);
    CHECK(l.render_height == 384);
}

TEST_CASE("Viewer layout: the render area fills what the panel leaves, and the render follows it", "[viewer][layout]") {
    for (int width : {600, 900, 1280, 1519, 1520, 1920, 2560}) {
        for (int height : {240, 480, 800, 1080, 1440}) {
            for (auto aspect : {std::pair<int, int>{384, 384}, {640, 360}, {300, 500}}) {
                LayoutRequest r = request(width, height, aspect.first, aspect.second);
                r.max_render_pixels = 1L << 30;  // no budget: one render pixel per screen pixel
                WindowLayout l = layout_window(r);
                check_invariants(r, l);
                CHECK(l.columns == (width >= 2 * kPanelColumnWidth + kMinRenderAreaWidth ? 2 : 1));
                CHECK(l.render_width == std::max(8, int(l.image.w)));
                CHECK(l.render_height == std::max(8, int(l.image.h)));
            }
        }
    }
    // A larger window, a larger render area and render (both within the default budget).
    WindowLayout small = layout_window(request(800, 400)), large = layout_window(request(1000, 600));
    CHECK(large.render_area.w > small.render_area.w);
    CHECK(large.render_width > small.render_width);
}

TEST_CASE("Viewer layout: past the pixel budget the render keeps its aspect and the display scales it", "[viewer][layout]") {
    LayoutRequest r = request(1920, 1080, 640, 360);
    r.max_render_pixels = 512 * 512;
    WindowLayout l = layout_window(r);
    check_invariants(r, l);
    CHECK(long(l.render_width) * long(l.render_height) <= r.max_render_pixels);
    CHECK(long(l.render_width + 2) * long(l.render_height + 2) > r.max_render_pixels);  // the budget is used
    CHECK(std::fabs(double(l.render_width) / double(l.render_height) - 640.0 / 360.0) < 0.01);
    CHECK(l.image.w > float(l.render_width));
}

TEST_CASE("Viewer layout: under \"scale\" the render keeps its size whatever the window", "[viewer][layout]") {
    for (int width : {700, 1280, 1920}) {
        LayoutRequest r = request(width, 900, 256, 192);
        r.sizing = parse_display_sizing("scale");
        WindowLayout l = layout_window(r);
        check_invariants(r, l);
        CHECK(l.render_width == 256);
        CHECK(l.render_height == 192);
    }
    CHECK_THROWS_WITH(parse_display_sizing("stretch"), Catch::Contains("--display") && Catch::Contains("unknown value \"stretch\""));
}

TEST_CASE("Viewer layout: open sections share a column's height", "[viewer][layout]") {
    auto total = [](const std::vector<float>& h) { return std::accumulate(h.begin(), h.end(), 0.0f); };
    // All fit: each its whole content.
    CHECK(share_heights({100, 200, 50}, 500, 90) == std::vector<float>{100, 200, 90});
    // Too little room: a section wanting less than an equal share keeps its content, the others
    // split the rest equally, and together they fill the column exactly.
    std::vector<float> h = share_heights({600, 120, 900}, 900, 90);
    CHECK(h[1] == 120.0f);
    CHECK(h[0] == Approx(390.0f));
    CHECK(h[2] == Approx(390.0f));
    CHECK(total(h) == Approx(900.0f));
    // No room at all: each keeps the least, and the column scrolls.
    CHECK(share_heights({300, 300}, 100, 90) == std::vector<float>{90, 90});
    CHECK(share_heights({}, 100, 90).empty());
}

}  // namespace viewer_layout_test
