// Each subcommand registers itself on the application; one file per subcommand (`bench`'s in bench/).
#pragma once

#include <CLI/CLI.hpp>

namespace lab::cli {

void register_lobe(CLI::App& app);
void register_albedo(CLI::App& app);
void register_brdf(CLI::App& app);
void register_validate(CLI::App& app);
void register_bench(CLI::App& app);
void register_report(CLI::App& app);
void register_devices(CLI::App& app);
void register_preview(CLI::App& app);
void register_render(CLI::App& app);
void register_merge(CLI::App& app);
void register_view(CLI::App& app);
void register_fit(CLI::App& app);
void register_convert(CLI::App& app);
// `bench preview`, registered under the bench group by register_bench
void register_bench_preview(CLI::App& bench);
// `bench render`, likewise
void register_bench_render(CLI::App& bench);
// `bench objects`, likewise
void register_bench_objects(CLI::App& bench);
// `bench compare`, likewise
void register_bench_compare(CLI::App& bench);
// `bench vectorization`, likewise
void register_bench_vectorization(CLI::App& bench);
// `bench breakdown`, likewise
void register_bench_breakdown(CLI::App& bench);
void register_bench_denoise(CLI::App& bench);

}  // namespace lab::cli
