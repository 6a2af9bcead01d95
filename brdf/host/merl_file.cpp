#include "brdf/host/merl_file.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "common/input_error.hpp"

namespace brdf {
namespace {

const char* const kChannelName[3] = {"red", "green", "blue"};

std::string entry_name(int channel, int e) {
    int ip = e % MERL_PHI_D_BINS;
    int id = (e / MERL_PHI_D_BINS) % MERL_THETA_D_BINS;
    int ih = e / (MERL_PHI_D_BINS * MERL_THETA_D_BINS);
    std::ostringstream s;
    s << kChannelName[channel] << " entry " << e << " (theta_h bin " << ih << ", theta_d bin " << id
      << ", phi_d bin " << ip << ")";
    return s.str();
}

// The fill of read_merl_file's comment: per (theta_h, phi_d) column, holes take the nearest measured
// entry below them in theta_d, or above when there is none below.
void fill_unmeasured(MeasuredTable& t) {
    if (t.unmeasured.empty()) return;
    for (int ih = 0; ih < MERL_THETA_H_BINS; ++ih)
        for (int ip = 0; ip < MERL_PHI_D_BINS; ++ip)
            for (int id = 0; id < MERL_THETA_D_BINS; ++id) {
                const int e = merl_entry_index(ih, id, ip);
                if (!t.unmeasured[std::size_t(e)]) continue;
                int from = -1;
                for (int k = id - 1; k >= 0 && from < 0; --k)
                    if (!t.unmeasured[std::size_t(merl_entry_index(ih, k, ip))]) from = merl_entry_index(ih, k, ip);
                for (int k = id + 1; k < MERL_THETA_D_BINS && from < 0; ++k)
                    if (!t.unmeasured[std::size_t(merl_entry_index(ih, k, ip))]) from = merl_entry_index(ih, k, ip);
                for (int c = 0; c < 3; ++c) t.rgb[std::size_t(3) * e + c] = from < 0 ? 0.0f : t.rgb[std::size_t(3) * from + c];
            }
}

}  // namespace

MeasuredTable read_merl_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw lab::InputError(path, "", "cannot open the measured BRDF file");
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0, std::ios::beg);

    const std::streamoff header = 3 * sizeof(std::int32_t);
    if (size < header)
        throw lab::InputError(path, "dimensions", "truncated: " + std::to_string(size) + " bytes, the header alone is 12");
    std::int32_t dims[3];
    in.read(reinterpret_cast<char*>(dims), sizeof dims);
    const std::int32_t expected[3] = {MERL_THETA_H_BINS, MERL_THETA_D_BINS, MERL_PHI_D_BINS};
    if (dims[0] != expected[0] || dims[1] != expected[1] || dims[2] != expected[2]) {
        std::ostringstream s;
        s << dims[0] << " x " << dims[1] << " x " << dims[2] << ", but a MERL table is 90 x 90 x 180";
        throw lab::InputError(path, "dimensions", s.str());
    }
    const std::streamoff payload = std::streamoff(3) * MERL_ENTRY_COUNT * sizeof(double);
    if (size < header + payload)
        throw lab::InputError(path, "data", "truncated: " + std::to_string(size) + " bytes, expected " +
                                                std::to_string(header + payload));
    if (size > header + payload)
        throw lab::InputError(path, "data", std::to_string(size - header - payload) +
                                                " bytes after the last entry (not a MERL table?)");

    MeasuredTable table;
    table.source = path;
    table.rgb.resize(std::size_t(3) * MERL_ENTRY_COUNT);
    std::vector<double> file(std::size_t(3) * MERL_ENTRY_COUNT);  // channel blocks, file units
    in.read(reinterpret_cast<char*>(file.data()), std::streamsize(file.size() * sizeof(double)));
    if (!in) throw lab::InputError(path, "data", "read failed");
    for (int e = 0; e < MERL_ENTRY_COUNT; ++e) {
        int negative = 0;
        for (int c = 0; c < 3; ++c) {
            const double v = file[std::size_t(c) * MERL_ENTRY_COUNT + e];
            if (!std::isfinite(v)) throw lab::InputError(path, entry_name(c, e), "not a finite number");
            negative += v < 0.0;
        }
        if (negative == 3) {
            if (table.unmeasured.empty()) table.unmeasured.assign(MERL_ENTRY_COUNT, false);
            table.unmeasured[std::size_t(e)] = true;
            continue;
        }
        for (int c = 0; c < 3; ++c) {
            const double v = file[std::size_t(c) * MERL_ENTRY_COUNT + e];
            if (v < 0.0)
                throw lab::InputError(path, entry_name(c, e),
                                      "negative (" + std::to_string(v) + ") while other channels are measured");
            table.rgb[std::size_t(3) * e + c] = float(v * kMerlScale[c]);
        }
    }
    fill_unmeasured(table);
    return table;
}

void write_merl_file(const std::string& path, const MeasuredTable& table) {
    if (table.rgb.size() != std::size_t(3) * MERL_ENTRY_COUNT)
        throw std::invalid_argument("write_merl_file: the table has " + std::to_string(table.rgb.size()) + " floats");
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw lab::InputError(path, "", "cannot write the measured BRDF file");
        const std::int32_t dims[3] = {MERL_THETA_H_BINS, MERL_THETA_D_BINS, MERL_PHI_D_BINS};
        out.write(reinterpret_cast<const char*>(dims), sizeof dims);
        std::vector<double> block(MERL_ENTRY_COUNT);
        for (int c = 0; c < 3; ++c) {
            for (int e = 0; e < MERL_ENTRY_COUNT; ++e)
                block[e] = is_unmeasured(table, e) ? -1.0 : double(table.rgb[std::size_t(3) * e + c]) / kMerlScale[c];
            out.write(reinterpret_cast<const char*>(block.data()), std::streamsize(block.size() * sizeof(double)));
        }
        if (!out.flush()) throw lab::InputError(path, "", "write failed");
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) throw lab::InputError(path, "", "cannot rename the written file into place");
}

MeasuredTable tabulate_merl(const std::function<float3(float3 wo, float3 wi)>& f, const std::string& source) {
    MeasuredTable table;
    table.source = source;
    table.rgb.resize(std::size_t(3) * MERL_ENTRY_COUNT);
    for (int ih = 0; ih < MERL_THETA_H_BINS; ++ih)
        for (int id = 0; id < MERL_THETA_D_BINS; ++id)
            for (int ip = 0; ip < MERL_PHI_D_BINS; ++ip) {
                float3 wo, wi;
                directions_from_half_diff(merl_bin_center(ih, id, ip), &wo, &wi);
                // Bin centres below the horizon (theta_h + theta_d > 90 degrees) hold 0, as no light arrives there.
                float3 v = (wo.z > 0.0f && wi.z > 0.0f) ? f(wo, wi) : float3(0.0f);
                const std::size_t e = std::size_t(merl_entry_index(ih, id, ip));
                for (int c = 0; c < 3; ++c) {
                    if (!(v[c] >= 0.0f) || !std::isfinite(v[c]))
                        throw std::runtime_error(source + ": tabulated BRDF is " + std::to_string(v[c]) + " at " + entry_name(c, int(e)));
                    table.rgb[3 * e + c] = v[c];
                }
            }
    return table;
}

}  // namespace brdf
