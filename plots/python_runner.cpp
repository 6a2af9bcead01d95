#include "plots/python_runner.hpp"

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string_view>

#include "common/child_process.hpp"
#include "common/input_error.hpp"
#include "plots/output_file.hpp"

namespace lab::plots {

// defined by the source embed_files() generates from plots/*.py (see plots/CMakeLists.txt)
namespace embedded {
std::string_view embedded_file(std::string_view path);
const std::vector<std::string_view>& embedded_paths();
}  // namespace embedded

namespace fs = std::filesystem;

std::vector<std::string> python_candidates() {
    std::vector<std::string> c;
    const char* env = std::getenv("DTOADQ_PYTHON");
    if (env && *env) c.push_back(env);
    c.push_back("/usr/bin/python3");
    c.push_back("python3");
    return c;
}

std::string find_matplotlib_python(const std::vector<std::string>& candidates) {
    for (const std::string& python : candidates)
        if (run_process({python, "-c", "import matplotlib, numpy"}, "/dev/null") == 0) return python;
    std::string tried;
    for (const std::string& python : candidates) tried += (tried.empty() ? "" : ", ") + python;
    throw std::runtime_error("matplotlib not found: install python3-matplotlib (or set DTOADQ_PYTHON); tried " + tried);
}

void run_plot_script(const std::string& script, const std::vector<std::string>& args, const fs::path& folder) {
    // looked up once per process: each probe starts an interpreter
    static const std::string python = find_matplotlib_python(python_candidates());
    for (std::string_view name : embedded::embedded_paths()) {
        std::ofstream out(folder / std::string(name), std::ios::binary);
        std::string_view text = embedded::embedded_file(name);
        out.write(text.data(), std::streamsize(text.size()));
        if (!out) throw std::runtime_error("cannot write " + (folder / std::string(name)).string());
    }
    if (embedded::embedded_file(script).empty()) throw std::logic_error("no embedded plot script " + script);
    std::vector<std::string> argv = {python, (folder / script).string()};
    argv.insert(argv.end(), args.begin(), args.end());
    fs::path log = folder / (script + ".log");
    int status = run_process(argv, log.string(), {"MPLBACKEND=Agg"});  // never try to open a window
    if (status != 0)
        throw std::runtime_error(script + " (" + python + ") failed with status " + std::to_string(status) + ": " + last_line(log));
}

void draw_chart(const std::string& script, const std::string& header, const std::function<void(std::ostream&)>& write_rows,
                const std::vector<std::string>& args, const std::string& png_path, const std::string& csv_path) {
    require_writable(png_path, "");
    if (!csv_path.empty()) require_writable(csv_path, "");
    TempFolder folder("plot");
    const std::filesystem::path csv = folder.path() / "chart.csv";
    const std::filesystem::path png = folder.path() / "chart.png";
    {
        std::ofstream out = open_output(csv.string(), "");
        out << header << "\n";
        write_rows(out);
        if (!out.flush()) throw InputError(csv.string(), "", "write failed");
    }
    std::vector<std::string> arguments = {"--data", csv.string(), "--out", png.string()};
    arguments.insert(arguments.end(), args.begin(), args.end());
    run_plot_script(script, arguments, folder.path());
    if (!csv_path.empty()) install_output(csv, csv_path, "");
    install_output(png, png_path, "");
}

}  // namespace lab::plots
