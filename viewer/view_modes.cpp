#include "viewer/view_modes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/input_error.hpp"

namespace lab::viewer {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

bool finite3(const float* c) { return std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]); }

void put(std::vector<uint8_t>* out, size_t p, std::array<uint8_t, 3> rgb) {
    for (size_t c = 0; c < 3; ++c) (*out)[3 * p + c] = rgb[c];
}

// A display value in [0, 1] (clamped) as a grey code, not sRGB encoded: the AOVs' scales are
// linear in what they show (a normal's component, a fraction of the depth range).
uint8_t code(float display) { return film::quantize8(display); }

// The image tone-mapped, as a grey of half its luminance: what the flagging views paint over.
std::vector<uint8_t> dimmed_grey(const film::ImageRgb& image, film::ToneMap tone_map, float exposure) {
    std::vector<uint8_t> out(3 * image.pixel_count());
    for (size_t p = 0; p < image.pixel_count(); ++p) {
        const float* c = image.rgb.data() + 3 * p;
        float display[3] = {0.0f, 0.0f, 0.0f};
        if (finite3(c)) film::tone_map_pixel(c, tone_map, exposure, display);
        const uint8_t grey = film::srgb8_code(0.5f * film::luminance(display[0], display[1], display[2]));
        put(&out, p, {grey, grey, grey});
    }
    return out;
}

// A slot's colour: eight distinct hues, then again; no surface black.
std::array<uint8_t, 3> slot_colour(int slot) {
    static const std::array<std::array<uint8_t, 3>, 8> palette = {{{230, 159, 0},
                                                                   {86, 180, 233},
                                                                   {0, 158, 115},
                                                                   {240, 228, 66},
                                                                   {0, 114, 178},
                                                                   {213, 94, 0},
                                                                   {204, 121, 167},
                                                                   {255, 255, 255}}};  // Okabe-Ito's colour-blind-safe set
    return slot < 0 ? std::array<uint8_t, 3>{0, 0, 0} : palette[size_t(slot) % palette.size()];
}

bool same_size(const film::ImageRgb* a, const film::ImageRgb& b) { return a && a->valid() && a->width == b.width && a->height == b.height; }

}  // namespace

const std::vector<std::pair<ViewMode, std::string>>& view_modes() {
    static const std::vector<std::pair<ViewMode, std::string>> modes = {
        {ViewMode::image, "image"},       {ViewMode::albedo, "albedo"},     {ViewMode::normal, "normal"},
        {ViewMode::depth, "depth"},       {ViewMode::slot, "slot"},         {ViewMode::samples, "samples"},
        {ViewMode::variance, "variance"}, {ViewMode::false_colour, "false-colour"}, {ViewMode::relative_error, "relative-error"},
        {ViewMode::gamut, "gamut"}};
    return modes;
}

const std::string& view_mode_name(ViewMode mode) {
    for (const auto& [m, name] : view_modes())
        if (m == mode) return name;
    return view_modes().front().second;
}

ViewMode parse_view_mode(const std::string& text, const std::string& option) {
    std::string names;
    for (const auto& [mode, name] : view_modes()) {
        if (name == text) return mode;
        names += (names.empty() ? "" : ", ") + name;
    }
    throw InputError(option, "", "unknown view \"" + text + "\" (expected one of " + names + ")");
}

bool needs_first_hits(ViewMode mode) {
    return mode == ViewMode::albedo || mode == ViewMode::normal || mode == ViewMode::depth || mode == ViewMode::slot;
}

bool needs_film_statistics(ViewMode mode) {
    return mode == ViewMode::samples || mode == ViewMode::variance || mode == ViewMode::relative_error;
}

float luminance_standard_error(const float variance[3]) {
    return film::luminance(std::sqrt(std::max(variance[0], 0.0f)), std::sqrt(std::max(variance[1], 0.0f)),
                           std::sqrt(std::max(variance[2], 0.0f)));
}

const std::vector<LegendBand>& false_colour_legend() {
    // One band a stop from -5 to +5 around middle grey, open-ended below and above, coloured along
    // a blue-to-red ramp with middle grey itself grey, as a camera's false-colour exposure aid.
    static const std::vector<LegendBand> bands = {{-kInf, -5.0f, {20, 0, 60}},  {-5.0f, -4.0f, {60, 0, 140}},  {-4.0f, -3.0f, {20, 40, 220}},
                                                  {-3.0f, -2.0f, {0, 130, 240}}, {-2.0f, -1.0f, {0, 190, 190}}, {-1.0f, 0.0f, {70, 200, 70}},
                                                  {0.0f, 1.0f, {128, 128, 128}}, {1.0f, 2.0f, {230, 220, 60}},  {2.0f, 3.0f, {250, 160, 30}},
                                                  {3.0f, 4.0f, {240, 90, 20}},   {4.0f, 5.0f, {210, 20, 20}},   {5.0f, kInf, {255, 255, 255}}};
    return bands;
}

std::vector<uint8_t> view_pixels(ViewMode mode, const ViewInputs& in) {
    if (!in.image || !in.image->valid()) return {};
    const film::ImageRgb& image = *in.image;
    const size_t pixels = image.pixel_count();
    const render::FirstHitAovs* hits = in.first_hits;
    if (needs_first_hits(mode) && !(hits && same_size(&hits->albedo, image) && same_size(&hits->normal, image) && hits->depth.size() == pixels &&
                                    hits->slot.size() == pixels))
        return {};
    if (needs_film_statistics(mode) && !(same_size(in.variance, image) && in.samples && in.samples->size() == pixels)) return {};
    const float scale = std::exp2(in.exposure_stops);
    std::vector<uint8_t> out(3 * pixels, 0);
    switch (mode) {
    case ViewMode::image: return film::to_srgb8(image, in.tone_map, in.exposure_stops);
    case ViewMode::albedo: return film::to_srgb8(hits->albedo, film::ToneMap::Clamp, 0.0f);
    case ViewMode::normal:
        for (size_t p = 0; p < pixels; ++p) {
            const float* n = hits->normal.rgb.data() + 3 * p;
            if (n[0] == 0.0f && n[1] == 0.0f && n[2] == 0.0f) continue;  // no surface: black
            put(&out, p, {code(0.5f * n[0] + 0.5f), code(0.5f * n[1] + 0.5f), code(0.5f * n[2] + 0.5f)});
        }
        return out;
    case ViewMode::depth: {
        // Inverse depth over the nearest's: the nearest white, twice as far half as bright, so a
        // ground running to the horizon leaves the depth range of a model near the camera visible
        // (a linear ramp over the whole range would whiten it); no surface black.
        float lo = kInf;
        for (float d : hits->depth)
            if (d > 0.0f) lo = std::min(lo, d);
        for (size_t p = 0; p < pixels; ++p) {
            const float d = hits->depth[p];
            if (!(d > 0.0f)) continue;
            const uint8_t g = code(lo / d);
            put(&out, p, {g, g, g});
        }
        return out;
    }
    case ViewMode::slot:
        for (size_t p = 0; p < pixels; ++p) put(&out, p, slot_colour(hits->slot[p]));
        return out;
    case ViewMode::samples: {
        // The count over the image's largest: a uniform render is white all over.
        float most = 0.0f;
        for (float n : *in.samples) most = std::max(most, n);
        for (size_t p = 0; p < pixels; ++p) {
            const uint8_t g = code(most > 0.0f ? (*in.samples)[p] / most : 0.0f);
            put(&out, p, {g, g, g});
        }
        return out;
    }
    case ViewMode::variance: {
        // The mean luminance's standard error over the image's 99th percentile (a few fireflies would
        // leave the rest black under the largest), its square root for contrast; a pixel with fewer
        // than two samples (no estimate) magenta.
        std::vector<float> error(pixels), finite;
        for (size_t p = 0; p < pixels; ++p) {
            const float* v = in.variance->rgb.data() + 3 * p;
            error[p] = finite3(v) ? luminance_standard_error(v) : -1.0f;
            if (error[p] >= 0.0f) finite.push_back(error[p]);
        }
        float most = 0.0f;
        if (!finite.empty()) {
            const auto at = finite.begin() + std::ptrdiff_t((finite.size() - 1) * 99 / 100);
            std::nth_element(finite.begin(), at, finite.end());
            most = *at;
        }
        for (size_t p = 0; p < pixels; ++p) {
            if (error[p] < 0.0f) {
                put(&out, p, kNonFiniteMagenta);
                continue;
            }
            const uint8_t g = code(most > 0.0f ? std::sqrt(std::min(error[p] / most, 1.0f)) : 0.0f);
            put(&out, p, {g, g, g});
        }
        return out;
    }
    case ViewMode::false_colour:
        for (size_t p = 0; p < pixels; ++p) {
            const float* c = image.rgb.data() + 3 * p;
            if (!finite3(c)) {
                put(&out, p, kNonFiniteMagenta);
                continue;
            }
            const float y = scale * film::luminance(c[0], c[1], c[2]);
            const float stops = y > 0.0f ? std::log2(y / kMiddleGrey) : -kInf;
            for (const LegendBand& band : false_colour_legend())
                if (stops >= band.lo_stops && stops < band.hi_stops) put(&out, p, band.rgb);
        }
        return out;
    case ViewMode::relative_error: {
        out = dimmed_grey(image, in.tone_map, in.exposure_stops);
        for (size_t p = 0; p < pixels; ++p) {
            const float* c = image.rgb.data() + 3 * p;
            const float* v = in.variance->rgb.data() + 3 * p;
            const float y = film::luminance(c[0], c[1], c[2]);
            // No estimate yet (fewer than two samples) counts as uncertain; a black pixel without
            // spread (a black background) as certain.
            const float error = finite3(v) ? luminance_standard_error(v) : kInf;
            const bool uncertain = !finite3(c) || (error > 0.0f && !(error <= in.relative_error_threshold * std::abs(y)));
            if (uncertain) put(&out, p, kFlagRed);
        }
        return out;
    }
    case ViewMode::gamut:
        out = dimmed_grey(image, in.tone_map, in.exposure_stops);
        for (size_t p = 0; p < pixels; ++p) {
            const float* c = image.rgb.data() + 3 * p;
            if (!finite3(c)) put(&out, p, kNonFiniteMagenta);
            else if (std::min({c[0], c[1], c[2]}) < 0.0f) put(&out, p, kNegativeCyan);
            else if (scale * std::max({c[0], c[1], c[2]}) > 1.0f) put(&out, p, kFlagRed);
        }
        return out;
    }
    return out;
}

}  // namespace lab::viewer
