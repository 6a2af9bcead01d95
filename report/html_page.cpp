#include "report/html_page.hpp"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "common/input_error.hpp"
#include "plots/output_file.hpp"

namespace lab::report {

namespace {

// Inline so that the page is one file; plain CSS 2 with no web fonts, so it renders offline.
constexpr const char* kStyle = R"(body { font-family: sans-serif; max-width: 72em; margin: 1em auto; padding: 0 1em; color: #222; }
h1 { margin-bottom: 0.2em; } .subtitle { color: #555; margin-top: 0; }
nav ol { columns: 2; } section { border-top: 1px solid #ccc; margin-top: 2em; }
figure { display: flex; flex-wrap: wrap; gap: 1.5em; align-items: flex-start; margin: 1.5em 0; }
figure img { max-width: 36em; height: auto; border: 1px solid #ddd; }
figcaption { flex-basis: 100%; font-size: 0.95em; color: #333; }
table { border-collapse: collapse; font-size: 0.9em; } th, td { border: 1px solid #ccc; padding: 0.2em 0.5em; }
th { background: #f0f0f0; } td.number { text-align: right; font-variant-numeric: tabular-nums; }
td.pass { background: #d8f0d8; color: #145214; font-weight: bold; } td.fail { background: #f6d4d4; color: #7a1010; font-weight: bold; }
.csv { font-size: 0.85em; })";

bool plain_name(const std::string& id) {
    if (id.empty()) return false;
    for (char c : id)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') return false;
    return true;
}

const char* cell_class(CellKind kind) {
    switch (kind) {
        case CellKind::number: return " class=\"number\"";
        case CellKind::pass: return " class=\"pass\"";
        case CellKind::fail: return " class=\"fail\"";
        case CellKind::text: break;
    }
    return "";
}

void write_table(std::ostringstream& out, const Table& table) {
    out << "<div class=\"numbers\"><table>\n<thead><tr>";
    for (const std::string& h : table.header) out << "<th>" << html_escape(h) << "</th>";
    out << "</tr></thead>\n<tbody>\n";
    for (const std::vector<Cell>& row : table.rows) {
        if (row.size() != table.header.size())
            throw std::invalid_argument("report page: a table row of " + std::to_string(row.size()) + " cells under a header of " +
                                        std::to_string(table.header.size()));
        out << "<tr>";
        for (const Cell& c : row) out << "<td" << cell_class(c.kind) << ">" << html_escape(c.text) << "</td>";
        out << "</tr>\n";
    }
    out << "</tbody></table>\n";
    if (!table.csv.empty()) out << "<p class=\"csv\">The same numbers: <a href=\"" << html_escape(table.csv) << "\">" << html_escape(table.csv) << "</a></p>\n";
    out << "</div>\n";
}

}  // namespace

std::string html_escape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string page_html(const Page& page) {
    std::set<std::string> ids;
    for (const Section& s : page.sections) {
        if (!plain_name(s.id)) throw std::invalid_argument("report page: section id '" + s.id + "' is not a plain name");
        if (!ids.insert(s.id).second) throw std::invalid_argument("report page: section id '" + s.id + "' is used twice");
    }
    std::ostringstream out;
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << html_escape(page.title) << "</title>\n<style>\n"
        << kStyle << "\n</style>\n</head>\n<body>\n<h1>" << html_escape(page.title) << "</h1>\n";
    if (!page.subtitle.empty()) out << "<p class=\"subtitle\">" << html_escape(page.subtitle) << "</p>\n";
    out << "<nav><ol>\n";
    for (const Section& s : page.sections) out << "<li><a href=\"#" << s.id << "\">" << html_escape(s.title) << "</a></li>\n";
    out << "</ol></nav>\n";
    for (const Section& s : page.sections) {
        out << "<section id=\"" << s.id << "\">\n<h2>" << html_escape(s.title) << "</h2>\n";
        if (!s.summary.empty()) out << "<p>" << html_escape(s.summary) << "</p>\n";
        for (const Figure& f : s.figures) {
            out << "<figure>\n";
            if (!f.image.empty())
                out << "<a href=\"" << html_escape(f.image) << "\"><img src=\"" << html_escape(f.image) << "\" alt=\"" << html_escape(f.alt)
                    << "\"></a>\n";
            write_table(out, f.numbers);
            out << "<figcaption>" << html_escape(f.caption) << "</figcaption>\n</figure>\n";
        }
        out << "</section>\n";
    }
    out << "</body>\n</html>\n";
    return out.str();
}

void write_page(const Page& page, const std::string& path) {
    const std::string html = page_html(page);
    std::ofstream out = plots::open_output(path, "-o");
    out << html;
    if (!out.flush()) throw InputError(path, "-o", "write failed");
}

void write_csv(const Table& table, const std::string& path) {
    std::ofstream out = plots::open_output(path, "-o");
    for (size_t i = 0; i < table.header.size(); ++i) out << (i ? "," : "") << plots::csv_field(table.header[i]);
    out << "\n";
    for (const std::vector<Cell>& row : table.rows) {
        for (size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << plots::csv_field(row[i].text);
        out << "\n";
    }
    if (!out.flush()) throw InputError(path, "-o", "write failed");
}

Cell number_cell(double value, int digits) { return {number_text(value, digits), CellKind::number}; }
Cell text_cell(std::string text) { return {std::move(text), CellKind::text}; }

std::string number_text(double value, int digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

std::string percent_text(double fraction, int digits) { return number_text(100.0 * fraction, digits) + " %"; }

}  // namespace lab::report
