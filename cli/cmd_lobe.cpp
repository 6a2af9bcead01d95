// PLACEHOLDER: replaced by the lobe subcommand implementation.
#include "cli/commands.hpp"
namespace lab::cli {
void register_lobe(CLI::App&) {}
}
