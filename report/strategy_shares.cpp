#include "report/strategy_shares.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/luminance.hpp"

namespace lab::report {

StrategyGroup strategy_group(int s, int t) {
    if (s < 0 || t < 1 || s + t < 2) throw std::invalid_argument("strategy_group: no strategy (" + std::to_string(s) + ", " + std::to_string(t) + ")");
    if (t == 1) return StrategyGroup::light_tracer;
    return s <= 1 ? StrategyGroup::path_tracer : StrategyGroup::connection;
}

const char* strategy_group_name(StrategyGroup group) {
    switch (group) {
        case StrategyGroup::path_tracer: return "the path tracer's (s <= 1)";
        case StrategyGroup::connection: return "connections (s, t >= 2)";
        case StrategyGroup::light_tracer: return "light tracing's (t = 1)";
    }
    return "";
}

StrategyShares strategy_shares(const std::vector<WeightedStrategy>& strategies, double minor, double unlit) {
    if (strategies.empty()) throw std::invalid_argument("strategy_shares: no strategies");
    const int w = strategies[0].image.width, h = strategies[0].image.height;
    const size_t pixels = size_t(w) * size_t(h);
    StrategyShares out;
    out.image = film::ImageRgb(w, h);
    // per pixel, each group's luminance
    std::vector<std::array<double, kStrategyGroups>> group_light(pixels, std::array<double, kStrategyGroups>{});
    std::vector<double> strategy_total(strategies.size(), 0.0);
    for (size_t k = 0; k < strategies.size(); ++k) {
        const WeightedStrategy& one = strategies[k];
        if (one.image.width != w || one.image.height != h) throw std::invalid_argument("strategy_shares: images of different sizes");
        const int group = int(strategy_group(one.s, one.t));
        for (size_t i = 0; i < pixels; ++i) {
            const float* p = one.image.rgb.data() + 3 * i;
            for (int c = 0; c < 3; ++c)
                if (!(p[c] >= 0.0f) || !std::isfinite(p[c])) throw std::invalid_argument("strategy_shares: a negative or non-finite pixel");
            for (int c = 0; c < 3; ++c) out.image.rgb[3 * i + size_t(c)] += p[c];
            const double y = luminance(double(p[0]), double(p[1]), double(p[2]));
            group_light[i][size_t(group)] += y;
            strategy_total[k] += y;
        }
    }
    double total = 0.0;
    for (const auto& g : group_light) total += g[0] + g[1] + g[2];
    const double mean = total / double(pixels);
    out.groups = film::ImageRgb(w, h);
    size_t lit = 0;
    std::array<size_t, kStrategyGroups> minor_count{};
    for (size_t i = 0; i < pixels; ++i) {
        const double sum = group_light[i][0] + group_light[i][1] + group_light[i][2];
        if (!(sum > unlit * mean)) continue;
        ++lit;
        // red: light tracing's, green: connections', blue: the path tracer's
        out.groups.rgb[3 * i + 0] = float(group_light[i][size_t(StrategyGroup::light_tracer)] / sum);
        out.groups.rgb[3 * i + 1] = float(group_light[i][size_t(StrategyGroup::connection)] / sum);
        out.groups.rgb[3 * i + 2] = float(group_light[i][size_t(StrategyGroup::path_tracer)] / sum);
        for (int g = 0; g < kStrategyGroups; ++g)
            if (group_light[i][size_t(g)] < minor * sum) ++minor_count[size_t(g)];
    }
    out.lit_pixels = double(lit) / double(pixels);
    for (int g = 0; g < kStrategyGroups; ++g) {
        double group_total = 0.0;
        for (const auto& p : group_light) group_total += p[size_t(g)];
        out.light[size_t(g)] = total > 0.0 ? group_total / total : 0.0;
        out.minor_pixels[size_t(g)] = lit > 0 ? double(minor_count[size_t(g)]) / double(lit) : 0.0;
    }
    for (size_t k = 0; k < strategies.size(); ++k)
        out.strategies.push_back({strategies[k].s, strategies[k].t, total > 0.0 ? strategy_total[k] / total : 0.0});
    return out;
}

}  // namespace lab::report
