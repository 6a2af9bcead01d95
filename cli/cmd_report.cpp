// PLACEHOLDER: replaced by the report subcommand implementation.
#include "cli/commands.hpp"
namespace lab::cli {
void register_report(CLI::App&) {}
}
