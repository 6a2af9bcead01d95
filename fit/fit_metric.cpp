#include "fit/fit_metric.hpp"

#include <cmath>
#include <algorithm>
#include <limits>
#include <thread>

#include "common/parallel_for.hpp"

namespace lab::fit {

brdf::float3 log_residual(brdf::float3 model, brdf::float3 measured, float cos_i) {
    brdf::float3 r;
    for (int c = 0; c < 3; ++c) r[c] = std::log1p(cos_i * model[c]) - std::log1p(cos_i * measured[c]);
    return r;
}

brdf::float3 model_value(const brdf::Material& m, const FitPair& pair) { return brdf::bsdf_eval(&m, pair.wo, pair.wi); }

namespace {

double squared_residuals(const brdf::Material& m, const FitPair* begin, const FitPair* end) {
    double sum = 0.0;
    for (const FitPair* p = begin; p != end; ++p) {
        const brdf::float3 r = log_residual(model_value(m, *p), p->measured, p->wi.z);
        sum += double(r.x) * r.x + double(r.y) * r.y + double(r.z) * r.z;
    }
    return sum;
}

}  // namespace

double fit_error(const brdf::Material& m, const std::vector<FitPair>& pairs) {
    if (pairs.empty()) return 0.0;
    // Fixed chunks summed in order, whatever the thread count: the same error, bit for bit, on any
    // machine, so a fit is repeatable. The threads share the chunks round-robin.
    constexpr size_t kChunk = 2048;
    const size_t chunks = (pairs.size() + kChunk - 1) / kChunk;
    std::vector<double> partial(chunks, 0.0);
    auto run = [&](size_t first, size_t step) {
        for (size_t c = first; c < chunks; c += step)
            partial[c] = squared_residuals(m, pairs.data() + c * kChunk, pairs.data() + std::min(pairs.size(), (c + 1) * kChunk));
    };
    const size_t threads = std::min<size_t>(chunks, size_t(hardware_threads()));
    std::vector<std::thread> workers;
    for (size_t t = 1; t < threads; ++t) workers.emplace_back(run, t, threads);
    run(0, threads);
    for (std::thread& w : workers) w.join();
    double sum = 0.0;
    for (double p : partial) sum += p;
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
