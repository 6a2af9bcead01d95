// The report's page: one self-contained HTML file (its style inline, no script, images linked from
// its folder) of sections, each a list of figures. A figure is a picture, or a table alone, with a
// caption that says what it shows and how it was measured, and its numbers in a table beside it;
// the same numbers go to a CSV file for scripts. `dtoadq report` writes it as index.html.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace lab::report {

// A table cell: its text, and how it is shown: a number (right-aligned), a verdict (coloured).
enum class CellKind { text, number, pass, fail };

struct Cell {
    std::string text;
    CellKind kind = CellKind::text;
};

struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<Cell>> rows;  // each as long as the header
    std::string csv;                      // the CSV file with the same numbers, relative to the page; empty: none
};

struct Figure {
    std::string image;    // a PNG relative to the page; empty for a table alone
    std::string alt;      // the picture in a few words, for a reader without it
    std::string caption;  // what the figure shows and how it was measured
    Table numbers;
};

struct Section {
    std::string id;       // the anchor of its entry in the page's contents
    std::string title;
    std::string summary;  // a paragraph before the figures; may be empty
    std::vector<Figure> figures;
};

struct Page {
    std::string title;
    std::string subtitle;
    std::vector<Section> sections;
};

// Text with &, <, >, " and ' escaped, for an element's content or an attribute's value.
std::string html_escape(std::string_view text);

// The page as HTML5. Throws std::invalid_argument for a table row whose length is not the header's,
// or a section id that is empty, repeated or not a plain name (letters, digits, '-', '_').
std::string page_html(const Page& page);

// Writes page_html() to `path`, or throws lab::InputError naming it.
void write_page(const Page& page, const std::string& path);

// Writes the table as CSV (the header, then the rows' text), or throws lab::InputError naming `path`.
void write_csv(const Table& table, const std::string& path);

// A number for a table: `digits` significant digits, without trailing noise ("0.941", "1.2e+07").
std::string number_text(double value, int digits = 4);
// A fraction as a percentage with `digits` significant digits: "12.5 %".
std::string percent_text(double fraction, int digits);

// Table cells: a number of `digits` significant digits (right-aligned), and text.
Cell number_cell(double value, int digits = 4);
Cell text_cell(std::string text);

}  // namespace lab::report
