// dtoadq: the lab's command line. Every job runs headless from here.
#include <cstdio>
#include <exception>
#include <string>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "common/input_error.hpp"

int main(int argc, char** argv) {
    CLI::App app{"DTOADQ lab: BRDF prototyping and image-based lighting"};
    app.require_subcommand(1);
    // CLI11's own errors in the lab's one-line form
    app.failure_message([](const CLI::App*, const CLI::Error& e) {
        return std::string("dtoadq: error: command line: ") + e.what() + " (see --help)\n";
    });
    lab::cli::register_report(app);
    lab::cli::register_lobe(app);
    lab::cli::register_albedo(app);
    lab::cli::register_brdf(app);
    lab::cli::register_validate(app);
    lab::cli::register_bench(app);
    lab::cli::register_devices(app);
    lab::cli::register_preview(app);
    lab::cli::register_render(app);
    lab::cli::register_merge(app);
    lab::cli::register_view(app);
    lab::cli::register_fit(app);
    lab::cli::register_convert(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::RuntimeError& e) {
        return e.get_exit_code();  // a job's own failure (validate, report: a physical check failed)
    } catch (const CLI::ParseError& e) {
        // --help is not an error; every command-line mistake is an input error: exit 2, as documented
        return app.exit(e) == 0 ? 0 : 2;
    } catch (const lab::InputError& e) {
        std::fprintf(stderr, "dtoadq: error: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "dtoadq: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
