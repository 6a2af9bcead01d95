// The layer order of docs/architecture.md ("## Layers"), checked against the source tree: every
// `#include "..."` of a folder names a file of its own folder or of a lower layer. The table is read
// from the document, so the rule is written once. Runs from the repository root (ctest's working
// directory for the tests).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const char* const kArchitecture = "docs/architecture.md";

// The quoted name of a line `#include "NAME"`, "" for any other line.
std::string included_name(const std::string& line) {
    size_t i = line.find_first_not_of(" \t");
    if (i == std::string::npos || line[i] != '#') return "";
    i = line.find_first_not_of(" \t", i + 1);
    if (i == std::string::npos || line.compare(i, 7, "include") != 0) return "";
    i = line.find_first_not_of(" \t", i + 7);
    if (i == std::string::npos || line[i] != '"') return "";
    const size_t close = line.find('"', i + 1);
    return close == std::string::npos ? "" : line.substr(i + 1, close - i - 1);
}

// Folder ("kernels/host") -> layer, from the "## Layers" table's rows "| N | `a/`, `b/` | ... |".
std::map<std::string, int> read_layers() {
    std::ifstream in(kArchitecture);
    REQUIRE(in);
    std::map<std::string, int> layers;
    bool in_section = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("## ", 0) == 0) in_section = line == "## Layers";
        if (!in_section || line.rfind("|", 0) != 0) continue;
        const size_t second = line.find('|', 1), third = second == std::string::npos ? second : line.find('|', second + 1);
        if (third == std::string::npos) continue;
        const std::string number = line.substr(1, second - 1);
        const size_t digits = number.find_first_of("0123456789");
        if (digits == std::string::npos || number.find_first_not_of(" \t0123456789") != std::string::npos) continue;
        const int layer = std::stoi(number.substr(digits));
        // the cell's folders: `a/` between backticks
        const std::string cell = line.substr(second + 1, third - second - 1);
        for (size_t open = cell.find('`'); open != std::string::npos;) {
            const size_t close = cell.find('`', open + 1);
            if (close == std::string::npos) break;
            const std::string quoted = cell.substr(open + 1, close - open - 1);
            if (quoted.size() > 1 && quoted.back() == '/') {
                layers[quoted.substr(0, quoted.size() - 1)] = layer;
                open = cell.find('`', close + 1);
            } else {
                open = close;
            }
        }
    }
    return layers;
}

bool is_source(const fs::path& path) {
    const std::string ext = path.extension().string();
    return ext == ".h" || ext == ".hpp" || ext == ".cpp" || ext == ".cl" || ext == ".c";
}

// The table's folder a repository-relative path lies in: the longest one that holds it, "" for none.
std::string folder_of(const std::string& path, const std::map<std::string, int>& layers) {
    std::string best;
    for (const auto& [folder, layer] : layers)
        if (path.rfind(folder + "/", 0) == 0 && folder.size() > best.size()) best = folder;
    return best;
}

// Where the kernel-source assembler and the compilers look: beside the including file, then from
// the repository root. "" for a name that is no file of the tree (a virtual or a test's file).
std::string resolve(const std::string& name, const fs::path& includer) {
    const fs::path beside = (includer.parent_path() / name).lexically_normal();
    if (fs::is_regular_file(beside)) return beside.generic_string();
    const fs::path from_root = fs::path(name).lexically_normal();
    if (fs::is_regular_file(from_root)) return from_root.generic_string();
    return {};
}

// Top-level folders that hold source files, build trees and hidden folders left out.
std::vector<std::string> source_folders() {
    std::vector<std::string> found;
    for (const fs::directory_entry& top : fs::directory_iterator(".")) {
        const std::string name = top.path().filename().string();
        if (!top.is_directory() || name.empty() || name[0] == '.' || fs::exists(top.path() / "CMakeCache.txt")) continue;
        for (const fs::directory_entry& e : fs::recursive_directory_iterator(top.path()))
            if (e.is_regular_file() && is_source(e.path())) {
                found.push_back(name);
                break;
            }
    }
    return found;
}

}  // namespace

TEST_CASE("every include points to its own folder or a lower layer of docs/architecture.md", "[layers]") {
    const std::map<std::string, int> layers = read_layers();
    REQUIRE(layers.size() >= 10);  // the table was found and read

    int includes = 0;
    for (const std::string& top : source_folders()) {
        {
            INFO("folder " << top << "/ holds source files; give it a layer in " << kArchitecture);
            CHECK(layers.count(top) == 1);
        }
        for (const fs::directory_entry& e : fs::recursive_directory_iterator(top)) {
            if (!e.is_regular_file() || !is_source(e.path())) continue;
            const fs::path file = e.path().lexically_normal();
            const std::string from = folder_of(file.generic_string(), layers);
            if (from.empty()) continue;
            std::ifstream in(file);
            int number = 0;
            for (std::string line; std::getline(in, line);) {
                ++number;
                const std::string name = included_name(line);
                if (name.empty()) continue;
                const std::string target = resolve(name, file);
                if (target.empty()) continue;
                const std::string to = folder_of(target, layers);
                ++includes;
                if (to == from) continue;
                INFO(file.generic_string() << ":" << number << " (" << from << "/, layer " << layers.at(from) << ") includes "
                                           << target << " (" << (to.empty() ? "no layer" : to + "/, layer " + std::to_string(layers.at(to)))
                                           << ")");
                CHECK((!to.empty() && layers.at(to) < layers.at(from)));
            }
        }
    }
    CHECK(includes > 500);  // the tree was read from its root
}
