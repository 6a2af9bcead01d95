#include "plots/preview_sheet.hpp"

#include <stdexcept>

#include "common/child_process.hpp"
#include "common/input_error.hpp"
#include "plots/output_file.hpp"
#include "plots/python_runner.hpp"

namespace lab::plots {

namespace fs = std::filesystem;

void write_preview_sheet(const std::vector<SheetImage>& images, const std::string& title, const std::string& png_path) {
    if (images.empty()) throw std::invalid_argument("preview sheet: no images");
    require_writable(png_path, "");
    TempFolder folder("plot");
    const fs::path list = folder.path() / "images.csv";
    {
        std::ofstream out = open_output(list.string(), "");
        out << "title,path\n";
        for (const SheetImage& image : images) out << csv_field(image.title) << ',' << csv_field(fs::absolute(image.png_path).string()) << '\n';
        if (!out.flush()) throw InputError(list.string(), "", "write failed");
    }
    const fs::path png = folder.path() / "sheet.png";
    run_plot_script("preview_sheet.py", {"--data", list.string(), "--out", png.string(), "--title=" + title}, folder.path());
    install_output(png, png_path, "");
}

}  // namespace lab::plots
