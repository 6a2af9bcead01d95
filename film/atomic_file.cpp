#include "film/atomic_file.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common/input_error.hpp"

namespace lab::film {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const std::string& path, int error) {
    throw InputError(path, "", std::string("cannot write: ") + std::strerror(error));
}

// Writes everything, through partial writes and interruptions; returns 0 or the errno.
int write_all(int fd, const char* data, size_t size) {
    while (size > 0) {
        ssize_t n = ::write(fd, data, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        data += n;
        size -= size_t(n);
    }
    return 0;
}

}  // namespace

void write_file_atomically(const std::string& path, const void* data, size_t size) {
    const fs::path target(path);
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    // a dot file, so a folder listing during the write does not show it as a result
    const std::string stem = "." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-";
    static std::atomic<unsigned> counter{0};

    std::string temporary;
    int fd = -1;
    for (int attempt = 0; fd < 0; ++attempt) {
        temporary = (folder / (stem + std::to_string(counter++))).string();
        fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && (errno != EEXIST || attempt >= 100)) fail(path, errno);
    }
    struct stat existing;
    if (::stat(path.c_str(), &existing) == 0 && S_ISREG(existing.st_mode)) ::fchmod(fd, existing.st_mode & 07777);

    int error = write_all(fd, static_cast<const char*>(data), size);
    if (error == 0 && ::fsync(fd) != 0) error = errno;  // the data is on disk before the name points at it
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error == 0 && ::rename(temporary.c_str(), path.c_str()) != 0) error = errno;
    if (error != 0) {
        ::unlink(temporary.c_str());
        fail(path, error);
    }
}

}  // namespace lab::film
