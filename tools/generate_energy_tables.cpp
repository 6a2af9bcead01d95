// Writes brdf/energy_table_ggx.h, brdf/energy_table_ggx_anisotropic.h, brdf/energy_table_hyper_cauchy.h,
// brdf/energy_table_dielectric.h (the energy-compensation tables, from the lab model's own single-scattering lobes) and
// brdf/energy_table_openpbr.h (the OpenPBR layers' albedos); --tables openpbr or anisotropic writes that one alone:
//   ./build/tools/generate_energy_tables brdf [--strata N] [--threads N] [--tables all|openpbr|anisotropic]
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "validation/energy_tables.hpp"

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s OUTPUT_DIR [--strata N] [--threads N] [--tables all|openpbr|anisotropic]\n", argv[0]);
        return 2;
    }
    std::string dir = argv[1];
    /* checked before minutes of quadrature, not after */
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) {
        std::fprintf(stderr, "%s: error: %s: OUTPUT_DIR is not a folder\n", argv[0], dir.c_str());
        return 2;
    }
    int strata = lab::validation::kEnergyTableStrata, threads = 2;
    std::string tables = "all";
    for (int k = 2; k + 1 < argc; k += 2) {
        std::string key = argv[k];
        if (key == "--tables" && (std::string(argv[k + 1]) == "all" || std::string(argv[k + 1]) == "openpbr" ||
                                  std::string(argv[k + 1]) == "anisotropic")) {
            tables = argv[k + 1];
            continue;
        }
        int value = std::atoi(argv[k + 1]);
        if (key == "--strata" && value > 0) strata = value;
        else if (key == "--threads" && value > 0) threads = value;
        else {
            std::fprintf(stderr, "%s: error: %s: expected --strata N, --threads N (N > 0) or --tables all|openpbr|anisotropic\n", argv[0], key.c_str());
            return 2;
        }
    }
    std::vector<std::pair<std::string, std::string>> files;
    if (tables == "all") {
        lab::validation::EnergyTables tables = lab::validation::compute_energy_tables(strata, threads);
        files = {{"energy_table_ggx.h", lab::validation::ggx_table_header(tables, strata)},
                 {"energy_table_hyper_cauchy.h", lab::validation::hyper_cauchy_table_header(tables, strata)},
                 {"energy_table_dielectric.h", lab::validation::dielectric_table_header(tables, strata)}};
    }
    if (tables == "all" || tables == "anisotropic")
        files.push_back({"energy_table_ggx_anisotropic.h",
                         lab::validation::anisotropic_table_header(lab::validation::compute_anisotropic_tables(strata, threads), strata)});
    if (tables == "all" || tables == "openpbr")
        files.push_back({"energy_table_openpbr.h",
                         lab::validation::openpbr_table_header(lab::validation::compute_openpbr_tables(strata, threads), strata)});
    for (const auto& [name, text] : files) {
        std::ofstream out(dir + "/" + name);
        if (!out) {
            std::fprintf(stderr, "%s: error: %s/%s: cannot write\n", argv[0], dir.c_str(), name.c_str());
            return 1;
        }
        out << text;
    }
    return 0;
}
