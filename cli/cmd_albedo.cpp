// PLACEHOLDER: replaced by the albedo subcommand implementation.
#include "cli/commands.hpp"
namespace lab::cli {
void register_albedo(CLI::App&) {}
}
