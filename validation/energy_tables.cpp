#include "validation/energy_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <map>
#include <utility>
#include <sstream>

#include "brdf/host/parameters.hpp"
#include "validation/albedo.hpp"
#include "common/parallel_for.hpp"

namespace lab::validation {

namespace {

// The albedo of a microfacet reflection lobe f(wi) at wo by its visible-normal sampler over a strata x
// strata midpoint grid (the weight f cos / pdf is at most 1, so the grid converges fast). GGX's sampler
// (brdf/ggx.h) maps u1 to the radius sqrt(u1) of a disk whose rim, u1 -> 1, holds the most tilted
// visible normals: at low roughness the light they send below the horizon, all that the lobe loses
// (0.2 % at alpha 0.04), lies in a sliver of u1 near 1 that an even grid misses or catches by turns
// (64 strata: E 0.6 % low at alpha 0.09, 0.2 % high at alpha 0.04, against 2048). So GGX's grid is even
// in s, u1 = 1 - (1 - s)^2, even in the height sqrt(1 - u1) of the disk at normal incidence, which
// puts a cell in every 1/64 of that height: within 5e-4 of 2048 strata at 64 (tests/test_energy_compensation.cpp
// compares it with the lab's own sampler). Hyper-Cauchy's sampler has no such rim.
double visible_normal_albedo(brdf::Microfacet mf, brdf::float3 wo, int strata, const std::function<float(brdf::float3)>& f) {
    const bool rim = mf.kind == BRDF_DISTRIBUTION_GGX;
    double sum = 0.0;
    for (int i = 0; i < strata; ++i)
        for (int j = 0; j < strata; ++j) {
            double s = (double(i) + 0.5) / double(strata), jacobian = rim ? 2.0 * (1.0 - s) : 1.0;
            float u1 = float(rim ? 1.0 - (1.0 - s) * (1.0 - s) : s), u2 = (float(j) + 0.5f) / float(strata);
            brdf::float3 wi;
            if (!brdf::microfacet_reflection_sample_direction(mf, wo, u1, u2, &wi)) continue;
            float pdf = brdf::microfacet_reflection_pdf(mf, wo, wi);
            if (!(pdf > 0.0f)) continue;
            sum += jacobian * double(f(wi)) * wi.z / pdf;
        }
    return sum / (double(strata) * strata);
}

}  // namespace

double single_scattering_albedo(int distribution, float shape, float roughness, float mu, int strata) {
    brdf::Material m = brdf::default_material();
    m.distribution = distribution;
    m.hc_shape = shape;
    m.roughness = roughness;
    brdf::Microfacet mf = brdf::microfacet_from_material(&m);
    // at mu = 0 the limit is exactly 1: the masking of wo grows without bound, so G2 / G1(wo) -> 1, and
    // every direction reflected off a visible normal is above the horizon
    if (brdf::microfacet_is_smooth(mf) || !(mu > 0.0f)) return 1.0;
    brdf::float3 wo(std::sqrt(std::fmax(0.0f, 1.0f - mu * mu)), 0.0f, mu);
    return visible_normal_albedo(mf, wo, strata, [&](brdf::float3 wi) { return brdf::microfacet_reflection_eval(mf, brdf::float3(1.0f), wo, wi).x; });
}

double anisotropic_albedo(float ratio, float phi, float roughness, float mu, int strata) {
    float ax = brdf::anisotropic_grid_alpha_x(ratio, roughness);
    brdf::Microfacet mf = brdf::microfacet_make(BRDF_DISTRIBUTION_GGX, std::fmax(ax, BRDF_MIN_ALPHA), std::fmax(ratio * ax, BRDF_MIN_ALPHA), 2.0f);
    if (brdf::microfacet_is_smooth(mf) || !(mu > 0.0f)) return 1.0;
    float s = std::sqrt(std::fmax(0.0f, 1.0f - mu * mu));
    brdf::float3 wo(s * std::cos(phi), s * std::sin(phi), mu);
    return visible_normal_albedo(mf, wo, strata, [&](brdf::float3 wi) { return brdf::microfacet_reflection_eval(mf, brdf::float3(1.0f), wo, wi).x; });
}

double dielectric_single_scattering_albedo(int side, float roughness, float ior, float mu, int strata) {
    brdf::Material m = brdf::default_material();
    m.weight_diffuse = 0.0f;
    m.weight_transmission = 1.0f;
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 1.0f;
    m.roughness = roughness;
    m.energy_compensation = 0;
    m.ior = std::fmax(ior, 1.01f);  // the grid's node at ior 1 stands for a rough interface of nearly matched index
    mu = std::fmax(mu, 1e-5f);  // the node at mu = 0 holds grazing incidence
    brdf::float3 wo(std::sqrt(std::fmax(0.0f, 1.0f - mu * mu)), 0.0f, side == 0 ? mu : -mu);
    return directional_albedo(m, wo, strata, 1).value.x;
}

double dielectric_reflection_albedo(float roughness, float ior, float mu, int strata) {
    brdf::Material m = brdf::default_material();
    m.roughness = roughness;
    brdf::Microfacet mf = brdf::microfacet_from_material(&m);
    if (brdf::microfacet_is_smooth(mf)) return brdf::fresnel_dielectric(mu, ior);
    // grazing: every visible facet is seen edge on, where F -> 1 (but for an index-matched interface)
    if (!(mu > 0.0f)) return ior > 1.0f ? 1.0 : 0.0;
    brdf::float3 wo(std::sqrt(std::fmax(0.0f, 1.0f - mu * mu)), 0.0f, mu);
    return visible_normal_albedo(mf, wo, strata, [&](brdf::float3 wi) { return brdf::dielectric_reflection_eval(mf, ior, wo, wi); });
}

double hemisphere_cosine_midpoint(int n_t, int n_phi, const std::function<double(brdf::float3 wi)>& g) {
    double sum = 0.0;
    for (int i = 0; i < n_t; ++i) {
        double t = (i + 0.5) / n_t, mu_i = t * t, s = std::sqrt(1.0 - mu_i * mu_i);
        for (int j = 0; j < n_phi; ++j) {
            double phi = 2.0 * M_PI * (j + 0.5) / n_phi;
            brdf::float3 wi(float(s * std::cos(phi)), float(s * std::sin(phi)), float(mu_i));
            sum += g(wi) * mu_i * 2.0 * t;  // g mu_i dmu_i, dmu_i = 2 t dt
        }
    }
    return sum * 2.0 * M_PI / (double(n_t) * n_phi);
}

double sheen_albedo(float roughness, float mu, int strata) {
    mu = std::fmax(mu, 1e-4f);  // the node at mu = 0 holds grazing view
    brdf::float3 wo(std::sqrt(std::fmax(0.0f, 1.0f - mu * mu)), 0.0f, mu);
    // where the lobe of a grazing wo peaks, V grows as 1 / mu_i; 2 strata in t per stratum in phi
    return hemisphere_cosine_midpoint(2 * strata, strata, [&](brdf::float3 wi) { return double(brdf::sheen_eval(roughness, wo, wi)); }) /
           SHEEN_TABLE_SCALE;
}

float dielectric_fresnel_average_of(float ior) {
    const int n = 1 << 14;
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
        float mu = (float(k) + 0.5f) / float(n);
        sum += double(brdf::fresnel_dielectric(mu, ior)) * mu;
    }
    return float(2.0 * sum / n);
}

float average_albedo(const float* row, int n_mu) {
    // the interpolant is piecewise linear in mu: a fine midpoint rule is exact to well below 1e-6
    const int n = 1 << 14;
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
        float mu = (float(k) + 0.5f) / float(n);
        sum += double(brdf::energy_grid_lerp(row, n_mu, brdf::energy_grid_mu_coordinate_of(mu, n_mu))) * mu;
    }
    return float(2.0 * sum / n);
}

namespace {

// point k of a row: node k / 2, or the midpoint (even in sqrt(mu)) after it for odd k
float row_point_mu(int k, int n_mu) {
    float s = 0.5f * float(k) / float(n_mu - 1);
    return s * s;
}

// raises both ends of each interval by how far its midpoint lies above the chord
void lift_row(const double* points, int n_mu, float* row) {
    std::vector<double> lift(size_t(n_mu), 0.0);
    for (int j = 0; j + 1 < n_mu; ++j) {
        double lo = std::fmin(points[2 * j], 1.0), hi = std::fmin(points[2 * j + 2], 1.0);
        double deficit = std::fmax(std::fmin(points[2 * j + 1], 1.0) - 0.5 * (lo + hi), 0.0);
        lift[size_t(j)] = std::fmax(lift[size_t(j)], deficit);
        lift[size_t(j) + 1] = std::fmax(lift[size_t(j) + 1], deficit);
    }
    for (int j = 0; j < n_mu; ++j) row[j] = float(std::fmin(std::fmin(points[2 * j], 1.0) + lift[size_t(j)], 1.0));
}

}  // namespace

std::vector<float> energy_slice(const std::function<double(float roughness, float mu)>& albedo, int n_r, int n_mu, int threads,
                                int first, int last) {
    // the rows first - 1 to last + 1 (in the grid) and the mid rows between them, at every mu point
    const int lo = std::max(first - 1, 0), hi = std::min(last + 1, n_r - 1), per_row = 2 * n_mu - 1, half_rows = 2 * (hi - lo) + 1;
    std::vector<double> points(size_t(half_rows) * size_t(per_row));
    parallel_for(half_rows * per_row, threads, [&](int k) {
        float roughness = 0.5f * float(2 * lo + k / per_row) / float(n_r - 1);
        points[size_t(k)] = albedo(roughness, row_point_mu(k % per_row, n_mu));
    });
    const int rows = hi - lo + 1;
    std::vector<float> base(size_t(rows) * size_t(n_mu));
    for (int i = 0; i < rows; ++i) lift_row(points.data() + size_t(2 * i) * per_row, n_mu, base.data() + size_t(i) * n_mu);
    // lift[i][j]: how far the mid rows on either side of row i lie above the bilinear interpolant near node j
    std::vector<double> lift(base.size(), 0.0);
    for (int i = 0; i + 1 < rows; ++i) {
        const float *a = base.data() + size_t(i) * n_mu, *b = a + n_mu;
        const double* mid = points.data() + size_t(2 * i + 1) * per_row;
        auto raise = [&](int j, double deficit) {
            for (int row : {i, i + 1}) lift[size_t(row) * n_mu + j] = std::fmax(lift[size_t(row) * n_mu + j], deficit);
        };
        for (int j = 0; j < n_mu; ++j) raise(j, std::fmin(mid[2 * j], 1.0) - 0.5 * (double(a[j]) + b[j]));
        for (int j = 0; j + 1 < n_mu; ++j) {
            double deficit = std::fmin(mid[2 * j + 1], 1.0) - 0.25 * (double(a[j]) + a[j + 1] + b[j] + b[j + 1]);
            raise(j, deficit);
            raise(j + 1, deficit);
        }
    }
    std::vector<float> out;
    for (int i = first; i <= last; ++i)
        for (int j = 0; j < n_mu; ++j) {
            size_t k = size_t(i - lo) * n_mu + j;
            out.push_back(float(std::fmin(double(base[k]) + lift[k], 1.0)));
        }
    return out;
}

unsigned short energy_table_code(float e) {
    float q = std::ceil(std::fmin(std::fmax(e, 0.0f), 1.0f) * ENERGY_TABLE_ONE);
    // the kernel decodes q * (1 / 65535) in float: step up where that lands below e
    while (q < ENERGY_TABLE_ONE && q * (1.0f / ENERGY_TABLE_ONE) < e) q += 1.0f;
    return static_cast<unsigned short>(q);
}

float energy_table_round_up(float e) { return float(energy_table_code(e)) * (1.0f / ENERGY_TABLE_ONE); }

namespace {

void round_up(std::vector<float>& values) {
    for (float& v : values) v = energy_table_round_up(v);
}

// one table of [roughness][mu] for a distribution and shape, and its averages
void fill_slice(int distribution, float shape, int strata, int threads, float* albedo, float* average) {
    std::vector<float> slice = energy_slice([&](float r, float mu) { return single_scattering_albedo(distribution, shape, r, mu, strata); },
                                            ENERGY_GRID_ROUGHNESS, ENERGY_GRID_MU, threads, 0, ENERGY_GRID_ROUGHNESS - 1);
    round_up(slice);
    std::copy(slice.begin(), slice.end(), albedo);
    for (int i = 0; i < ENERGY_GRID_ROUGHNESS; ++i) average[i] = average_albedo(albedo + i * ENERGY_GRID_MU);
}

// Where a table's arrays live in a kernel: `__constant` (CONSTANT_MEM), or nowhere, for a table
// the kernels read from the BSDF tables buffer in global memory (brdf/bsdf_tables.h), whose
// header the host alone includes.
enum class TableStorage { constant, host };

const char* storage_text(TableStorage storage) { return storage == TableStorage::constant ? "CONSTANT_MEM const" : "const"; }

std::string array_text(const char* name, const char* size, const std::vector<float>& values, int per_line,
                       TableStorage storage = TableStorage::constant) {
    std::ostringstream out;
    out << storage_text(storage) << " float " << name << "[" << size << "] = {\n";
    for (size_t k = 0; k < values.size(); ++k) {
        char number[32];
        std::snprintf(number, sizeof number, "%.7ff", double(values[k]));
        out << (k % size_t(per_line) == 0 ? "    " : " ") << number << (k + 1 < values.size() ? "," : "");
        if ((k + 1) % size_t(per_line) == 0 || k + 1 == values.size()) out << "\n";
    }
    out << "};\n";
    return out.str();
}

// an albedo table, already rounded up, as its 16-bit codes
std::string albedo_array_text(const char* name, const char* size, const std::vector<float>& values,
                              TableStorage storage = TableStorage::constant) {
    const int per_line = 12;
    std::ostringstream out;
    out << storage_text(storage) << " ushort " << name << "[" << size << "] = {\n";
    for (size_t k = 0; k < values.size(); ++k) {
        long code = std::lround(double(values[k]) * double(ENERGY_TABLE_ONE));  // values are codes / 65535 already
        out << (k % size_t(per_line) == 0 ? "    " : " ") << code << (k + 1 < values.size() ? "," : "");
        if ((k + 1) % size_t(per_line) == 0 || k + 1 == values.size()) out << "\n";
    }
    out << "};\n";
    return out.str();
}

std::string header(const char* guard, const std::string& what, int strata, const std::string& arrays) {
    std::ostringstream out;
    out << "/* GENERATED by tools/generate_energy_tables (validation/energy_tables.cpp), " << strata << "x" << strata
        << " samples per entry; do not edit.\n"
        << " * " << what << "\n"
        << " * Grid: brdf/energy_grid.h. Single source: the same numbers reach the C++ and the OpenCL builds. */\n"
        << "#ifndef " << guard << "\n#define " << guard << "\n#include \"single_source/vocabulary.h\"\n"
        << "#include \"energy_grid.h\"\n\n"
        << arrays << "\n#endif\n";
    return out.str();
}

}  // namespace

EnergyTables compute_energy_tables(int strata, int threads) {
    EnergyTables t;
    const int slice = ENERGY_GRID_ROUGHNESS * ENERGY_GRID_MU;
    t.ggx_albedo.resize(size_t(slice));
    t.ggx_average.resize(ENERGY_GRID_ROUGHNESS);
    fill_slice(BRDF_DISTRIBUTION_GGX, 2.0f, strata, threads, t.ggx_albedo.data(), t.ggx_average.data());
    t.hyper_cauchy_albedo.resize(size_t(slice) * ENERGY_GRID_SHAPE);
    t.hyper_cauchy_average.resize(size_t(ENERGY_GRID_ROUGHNESS) * ENERGY_GRID_SHAPE);
    for (int k = 0; k < ENERGY_GRID_SHAPE; ++k)
        fill_slice(BRDF_DISTRIBUTION_HYPER_CAUCHY, brdf::energy_grid_shape(k), strata, threads,
                   t.hyper_cauchy_albedo.data() + size_t(k) * slice, t.hyper_cauchy_average.data() + size_t(k) * ENERGY_GRID_ROUGHNESS);
    const int rows = 2 * DIELECTRIC_GRID_IOR * DIELECTRIC_GRID_ROUGHNESS;
    t.dielectric_albedo.resize(size_t(rows) * DIELECTRIC_GRID_MU);
    t.dielectric_average.resize(size_t(rows));
    for (int side : {0, 1})
        for (int k = 0; k < DIELECTRIC_GRID_IOR; ++k) {
            std::vector<float> slice = energy_slice([&](float r, float mu) {
                return dielectric_single_scattering_albedo(side, r, brdf::energy_grid_ior(k), mu, strata * kDielectricStrataFactor);
            }, DIELECTRIC_GRID_ROUGHNESS, DIELECTRIC_GRID_MU, threads, 0, DIELECTRIC_GRID_ROUGHNESS - 1);
            round_up(slice);
            std::copy(slice.begin(), slice.end(), t.dielectric_albedo.begin() + ptrdiff_t((side * DIELECTRIC_GRID_IOR + k) * DIELECTRIC_GRID_ROUGHNESS * DIELECTRIC_GRID_MU));
        }
    for (int r = 0; r < rows; ++r) t.dielectric_average[size_t(r)] = average_albedo(t.dielectric_albedo.data() + size_t(r) * DIELECTRIC_GRID_MU, DIELECTRIC_GRID_MU);
    for (int k = 0; k < DIELECTRIC_GRID_IOR; ++k)
        t.dielectric_fresnel.push_back(dielectric_fresnel_average_of(std::fmax(brdf::energy_grid_ior(k), 1.01f)));
    return t;
}

namespace {

// E at the half nodes (hq / 2, hp / 2) in ratio and azimuth: rows first to last of energy_slice() over roughness and mu
std::vector<float> anisotropic_half_slice(int hq, int hp, int first, int last, int strata, int threads) {
    float ratio = brdf::anisotropic_grid_ratio(0.5f * float(hq)), phi = brdf::anisotropic_grid_phi(0.5f * float(hp));
    return energy_slice([&](float r, float mu) { return anisotropic_albedo(ratio, phi, r * ANISO_GRID_ROUGHNESS_MAX, mu, strata); },
                        ANISO_GRID_ROUGHNESS, ANISO_GRID_MU, threads, first, last);
}

}  // namespace

std::vector<float> anisotropic_node_entries(int k, int l, const std::function<const std::vector<float>&(int hq, int hp)>& at) {
    const std::vector<float>& own = at(2 * k, 2 * l);
    std::vector<float> lift(own.size(), 0.0f);
    // the group of nodes k0 .. k0 + dk, l0 .. l0 + dl (a pair in azimuth or in ratio, or a cell) and its midpoint
    auto raise = [&](int k0, int l0, int dk, int dl) {
        if (k0 < 0 || l0 < 0 || k0 + dk >= ANISO_GRID_RATIO || l0 + dl >= ANISO_GRID_PHI) return;
        const std::vector<float>& mid = at(2 * k0 + dk, 2 * l0 + dl);
        for (size_t e = 0; e < own.size(); ++e) {
            double mean = 0.0;
            for (int a = 0; a <= dk; ++a)
                for (int b = 0; b <= dl; ++b) mean += at(2 * (k0 + a), 2 * (l0 + b))[e];
            lift[e] = std::fmax(lift[e], float(std::fmin(double(mid[e]), 1.0) - mean / double((dk + 1) * (dl + 1))));
        }
    };
    for (int dk = 0; dk <= 1; ++dk)
        for (int dl = 0; dl <= 1; ++dl)
            if (dk + dl > 0)
                for (int a = 0; a <= dk; ++a)
                    for (int b = 0; b <= dl; ++b) raise(k - a, l - b, dk, dl);
    std::vector<float> out(own.size());
    for (size_t e = 0; e < own.size(); ++e) out[e] = std::fmin(own[e] + lift[e], 1.0f);
    return out;
}

std::vector<float> anisotropic_table_row(int k, int l, int i, int strata, int threads) {
    std::map<std::pair<int, int>, std::vector<float>> slices;
    return anisotropic_node_entries(k, l, [&](int hq, int hp) -> const std::vector<float>& {
        auto found = slices.find({hq, hp});
        if (found == slices.end()) found = slices.emplace(std::make_pair(hq, hp), anisotropic_half_slice(hq, hp, i, i, strata, threads)).first;
        return found->second;
    });
}

float anisotropic_table_average(const std::vector<float>& albedo, int k, int i) {
    // the mean over phi of the interpolant, linear in phi between the nodes: node l's weight is the mean of its hat function
    const int np = ANISO_GRID_PHI, n_phi = 1 << 14;
    std::vector<double> weight(size_t(np), 0.0);
    for (int j = 0; j < n_phi; ++j) {
        double u = brdf::anisotropic_grid_phi_coordinate(float(0.5 * M_PI * (j + 0.5) / n_phi));
        int l = std::min(int(u), np - 2);
        weight[size_t(l)] += (l + 1 - u) / n_phi;
        weight[size_t(l) + 1] += (u - l) / n_phi;
    }
    double sum = 0.0;
    for (int l = 0; l < np; ++l)
        sum += weight[size_t(l)] * average_albedo(albedo.data() + size_t(((k * np + l) * ANISO_GRID_ROUGHNESS + i) * ANISO_GRID_MU), ANISO_GRID_MU);
    return float(sum);
}

AnisotropicTables compute_anisotropic_tables(int strata, int threads) {
    const int nq = ANISO_GRID_RATIO, np = ANISO_GRID_PHI;
    // slices at every half node in ratio and azimuth: (2 nq - 1) x (2 np - 1), each lifted in roughness and mu
    std::vector<std::vector<float>> half(size_t((2 * nq - 1) * (2 * np - 1)));
    for (int hq = 0; hq < 2 * nq - 1; ++hq)
        for (int hp = 0; hp < 2 * np - 1; ++hp)
            half[size_t(hq * (2 * np - 1) + hp)] = anisotropic_half_slice(hq, hp, 0, ANISO_GRID_ROUGHNESS - 1, strata, threads);
    auto at = [&](int hq, int hp) -> const std::vector<float>& { return half[size_t(hq * (2 * np - 1) + hp)]; };
    AnisotropicTables t;
    for (int k = 0; k < nq; ++k)
        for (int l = 0; l < np; ++l) {
            std::vector<float> node = anisotropic_node_entries(k, l, at);
            t.albedo.insert(t.albedo.end(), node.begin(), node.end());
        }
    round_up(t.albedo);
    for (int k = 0; k < nq; ++k)
        for (int i = 0; i < ANISO_GRID_ROUGHNESS; ++i) t.average.push_back(anisotropic_table_average(t.albedo, k, i));
    return t;
}

std::string anisotropic_table_header(const AnisotropicTables& t, int strata) {
    return header("BRDF_ENERGY_TABLE_GGX_ANISOTROPIC_H",
                  "Anisotropic GGX: E(w) [ratio][phi][roughness][mu] (16-bit, rounded up) and E_avg [ratio][roughness].\n"
                  " * The host's copy: kernels read these numbers from the BSDF tables buffer (brdf/bsdf_tables.h).",
                  strata,
                  albedo_array_text("energy_ggx_anisotropic_albedo", "ANISO_GRID_RATIO * ANISO_GRID_PHI * ANISO_GRID_ROUGHNESS * ANISO_GRID_MU",
                                    t.albedo, TableStorage::host) +
                      "\n" + array_text("energy_ggx_anisotropic_average", "ANISO_GRID_RATIO * ANISO_GRID_ROUGHNESS", t.average, 8, TableStorage::host));
}

OpenPbrTables compute_openpbr_tables(int strata, int threads) {
    OpenPbrTables t;
    for (int k = 0; k < DIELECTRIC_GRID_IOR; ++k) {
        const float ior = brdf::energy_grid_ior(k);
        std::vector<float> slice = energy_slice([&](float r, float mu) { return dielectric_reflection_albedo(r, ior, mu, strata); },
                                                DIELECTRIC_GRID_ROUGHNESS, DIELECTRIC_GRID_MU, threads, 0, DIELECTRIC_GRID_ROUGHNESS - 1);
        round_up(slice);
        t.specular_albedo.insert(t.specular_albedo.end(), slice.begin(), slice.end());
    }
    for (size_t r = 0; r < t.specular_albedo.size() / DIELECTRIC_GRID_MU; ++r)
        t.specular_average.push_back(average_albedo(t.specular_albedo.data() + r * DIELECTRIC_GRID_MU, DIELECTRIC_GRID_MU));
    t.sheen_albedo = energy_slice([&](float r, float mu) { return sheen_albedo(r, mu, strata * kSheenStrataFactor); }, ENERGY_GRID_ROUGHNESS,
                                  ENERGY_GRID_MU, threads, 0, ENERGY_GRID_ROUGHNESS - 1);
    round_up(t.sheen_albedo);
    return t;
}

std::string openpbr_table_header(const OpenPbrTables& t, int strata) {
    return header("BRDF_ENERGY_TABLE_OPENPBR_H",
                  "OpenPBR's layers: E(mu) of GGX reflection off a dielectric with its exact Fresnel [ior][roughness][mu] (dielectric grid) and its "
                  "E_avg [ior][roughness]; E(mu) / SHEEN_TABLE_SCALE of the Charlie sheen [roughness][mu] (conductors' grid, " +
                      std::to_string(kSheenStrataFactor) + "x the strata per side). 16-bit, rounded up.",
                  strata,
                  albedo_array_text("energy_openpbr_specular_albedo", "DIELECTRIC_GRID_IOR * DIELECTRIC_GRID_ROUGHNESS * DIELECTRIC_GRID_MU",
                                    t.specular_albedo) +
                      "\n" + array_text("energy_openpbr_specular_average", "DIELECTRIC_GRID_IOR * DIELECTRIC_GRID_ROUGHNESS", t.specular_average, 8) +
                      "\n" + albedo_array_text("energy_openpbr_sheen_albedo", "ENERGY_GRID_ROUGHNESS * ENERGY_GRID_MU", t.sheen_albedo));
}

std::string ggx_table_header(const EnergyTables& t, int strata) {
    return header("BRDF_ENERGY_TABLE_GGX_H", "GGX: E(mu) [roughness][mu] (16-bit, rounded up) and E_avg [roughness].", strata,
                  albedo_array_text("energy_ggx_albedo", "ENERGY_GRID_ROUGHNESS * ENERGY_GRID_MU", t.ggx_albedo) + "\n" +
                      array_text("energy_ggx_average", "ENERGY_GRID_ROUGHNESS", t.ggx_average, 8));
}

std::string hyper_cauchy_table_header(const EnergyTables& t, int strata) {
    return header("BRDF_ENERGY_TABLE_HYPER_CAUCHY_H", "Hyper-Cauchy: E(mu) [shape][roughness][mu] (16-bit, rounded up) and E_avg [shape][roughness].",
                  strata,
                  albedo_array_text("energy_hyper_cauchy_albedo", "ENERGY_GRID_SHAPE * ENERGY_GRID_ROUGHNESS * ENERGY_GRID_MU",
                                    t.hyper_cauchy_albedo) +
                      "\n" +
                      array_text("energy_hyper_cauchy_average", "ENERGY_GRID_SHAPE * ENERGY_GRID_ROUGHNESS", t.hyper_cauchy_average, 8));
}

std::string dielectric_table_header(const EnergyTables& t, int strata) {
    return header("BRDF_ENERGY_TABLE_DIELECTRIC_H",
                  "Rough GGX dielectric, white, reflection + transmission: E(mu) [side][ior][roughness][mu] (16-bit, rounded up; side 0 outside, 1 "
                  "inside), E_avg [side][ior][roughness], and the Fresnel average from outside [ior].",
                  strata * kDielectricStrataFactor,
                  albedo_array_text("energy_dielectric_albedo", "2 * DIELECTRIC_GRID_IOR * DIELECTRIC_GRID_ROUGHNESS * DIELECTRIC_GRID_MU",
                                    t.dielectric_albedo) +
                      "\n" +
                      array_text("energy_dielectric_average", "2 * DIELECTRIC_GRID_IOR * DIELECTRIC_GRID_ROUGHNESS", t.dielectric_average, 8) +
                      "\n" + array_text("energy_dielectric_fresnel_average", "DIELECTRIC_GRID_IOR", t.dielectric_fresnel, 8));
}

}  // namespace lab::validation
