// PLACEHOLDER: replaced by the validate subcommand implementation.
#include "cli/commands.hpp"
namespace lab::cli {
void register_validate(CLI::App&) {}
}
