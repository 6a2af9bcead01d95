// Runs the embedded matplotlib scripts (plots/*.py) with a Python found at run time, so an
// installed dtoadq needs neither the source tree nor a particular Python.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace lab::plots {

// The interpreters tried, in order: $DTOADQ_PYTHON (when set), /usr/bin/python3, python3 on PATH.
std::vector<std::string> python_candidates();

// The first candidate that can import matplotlib and numpy. Throws std::runtime_error
// "matplotlib not found: install python3-matplotlib ..." when none can.
std::string find_matplotlib_python(const std::vector<std::string>& candidates);

// Writes the embedded scripts into `folder` and runs `script` there with the Agg backend. The
// script's output goes to a log in `folder`; a failure throws with the log's last line.
void run_plot_script(const std::string& script, const std::vector<std::string>& args, const std::filesystem::path& folder);

// A chart drawn from a CSV of its numbers, as most of the plots' scripts take them: checks first
// that `png_path` and `csv_path` (empty: none) can be written, writes `header` and then what
// `write_rows` writes to a CSV in a temporary folder, runs `script` there with `--data CSV --out PNG`
// and `args`, and puts the PNG at `png_path` and the CSV at `csv_path`. Throws lab::InputError
// naming a path that cannot be written, std::runtime_error when the script fails.
void draw_chart(const std::string& script, const std::string& header, const std::function<void(std::ostream&)>& write_rows,
                const std::vector<std::string>& args, const std::string& png_path, const std::string& csv_path);

}  // namespace lab::plots
