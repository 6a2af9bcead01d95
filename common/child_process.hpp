// Running another program the lab drives (the plotting Python, FFmpeg) and waiting for it, its
// output kept in a log file; and a private temporary folder for what it reads and writes.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lab {

// Runs argv (looked up on PATH when it has no slash) with standard input from /dev/null and both
// output streams sent to `log`, in this process's environment with `set_env` ("NAME=VALUE" each)
// put in place of any variable of that name. Returns the exit status, or -1 when it could not be
// started or was killed.
int run_process(const std::vector<std::string>& argv, const std::string& log, const std::vector<std::string>& set_env = {});

// The last line of a file that is not blank (a failed program's log: usually its error).
std::string last_line(const std::filesystem::path& file);

// A private temporary folder (dtoadq-PURPOSE-XXXXXX), removed with everything in it when this goes
// out of scope. Throws std::runtime_error when it cannot be made.
class TempFolder {
public:
    explicit TempFolder(const std::string& purpose);
    ~TempFolder();
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

}  // namespace lab
