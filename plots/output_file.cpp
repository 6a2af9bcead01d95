#include "plots/output_file.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <system_error>

#include <unistd.h>

#include "common/input_error.hpp"

namespace lab::plots {

namespace fs = std::filesystem;

void require_writable(const std::string& path, const std::string& field) {
    if (path.empty()) throw InputError("command line", field, "an output path is required");
    fs::path p(path);
    std::error_code ec;
    if (fs::is_directory(p, ec)) throw InputError(path, field, "is a folder, not a file");
    if (fs::exists(p, ec)) {
        if (access(p.c_str(), W_OK) != 0) throw InputError(path, field, std::string("cannot write: ") + std::strerror(errno));
        return;
    }
    fs::path parent = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    if (!fs::is_directory(parent, ec)) throw InputError(path, field, "cannot write: folder " + parent.string() + " does not exist");
    if (access(parent.c_str(), W_OK) != 0) throw InputError(path, field, std::string("cannot write: ") + std::strerror(errno));
}

std::ofstream open_output(const std::string& path, const std::string& field) {
    std::ofstream out(path);
    if (!out) throw InputError(path, field, std::string("cannot write: ") + std::strerror(errno));
    return out;
}

void install_output(const fs::path& from, const std::string& path, const std::string& field) {
    std::error_code ec;
    fs::copy_file(from, path, fs::copy_options::overwrite_existing, ec);
    if (ec) throw InputError(path, field, "cannot write: " + ec.message());
}

std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + "\"";
}

std::string csv_number(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", v);
    return text;
}

}  // namespace lab::plots
