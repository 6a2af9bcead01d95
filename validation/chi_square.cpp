#include "validation/chi_square.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "validation/chi_square_distribution.hpp"
#include "common/parallel_for.hpp"
#include "validation/sphere_quadrature.hpp"
#include "validation/uniform_random.hpp"

namespace lab::validation {

namespace {

constexpr double kTwoPi = 6.283185307179586476925;
constexpr double kMinExpected = 5.0;     // cells expected to hold fewer samples are pooled
constexpr double kUnitTolerance = 1e-3;  // |length(wi) - 1| allowed for a sample
constexpr float kConsistency = 1e-4f;    // relative agreement of a sample's pdf and f with pdf() and eval()

std::string format(const char* fmt, double a = 0, double b = 0, double c = 0, double d = 0, double e = 0, double f = 0) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, fmt, a, b, c, d, e, f);
    return buffer;
}

bool in_domain(brdf::float3 w) {
    if (!std::isfinite(w.x) || !std::isfinite(w.y) || !std::isfinite(w.z)) return false;
    double len = std::sqrt(double(w.x) * w.x + double(w.y) * w.y + double(w.z) * w.z);
    return std::fabs(len - 1.0) <= kUnitTolerance;
}

// The samples whose pdf and f are checked against bsdf_pdf and bsdf_eval: one in kPromiseCheckEvery,
// those whose u.x falls in every kPromiseCheckEvery-th of 4096 equal strata. The two calls cost more
// than the sample itself (for a layered material each sets the layers up again), and a value that
// departs systematically shows on any share of the samples: u.x, which picks the lobe and then
// drives it, is met at every scale above 1/4096 of its range.
constexpr int kPromiseCheckEvery = 8;

bool promise_checked(brdf::float3 u) { return int(u.x * 4096.0f) % kPromiseCheckEvery == 0; }

std::string describe_cell(int cell, const SphereGrid& grid) {
    double z0, z1, p0, p1;
    grid.bounds(cell, &z0, &z1, &p0, &p1);
    const double to_degrees = 360.0 / kTwoPi;
    return format("cos theta [%.3f, %.3f] phi [%.1f, %.1f] deg", z0, z1, p0 * to_degrees, p1 * to_degrees);
}

struct Tally {
    std::vector<long> counts;  // per cell, continuous samples only
    long delta = 0, failed = 0;
};

struct Histogram {
    std::vector<long> observed;  // per cell, continuous samples only
    long delta = 0, failed = 0;
    std::string defect;          // the first broken promise in chunk order; empty when none
};

struct Bin {
    double expected;
    long observed;
    int cell;  // -1: the samples that were not continuous (deltas and failures); -2: a pool
};

// 1. Histogram of the samples, in fixed chunks with their own seeds.
Histogram sample_histogram(const DirectionSampler& sampler, const SphereGrid& grid, const ChiSquareOptions& options) {
    const int cells = grid.cells();
    const long n = options.samples;
    const int chunks = int(std::clamp(n / 8192, 1L, 256L));
    std::vector<Tally> tallies(chunks);
    std::vector<std::string> chunk_defects(chunks);
    parallel_for(chunks, options.threads, [&](int c) {
        Tally& t = tallies[c];
        t.counts.assign(cells, 0);
        UniformRandom rng(options.seed * 1000003ull + uint64_t(c));
        long begin = n * c / chunks, end = n * (c + 1) / chunks;
        for (long i = begin; i < end; ++i) {
            DirectionSample s = sampler(rng.next_float3());
            if (!s.defect.empty()) {
                if (chunk_defects[c].empty()) chunk_defects[c] = s.defect;
                continue;
            }
            if (s.kind == SampleKind::Failed) {
                ++t.failed;
            } else if (!in_domain(s.wi)) {
                if (chunk_defects[c].empty())
                    chunk_defects[c] = format("sample outside the domain: wi = (%g, %g, %g)", s.wi.x, s.wi.y, s.wi.z);
            } else if (s.kind == SampleKind::Delta) {
                ++t.delta;
            } else {
                ++t.counts[grid.cell_of(s.wi)];
            }
        }
    });
    Histogram h;
    h.observed.assign(cells, 0);
    for (const Tally& t : tallies) {
        for (int i = 0; i < cells; ++i) h.observed[i] += t.counts[i];
        h.delta += t.delta;
        h.failed += t.failed;
    }
    for (const std::string& d : chunk_defects) {
        if (!d.empty()) {
            h.defect = d;
            break;
        }
    }
    return h;
}

// 2. The density integrated over each cell; the tolerance keeps the error of the expected count
// far below its Poisson noise (estimated from the observed count). Sets result->pdf_integral, or
// result->failure where the density is negative or not finite, integrates to 0 over a cell that
// holds samples, or to more than 1 over the sphere.
std::vector<double> cell_integrals(const DirectionDensity& density, const SphereGrid& grid, const std::vector<long>& observed,
                                   const ChiSquareOptions& options, ChiSquareResult* result) {
    const int cells = grid.cells();
    const long n = options.samples;
    std::vector<std::string> cell_defects(cells);
    auto checked_density = [&](int cell, brdf::float3 w) {
        double p = density(w);
        if (!(p >= 0.0) || !std::isfinite(p)) {
            if (cell_defects[cell].empty()) cell_defects[cell] = format("density %g at wi = (%g, %g, %g)", p, w.x, w.y, w.z);
            return 0.0;
        }
        return p;
    };
    auto tolerance = [&](int cell) { return 0.01 * std::sqrt(std::max(double(observed[cell]), 1.0)) / double(n); };
    std::vector<double> integral = integrate_cells(checked_density, grid, tolerance, options.threads);
    for (const std::string& d : cell_defects) {
        if (!d.empty()) {
            result->failure = d;
            return integral;
        }
    }
    for (int i = 0; i < cells; ++i) result->pdf_integral += integral[i];
    for (int i = 0; i < cells; ++i) {
        if (observed[i] > 0 && !(integral[i] > 0.0)) {
            result->failure = format("%g samples in a cell where the density integrates to 0: ", double(observed[i])) +
                              describe_cell(i, grid);
            return integral;
        }
    }
    if (result->pdf_integral > 1.0 + 1e-3)
        result->failure = format("the density integrates to %.6f over the sphere (more than 1)", result->pdf_integral);
    return integral;
}

// 3. Pearson's statistic over the cells and one bin for the non-continuous samples (so the
// bins form a multinomial with total n), pooling bins expected to hold fewer than 5. Sets
// result->statistic, worst_cell and cells.
void pearson_statistic(const Histogram& h, const std::vector<double>& integral, const SphereGrid& grid, long n,
                       ChiSquareResult* result) {
    const int cells = grid.cells();
    std::vector<Bin> bins;
    bins.reserve(cells + 1);
    for (int i = 0; i < cells; ++i) bins.push_back({double(n) * integral[i], h.observed[i], i});
    bins.push_back({double(n) * std::max(0.0, 1.0 - result->pdf_integral), h.delta + h.failed, -1});
    std::stable_sort(bins.begin(), bins.end(), [](const Bin& a, const Bin& b) { return a.expected < b.expected; });
    Bin pool{0.0, 0, -2};
    std::vector<Bin> kept;
    for (const Bin& b : bins) {
        if (b.expected < kMinExpected) {
            pool.expected += b.expected;
            pool.observed += b.observed;
        } else {
            kept.push_back(b);
        }
    }
    if (pool.expected >= kMinExpected || kept.empty()) {
        kept.push_back(pool);
    } else {
        kept.front().expected += pool.expected;  // too small alone: joins the smallest kept bin
        kept.front().observed += pool.observed;
        kept.front().cell = -2;
    }
    double worst = -1.0;
    for (const Bin& b : kept) {
        if (!(b.expected > 0.0)) continue;
        double diff = double(b.observed) - b.expected;
        double term = diff * diff / b.expected;
        result->statistic += term;
        if (term > worst) {
            worst = term;
            std::string where = b.cell >= 0 ? describe_cell(b.cell, grid)
                                : b.cell == -1 ? std::string("delta + failed samples") : std::string("pooled cells");
            result->worst_cell = where + format(": observed %.0f, expected %.1f", double(b.observed), b.expected);
        }
    }
    result->cells = int(kept.size());
}

}  // namespace

ChiSquareResult chi_square_test(const DirectionSampler& sampler, const DirectionDensity& density,
                                const ChiSquareOptions& options) {
    ChiSquareResult result;
    result.alpha = sidak_alpha(options.significance, options.tests);
    const SphereGrid grid{options.z_cells, options.phi_cells};
    const long n = options.samples;

    const Histogram h = sample_histogram(sampler, grid, options);
    long continuous = n - h.delta - h.failed;
    result.delta_fraction = double(h.delta) / n;
    result.failed_fraction = double(h.failed) / n;
    result.continuous_fraction = double(continuous) / n;
    if (!h.defect.empty()) {
        result.failure = h.defect;
        return result;
    }

    const std::vector<double> integral = cell_integrals(density, grid, h.observed, options, &result);
    if (!result.failure.empty()) return result;

    pearson_statistic(h, integral, grid, n, &result);
    result.dof = result.cells - 1;
    result.p_value = result.dof > 0 ? chi_square_survival(result.statistic, result.dof) : 1.0;
    result.passed = result.p_value >= result.alpha;
    if (!result.passed)
        result.failure = format("p-value %.3g below the level %.3g", result.p_value, result.alpha) + "; worst " +
                         result.worst_cell;
    return result;
}

std::string describe(const ChiSquareResult& r) {
    std::string s = format("p = %.4g (alpha %.3g), chi2 = %.1f, dof %.0f", r.p_value, r.alpha, r.statistic, double(r.dof));
    s += format("; pdf integral %.6f; samples continuous %.6f, delta %.6f, failed %.6f", r.pdf_integral,
                r.continuous_fraction, r.delta_fraction, r.failed_fraction);
    if (!r.failure.empty()) s += "; FAILED: " + r.failure;
    return s;
}

DirectionSampler bsdf_direction_sampler(const brdf::Material& material, brdf::float3 wo) {
    return [material, wo](brdf::float3 u) {
        DirectionSample out;
        brdf::BsdfSample s = brdf::bsdf_sample(&material, wo, u);
        if (s.flags == 0) return out;
        out.wi = s.wi;
        if (!in_domain(s.wi)) {  // the test reports it
            out.kind = SampleKind::Continuous;
            return out;
        }
        if (!std::isfinite(s.pdf) || !(s.pdf > 0.0f) || !brdf::finite3(s.f) || std::fmin(s.f.x, std::fmin(s.f.y, s.f.z)) < 0.0f) {
            out.defect = format("sample wi = (%g, %g, %g) carries pdf %g, f.x %g", s.wi.x, s.wi.y, s.wi.z, s.pdf, s.f.x);
            return out;
        }
        if (s.flags & BSDF_DELTA) {
            out.kind = SampleKind::Delta;
            if (s.pdf > 1.0f) out.defect = format("delta sample with discrete probability %g > 1", s.pdf);
            return out;
        }
        out.kind = SampleKind::Continuous;
        if (s.wi.z != 0.0f && wo.z != 0.0f) {
            int side = brdf::same_hemisphere(wo, s.wi) ? BSDF_REFLECTION : BSDF_TRANSMISSION;
            if ((s.flags & (BSDF_REFLECTION | BSDF_TRANSMISSION)) != side)
                out.defect = format("sample wi = (%g, %g, %g) has flags %g, wrong side", s.wi.x, s.wi.y, s.wi.z, s.flags);
        }
        if (!promise_checked(u)) return out;
        float pdf = brdf::bsdf_pdf(&material, wo, s.wi);
        if (std::fabs(s.pdf - pdf) > kConsistency * std::fmax(s.pdf, pdf))
            out.defect = format("sample wi = (%g, %g, %g) returned pdf %.8g, bsdf_pdf gives %.8g", s.wi.x, s.wi.y, s.wi.z,
                                s.pdf, pdf);
        brdf::float3 f = brdf::bsdf_eval(&material, wo, s.wi);
        float scale = kConsistency * std::fmax(brdf::max_component(f), brdf::max_component(s.f));
        for (int c = 0; c < 3; ++c) {
            if (std::fabs(s.f[c] - f[c]) > scale)
                out.defect = format("sample wi = (%g, %g, %g) returned f %.8g, bsdf_eval gives %.8g (channel %g)", s.wi.x,
                                    s.wi.y, s.wi.z, s.f[c], f[c], c);
        }
        return out;
    };
}

DirectionDensity bsdf_direction_density(const brdf::Material& material, brdf::float3 wo) {
    return [material, wo](brdf::float3 wi) { return double(brdf::bsdf_pdf(&material, wo, wi)); };
}

ChiSquareResult chi_square_bsdf(const brdf::Material& material, brdf::float3 wo, const ChiSquareOptions& options) {
    return chi_square_test(bsdf_direction_sampler(material, wo), bsdf_direction_density(material, wo), options);
}

}  // namespace lab::validation
