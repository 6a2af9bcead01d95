// PLACEHOLDER: replaced by the bench subcommand implementation.
#include "cli/commands.hpp"
namespace lab::cli {
void register_bench(CLI::App&) {}
}
