// Test helper: runs a command, and once its output (stdout and stderr, passed through) shows a
// given text, waits a moment and then does ACTION to it: "int" sends SIGINT, as Ctrl-C would;
// "int,S" sends a second SIGINT S seconds after the first; "remove=PATH" deletes the folder PATH
// instead (its output folder vanishing while it renders). Exits with the command's exit status
// (128 + N when signal N ended it), 125 when the text never showed.
//   run_and_interrupt TEXT DELAY_SECONDS ACTION COMMAND [ARGS...]
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

int main(int argc, char** argv) {
    if (argc < 5) {
        std::fprintf(stderr, "usage: run_and_interrupt TEXT DELAY_SECONDS int|int,SECONDS|remove=PATH COMMAND [ARGS...]\n");
        return 2;
    }
    const std::string trigger = argv[1];
    const double delay = std::atof(argv[2]);
    const std::string action = argv[3];
    const bool remove = action.rfind("remove=", 0) == 0;
    const bool twice = action.rfind("int,", 0) == 0;
    const double second_delay = twice ? std::atof(action.c_str() + 4) : 0.0;
    int out[2];
    if (::pipe(out) != 0) return 2;
    const pid_t child = ::fork();
    if (child < 0) return 2;
    if (child == 0) {
        ::signal(SIGINT, SIG_DFL);
        ::dup2(out[1], STDOUT_FILENO);
        ::dup2(out[1], STDERR_FILENO);
        ::close(out[0]);
        ::close(out[1]);
        ::execv(argv[4], argv + 4);
        std::perror(argv[4]);
        ::_exit(127);
    }
    ::close(out[1]);
    std::string seen;
    bool sent = false;
    const auto start = std::chrono::steady_clock::now();
    char buffer[4096];
    while (true) {
        pollfd p{out[0], POLLIN, 0};
        if (::poll(&p, 1, 200) > 0) {
            const ssize_t n = ::read(out[0], buffer, sizeof buffer);
            if (n <= 0) break;
            std::fwrite(buffer, 1, size_t(n), stdout);
            std::fflush(stdout);
            if (!sent) seen.append(buffer, size_t(n));
        }
        if (!sent && seen.find(trigger) != std::string::npos) {
            std::this_thread::sleep_for(std::chrono::duration<double>(delay));
            if (remove) {
                std::error_code ec;
                std::filesystem::remove_all(action.substr(7), ec);
                std::printf("\n[run_and_interrupt: removed %s]\n", action.substr(7).c_str());
            } else {
                std::printf("\n[run_and_interrupt: SIGINT]\n");
                ::kill(child, SIGINT);
            }
            if (twice) {
                std::this_thread::sleep_for(std::chrono::duration<double>(second_delay));
                std::printf("\n[run_and_interrupt: second SIGINT]\n");
                ::kill(child, SIGINT);
            }
            sent = true;
        }
        if (std::chrono::steady_clock::now() - start > std::chrono::seconds(400)) {
            std::printf("\n[run_and_interrupt: no \"%s\" in 400 s: killed]\n", trigger.c_str());
            ::kill(child, SIGKILL);
            break;
        }
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    if (!sent) std::printf("[run_and_interrupt: \"%s\" never appeared]\n", trigger.c_str());
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::printf("[run_and_interrupt: exit status %d]\n", code);
    return sent ? code : 125;
}
