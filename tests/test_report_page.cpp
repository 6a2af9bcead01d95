// The report's page writer (report/html_page.hpp): escaping, the structure tools/check_report_page.py
// reads, and the inputs it refuses. The page of a real report is checked end to end, in a browser,
// by the command-line test cli.report.page_opens_in_a_browser.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "report/html_page.hpp"

using lab::report::Cell;
using lab::report::CellKind;

namespace {

lab::report::Page one_figure_page(const std::string& caption, const std::string& cell) {
    lab::report::Page page;
    page.title = "T & <t>";
    lab::report::Section s;
    s.id = "one";
    s.title = "One";
    lab::report::Figure f;
    f.image = "a b.png";
    f.alt = "a \"quoted\" picture";
    f.caption = caption;
    f.numbers.header = {"name", "verdict"};
    f.numbers.rows = {{{cell, CellKind::text}, {"PASS", CellKind::pass}}, {{"x", CellKind::text}, {"FAIL", CellKind::fail}}};
    f.numbers.csv = "one.csv";
    s.figures.push_back(f);
    page.sections.push_back(s);
    return page;
}

}  // namespace

TEST_CASE("Report page: text is escaped wherever it goes", "[report]") {
    CHECK(lab::report::html_escape("a<b>&\"c'") == "a&lt;b&gt;&amp;&quot;c&#39;");
    const std::string html = lab::report::page_html(one_figure_page("<script>alert(1)</script>", "1 < 2 & 3"));
    CHECK(html.find("<script>") == std::string::npos);
    CHECK(html.find("&lt;script&gt;alert(1)&lt;/script&gt;") != std::string::npos);
    CHECK(html.find("<td>1 &lt; 2 &amp; 3</td>") != std::string::npos);
    CHECK(html.find("alt=\"a &quot;quoted&quot; picture\"") != std::string::npos);
    CHECK(html.find("<title>T &amp; &lt;t&gt;</title>") != std::string::npos);
}

TEST_CASE("Report page: figures carry their caption, their table with verdicts, and the link to their CSV", "[report]") {
    const std::string html = lab::report::page_html(one_figure_page("What it shows.", "a"));
    CHECK(html.rfind("<!DOCTYPE html>", 0) == 0);
    CHECK(html.find("<a href=\"#one\">One</a>") != std::string::npos);
    CHECK(html.find("<section id=\"one\">") != std::string::npos);
    CHECK(html.find("<img src=\"a b.png\"") != std::string::npos);
    CHECK(html.find("<figcaption>What it shows.</figcaption>") != std::string::npos);
    CHECK(html.find("<td class=\"pass\">PASS</td>") != std::string::npos);
    CHECK(html.find("<td class=\"fail\">FAIL</td>") != std::string::npos);
    CHECK(html.find("<a href=\"one.csv\">one.csv</a>") != std::string::npos);
}

TEST_CASE("Report page: a row that does not match its header, or a bad section id, is refused", "[report]") {
    lab::report::Page page = one_figure_page("c", "a");
    page.sections[0].figures[0].numbers.rows.push_back({{"only one cell", CellKind::text}});
    CHECK_THROWS_AS(lab::report::page_html(page), std::invalid_argument);
    for (const std::string id : {"", "two words", "quote\"d"}) {
        page = one_figure_page("c", "a");
        page.sections[0].id = id;
        CHECK_THROWS_AS(lab::report::page_html(page), std::invalid_argument);
    }
    page = one_figure_page("c", "a");
    page.sections.push_back(page.sections[0]);
    CHECK_THROWS_AS(lab::report::page_html(page), std::invalid_argument);
}

TEST_CASE("Report page: CSV fields with commas and quotes are quoted", "[report]") {
    lab::report::Table t;
    t.header = {"material", "value"};
    t.rows = {{{"satin, \"silver\"", CellKind::text}, {"0.5", CellKind::number}}};
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "dtoadq_test_report_page.csv";
    lab::report::write_csv(t, path.string());
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    CHECK(text.str() == "material,value\n\"satin, \"\"silver\"\"\",0.5\n");
    std::filesystem::remove(path);
    CHECK(lab::report::number_text(0.94123456) == "0.9412");
    CHECK(lab::report::number_text(12345678.0, 3) == "1.23e+07");
}
