#include "brdf/host/measured_registry.hpp"

#include <atomic>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>

#include <cstring>

#include "brdf/brdf.hpp"
#include "common/input_error.hpp"

namespace brdf {
namespace {

// The energy part of the array (brdf/bsdf_tables.h), which every registry begins with.
std::vector<float> bsdf_energy_table_data() {
    static_assert(sizeof(energy_ggx_anisotropic_albedo) <= (BSDF_TABLES_ANISOTROPIC_AVERAGE - BSDF_TABLES_ANISOTROPIC_ALBEDO) * sizeof(float),
                  "the anisotropic codes fit their floats");
    static_assert(sizeof(energy_ggx_anisotropic_average) == (BSDF_TABLES_MEASURED - BSDF_TABLES_ANISOTROPIC_AVERAGE) * sizeof(float),
                  "the anisotropic averages fill theirs");
    std::vector<float> data(BSDF_TABLES_MEASURED, 0.0f);
    std::memcpy(data.data() + BSDF_TABLES_ANISOTROPIC_ALBEDO, energy_ggx_anisotropic_albedo, sizeof(energy_ggx_anisotropic_albedo));
    std::memcpy(data.data() + BSDF_TABLES_ANISOTROPIC_AVERAGE, energy_ggx_anisotropic_average, sizeof(energy_ggx_anisotropic_average));
    return data;
}

// Registration copies the array and publishes the copy; earlier arrays stay alive (retired), so a
// thread evaluating through a pointer it read before a registration never reads freed memory. A few
// tables per process make the copies cheap next to reading a file.
using Array = std::shared_ptr<const std::vector<float>>;
struct Registry {
    std::mutex mutex;  // serialises registrations
    Array current = std::make_shared<const std::vector<float>>(bsdf_energy_table_data());
    std::vector<Array> retired;
    std::atomic<const float*> data{current->data()};  // current->data(), read on every host evaluation
    std::map<std::string, int> offsets;  // by file (canonical path) or table source
};

Registry& registry() {
    static Registry r;
    return r;
}

void append_cdf(const std::vector<double>& mass, std::vector<float>* out) {
    double total = 0.0;
    for (double m : mass) total += m;
    double running = 0.0;
    out->push_back(0.0f);
    for (size_t i = 0; i + 1 < mass.size(); ++i) {
        running += mass[i];
        out->push_back(float(running / total));
    }
    out->push_back(1.0f);  // exactly: the last cell ends at 1 whatever the rounding
}

int register_block(const std::string& key, const std::function<std::vector<float>()>& make) {
    Registry& r = registry();
    {
        std::lock_guard<std::mutex> lock(r.mutex);
        auto it = r.offsets.find(key);
        if (it != r.offsets.end()) return it->second;
    }
    std::vector<float> block = make();
    std::lock_guard<std::mutex> lock(r.mutex);
    auto it = r.offsets.find(key);
    if (it != r.offsets.end()) return it->second;
    const Array old = std::atomic_load(&r.current);
    if (old->size() + block.size() > size_t(0x7fffffff))
        throw lab::InputError(key, "", "too many measured tables for one process (2^31 floats)");
    int offset = int(old->size());
    auto grown = std::make_shared<std::vector<float>>(*old);
    grown->insert(grown->end(), block.begin(), block.end());
    r.retired.push_back(old);
    r.data.store(grown->data(), std::memory_order_release);
    std::atomic_store(&r.current, Array(std::move(grown)));
    r.offsets[key] = offset;
    return offset;
}

std::vector<float> block_of(const MeasuredTable& table) {
    std::vector<float> block = table.rgb;
    block.reserve(MEASURED_BLOCK_FLOATS);
    append_measured_sampler(&block);
    return block;
}

}  // namespace

const float* bsdf_tables() { return registry().data.load(std::memory_order_acquire); }

const std::vector<float>& bsdf_table_data() { return *std::atomic_load(&registry().current); }


void append_measured_sampler(std::vector<float>* block) {
    const float* table = block->data();
    const int nt = MEASURED_THETA_I_BINS, np = MEASURED_PHI_BINS;
    const double band = 0.5 * M_PI / nt, cell_phi = M_PI / np;
    std::vector<float> sampler;
    sampler.reserve(size_t(MEASURED_THETA_O_BINS) * MEASURED_SAMPLER_BIN_FLOATS);
    for (int k = 0; k < MEASURED_THETA_O_BINS; ++k) {
        float theta_o = (float(k) + 0.5f) * 0.5f * SS_PI / MEASURED_THETA_O_BINS;
        float3 wo = make_float3(std::sin(theta_o), 0.0f, std::cos(theta_o));
        std::vector<double> cells(size_t(nt) * np);
        double total = 0.0, solid_angle = 0.0;
        for (int j = 0; j < nt; ++j) {
            double area = measured_cell_solid_angle(j);
            for (int l = 0; l < np; ++l) {
                double sum = 0.0;
                for (int a = 0; a < 2; ++a)
                    for (int b = 0; b < 2; ++b) {
                        double theta = (j + 0.25 + 0.5 * a) * band, phi = (l + 0.25 + 0.5 * b) * cell_phi;
                        float3 wi = make_float3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                                                float(std::cos(theta)));
                        float3 f = merl_eval(table, wo, wi);
                        sum += (f.x + f.y + f.z) / 3.0 * wi.z;
                    }
                cells[size_t(j) * np + l] = sum / 4.0 * area;
                total += cells[size_t(j) * np + l];
                solid_angle += area;
            }
        }
        // the floor; a black table gets the uniform density
        double floor = total > 0.0 ? 0.02 * total / solid_angle : 1.0;
        std::vector<double> rows(nt, 0.0);
        for (int j = 0; j < nt; ++j) {
            double area = measured_cell_solid_angle(j);
            for (int l = 0; l < np; ++l) rows[j] += (cells[size_t(j) * np + l] += floor * area);
        }
        append_cdf(rows, &sampler);
        for (int j = 0; j < nt; ++j)
            append_cdf(std::vector<double>(cells.begin() + size_t(j) * np, cells.begin() + size_t(j + 1) * np), &sampler);
    }
    block->insert(block->end(), sampler.begin(), sampler.end());
}

int register_measured_table(const MeasuredTable& table) {
    if (table.rgb.size() != size_t(MEASURED_TABLE_FLOATS))
        throw lab::InputError(table.source, "", "a measured table needs " + std::to_string(MEASURED_TABLE_FLOATS) + " floats");
    return register_block(table.source, [&] { return block_of(table); });
}

int register_measured_file(const std::string& path) {
    std::error_code ec;
    std::string key = std::filesystem::weakly_canonical(path, ec).string();
    if (ec) key = path;
    return register_block(key, [&] { return block_of(read_merl_file(path)); });
}

}  // namespace brdf
