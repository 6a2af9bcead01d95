#include "fit/fit_metric.hpp"

#include <cmath>
#include <limits>

namespace lab::fit {

brdf::float3 log_residual(brdf::float3 model, brdf::float3 measured, float cos_i) {
    brdf::float3 r;
    for (int c = 0; c < 3; ++c) r[c] = std::log1p(cos_i * model[c]) - std::log1p(cos_i * measured[c]);
    return r;
}

brdf::float3 model_value(const brdf::Material& m, const FitPair& pair) { return brdf::bsdf_eval(&m, pair.wo, pair.wi); }

double fit_error(const brdf::Material& m, const std::vector<FitPair>& pairs) {
    if (pairs.empty()) return 0.0;
    double sum = 0.0;
    for (const FitPair& p : pairs) {
        const brdf::float3 r = log_residual(model_value(m, p), p.measured, p.wi.z);
        sum += double(r.x) * r.x + double(r.y) * r.y + double(r.z) * r.z;
    }
    return std::sqrt(sum / (3.0 * double(pairs.size())));
}

ErrorBreakdown error_breakdown(const brdf::Material& m, const std::vector<FitPair>& pairs) {
    constexpr int kBands = 9;
    double channel_sum[3] = {0.0, 0.0, 0.0};
    double band_sum[kBands] = {};
    int band_count[kBands] = {};
    for (const FitPair& p : pairs) {
        const brdf::float3 r = log_residual(model_value(m, p), p.measured, p.wi.z);
        double squares = 0.0;
        for (int c = 0; c < 3; ++c) {
            channel_sum[c] += double(r[c]) * r[c];
            squares += double(r[c]) * r[c];
        }
        const double theta = std::acos(std::fmin(1.0, double(p.wi.z))) * 180.0 / M_PI;
        const int band = std::min(kBands - 1, int(theta / 10.0));
        band_sum[band] += squares;
        band_count[band] += 1;
    }
    ErrorBreakdown b;
    const double n = double(pairs.size());
    b.total = n > 0 ? std::sqrt((channel_sum[0] + channel_sum[1] + channel_sum[2]) / (3.0 * n)) : 0.0;
    for (int c = 0; c < 3; ++c) b.channel[c] = n > 0 ? std::sqrt(channel_sum[c] / n) : 0.0;
    for (int k = 0; k < kBands; ++k)
        b.incidence.push_back({10.0 * k, 10.0 * (k + 1), band_count[k],
                               band_count[k] > 0 ? std::sqrt(band_sum[k] / (3.0 * band_count[k])) : std::numeric_limits<double>::quiet_NaN()});
    return b;
}

ErrorMap error_map(const brdf::MeasuredTable& table, const brdf::Material& m, int phi_d_stride) {
    const std::vector<FitPair> pairs = fit_pairs(table, PairGrid{1, 1, phi_d_stride, 1});
    std::vector<double> sum(MERL_THETA_H_BINS * MERL_THETA_D_BINS, 0.0);
    std::vector<int> count(sum.size(), 0);
    for (const FitPair& p : pairs) {
        const brdf::float3 r = log_residual(model_value(m, p), p.measured, p.wi.z);
        const int cell = p.ih * MERL_THETA_D_BINS + p.id;
        sum[cell] += double(r.x) * r.x + double(r.y) * r.y + double(r.z) * r.z;
        count[cell] += 3;
    }
    ErrorMap map;
    map.error.resize(sum.size());
    for (size_t i = 0; i < sum.size(); ++i)
        map.error[i] = count[i] > 0 ? std::sqrt(sum[i] / count[i]) : std::numeric_limits<double>::quiet_NaN();
    return map;
}

}  // namespace lab::fit
