// SPDX-License-Identifier: MIT
// The report page: the data as JSON, the fixed viewer and KaTeX, written atomically.
#include "alembert/report/report.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "alembert/cleanup.hpp"
#include "alembert/error.hpp"
#include "report_detail.hpp"

namespace alembert {

namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) return "";
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string html_escape(const std::string& s) {
    std::string o;
    for (char c : s) {
        if (c == '<')
            o += "&lt;";
        else if (c == '>')
            o += "&gt;";
        else if (c == '&')
            o += "&amp;";
        else if (c == '"')
            o += "&quot;";
        else
            o += c;
    }
    return o;
}

}  // namespace

std::string report_history_title(const std::string& statement, int line, const std::string& file) {
    std::string title = statement;
    if (line > 0) title += " at line " + std::to_string(line);
    if (!file.empty()) title += " (" + file + ")";
    return title;
}

std::string default_katex_dir() {
    if (const char* env = std::getenv("ALEMBERT_KATEX_DIR"); env && *env) return env;
    return ALEMBERT_KATEX_DIR;
}

std::string default_three_dir() {
    if (const char* env = std::getenv("ALEMBERT_THREE_DIR"); env && *env) return env;
    return ALEMBERT_THREE_DIR;
}

std::string render_report_html(const ReportContent& content, const std::string& katex_dir,
                               const std::string& three_dir) {
    return report_detail::render_html(content, report_detail::typeset_equations(content),
                                      katex_dir, three_dir);
}

std::string report_detail::render_html(const ReportContent& content,
                                       const std::vector<std::string>& equations,
                                       const std::string& katex_dir,
                                       const std::string& three_dir,
                                       const std::vector<RowSteps>* steps,
                                       const BruteForceCount* count) {
    const std::string json = render_json(content, equations, steps, count);
    const fs::path katex(katex_dir);
    const std::string katex_js = katex_dir.empty() ? "" : read_text(katex / "katex.min.js");
    const std::string katex_css = katex_dir.empty() ? "" : read_text(katex / "katex.min.css");
    // three.js only where there is a 3D view: a motion, or a spatial model
    const bool view3d = json.find("\"animation\":null") == std::string::npos ||
                        json.find("\"planar\":false") != std::string::npos;
    const std::string three_js =
        three_dir.empty() || !view3d ? "" : read_text(fs::path(three_dir) / "three.min.js");
    std::string page;
    page.reserve(json.size() + katex_js.size() + katex_css.size() + three_js.size() + 64000);
    page += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    page += "<meta name=\"generator\" content=\"Alembert\">\n";
    page += "<title>" + html_escape(content.title) + "</title>\n";  // the model's name
    if (!katex_css.empty()) page += "<style>\n" + katex_css + "\n</style>\n";
    page += "<style>\n" + std::string(report_detail::kViewerStyle) + "</style>\n";
    if (!katex_js.empty()) page += "<script>\n" + katex_js + "\n</script>\n";
    if (!three_js.empty()) page += "<script>\n" + three_js + "\n</script>\n";
    page += "</head>\n<body>\n";
    page += "<div id=\"alembert-status\" data-status=\"loading\">loading the report...</div>\n";
    page += "<pre id=\"alembert-errors\"></pre>\n<main id=\"report\"></main>\n";
    page += "<script type=\"application/json\" id=\"alembert-data\">" + json + "</script>\n";
    page += "<script>\n" + std::string(report_detail::kViewerScript) + "</script>\n";
    page += "</body>\n</html>\n";
    return page;
}

namespace {

fs::path report_directory(const std::string& dir, const char* caller) {
    const fs::path out(dir);
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec || !fs::is_directory(out))
        throw ArgumentError(std::string(caller) + ": cannot create the directory '" + dir + "' (" +
                            (ec ? ec.message() : std::string("a file is in the way")) +
                            "); choose another --out or remove the file");
    return out;
}

}  // namespace

std::string write_report_latex(const ReportContent& content, const std::string& dir) {
    const std::string tex = render_report_latex(content);
    const fs::path path = report_directory(dir, "write_report_latex()") / "roadmap.tex";
    write_file_atomically(path, tex, "write_report_latex()");
    return path.string();
}

std::string write_report(const ReportContent& content, const std::string& dir) {
    const fs::path out(dir);
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec || !fs::is_directory(out))
        throw ArgumentError("write_report(): cannot create the directory '" + dir + "' (" +
                            (ec ? ec.message() : std::string("a file is in the way")) +
                            "); choose another --out or remove the file");
    const std::string katex = default_katex_dir();
    const bool have_katex = fs::is_regular_file(fs::path(katex) / "katex.min.js", ec);
    const std::string three = default_three_dir();
    const bool have_three = fs::is_regular_file(fs::path(three) / "three.min.js", ec);
    // the equations are typeset once, for the page and roadmap.tex
    const std::vector<std::string> equations = report_detail::typeset_equations(content);
    const std::vector<report_detail::RowSteps> steps = report_detail::calc_rows_steps(content, equations);
    const report_detail::BruteForceCount count = report_detail::calc_brute_force_count(content);
    const std::string page = report_detail::render_html(content, equations,
                                                        have_katex ? katex : "",
                                                        have_three ? three : "", &steps, &count);
    // KaTeX's stylesheet names its fonts relative to the page: fonts/KaTeX_*.woff2
    if (have_katex) {
        fs::create_directories(out / "fonts", ec);
        for (const auto& entry : fs::directory_iterator(fs::path(katex) / "fonts", ec)) {
            if (entry.path().extension() != ".woff2") continue;
            write_file_atomically(out / "fonts" / entry.path().filename(), read_text(entry.path()),
                             "write_report()");
        }
    }
    write_file_atomically(out / "roadmap.tex", report_detail::render_latex(content, equations, &steps, &count),
                     "write_report()");
    const fs::path index = out / "index.html";
    write_file_atomically(index, page, "write_report()");
    return index.string();
}

}  // namespace alembert
