// Where the viewer's window puts things, as a pure function of its size, so that it can be tested
// without a display: the render area left of the panel, the render drawn in it at the render's
// aspect, the panel in one or two columns, and the size the render should have. Also how a panel
// column shares its height among the sections open in it.
#pragma once

#include <string>
#include <vector>

namespace lab::viewer {

// What a window size changes: the render's size ("render": the render follows the area, up to a
// pixel budget beyond which the display scales it up) or only the display ("scale": the render
// keeps its size and is drawn scaled to fit).
enum class DisplaySizing { Render, Scale };
// "render" or "scale"; throws lab::InputError("--display", ...) otherwise.
DisplaySizing parse_display_sizing(const std::string& text);

struct Rect {
    float x = 0.0f, y = 0.0f, w = 0.0f, h = 0.0f;
    float right() const { return x + w; }
    float bottom() const { return y + h; }
    bool contains(float px, float py) const { return px >= x && px < right() && py >= y && py < bottom(); }
};
// Whether two rectangles share any area (touching edges do not).
bool overlap(const Rect& a, const Rect& b);

struct LayoutRequest {
    int window_width = 0, window_height = 0;  // in the window's own coordinates (ImGui's display size)
    int aspect_width = 1, aspect_height = 1;  // the render's aspect: the --size the viewer opened with
    DisplaySizing sizing = DisplaySizing::Render;
    int fixed_width = 1, fixed_height = 1;    // the render's size under "scale"
    long max_render_pixels = 512 * 512;         // the budget under "render"
};

struct WindowLayout {
    Rect render_area;  // left of the panel, the whole height
    Rect image;        // the render in it: its aspect, as large as fits, at the top, centred across
    Rect panel;        // right, the whole height
    int columns = 1;   // of the panel: two where the window is wide enough for the render to keep kMinRenderArea
    int render_width = 1, render_height = 1;  // the size the render should have
};

constexpr int kPanelColumnWidth = 440;
// The render area is never narrower than this: a second panel column opens only where it stays.
constexpr int kMinRenderAreaWidth = 640;
// The smallest window: one panel column and a sliver of render beside it.
constexpr int kSmallestWindowWidth = kPanelColumnWidth + 64, kSmallestWindowHeight = 240;

WindowLayout layout_window(const LayoutRequest& request);
// One line for the terminal (`view --stats`): "layout: window WxH, render area ..., image X,Y WxH,
// render WxH, panel X,Y WxH, columns N".
std::string describe_layout(const WindowLayout& layout, int window_width, int window_height);

// The heights of a column's open sections: each gets what its content wants when all fit in
// `available`; otherwise the space is shared so that a section wanting less than an equal share
// keeps its whole content and the others split the rest equally (each scrolls inside its share),
// and no section is given less than `min_height` (the column then scrolls as a whole).
std::vector<float> share_heights(const std::vector<float>& wanted, float available, float min_height);

}  // namespace lab::viewer
