// Ctrl-C for the long jobs (preview, render, report): the first SIGINT asks the job to stop at the next
// point where it can keep what it has (the end of a sample launch, the end of a preset); the job
// then writes what it has and exits with kInterruptedExitStatus. A second SIGINT stops the
// process at once: every file is written atomically (film/atomic_file.hpp), so none is left
// truncated - only the old file or the complete new one.
#pragma once

namespace lab::render {

// 128 + SIGINT, what a shell reports for a command ended by Ctrl-C.
constexpr int kInterruptedExitStatus = 130;

// While one exists SIGINT is caught; the outermost clears the request when it starts and restores
// the previous handler when it ends. Nests: `report` holds one around the previews' own.
class InterruptScope {
public:
    InterruptScope();
    ~InterruptScope();
    InterruptScope(const InterruptScope&) = delete;
    InterruptScope& operator=(const InterruptScope&) = delete;
};

// Whether Ctrl-C was pressed since the outermost InterruptScope began.
bool interrupt_requested();

}  // namespace lab::render
