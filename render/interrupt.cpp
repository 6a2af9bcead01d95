#include "render/interrupt.hpp"

#include <unistd.h>

#include <csignal>

namespace lab::render {
namespace {

volatile std::sig_atomic_t g_requests = 0;
int g_depth = 0;
void (*g_previous)(int) = SIG_DFL;

extern "C" void dtoadq_on_sigint(int) {
    if (g_requests > 0) {  // the second Ctrl-C: stop now (only async-signal-safe calls here)
        static const char message[] = "\ndtoadq: interrupted again: stopped; files already written are complete\n";
        (void)!::write(STDERR_FILENO, message, sizeof message - 1);
        ::_exit(kInterruptedExitStatus);
    }
    g_requests = g_requests + 1;
}

}  // namespace

InterruptScope::InterruptScope() {
    if (g_depth++ == 0) {
        g_requests = 0;
        g_previous = std::signal(SIGINT, dtoadq_on_sigint);
    }
}

InterruptScope::~InterruptScope() {
    if (--g_depth == 0) std::signal(SIGINT, g_previous == SIG_ERR ? SIG_DFL : g_previous);
}

bool interrupt_requested() { return g_requests > 0; }

}  // namespace lab::render
