// SPDX-License-Identifier: MIT
// The report's data: the sit-to-stand road-map with its free-body diagrams, histories, motion.
#include "alembert/report/report.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "alembert/eom/planner.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"

namespace alembert {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

// the JSON of the road-map row for `variable`, up to the next row
std::string row_of(const std::string& json, const std::string& variable) {
    std::size_t begin = json.find("{\"variable\":\"" + variable + "\"");
    EXPECT_NE(begin, std::string::npos) << variable;
    std::size_t end = json.find("{\"variable\":\"", begin + 1);
    if (end == std::string::npos) end = json.find("\"histories\":", begin);
    return json.substr(begin, end - begin);
}

struct SitToStand {
    SampleModel m = make_triple_pendulum();
    ReportContent content;
    SitToStand() {
        content.system = &m.system;
        content.title = "sit_to_stand";
        content.rows = plan_roadmap(m.system, m.q, m.unknowns);
        content.coordinates = m.q;
        content.configuration[m.q[0].symbol()] = 0.35;
        content.configuration[m.q[1].symbol()] = -1.2;
        content.configuration[m.q[2].symbol()] = 1.0;
        content.units["T_A"] = "N*m";
    }
};

TEST(Report, EachRowsFreeBodyDiagramHoldsTheLoadsExternalToItsSystem) {
    SitToStand s;
    const std::string json = render_report_json(s.content);
    // S = {A, B, C} about A_o: T_A, gravity at three mass centres, the ground's force at A_o
    const std::string a = row_of(json, "T_A");
    EXPECT_NE(a.find("\"system\":[\"A\",\"B\",\"C\"],\"about\":\"A_o\""), std::string::npos) << a;
    EXPECT_EQ(count(a, "\"kind\":\"gravity\""), 3u);
    EXPECT_EQ(count(a, "\"kind\":\"torque\""), 1u);
    EXPECT_EQ(count(a, "\"kind\":\"joint\",\"label\":\"from N\",\"at\":\"A_o\""), 1u);
    EXPECT_EQ(count(a, "\"kind\":"), 5u);
    // S = {B, C} about B_o: T_B, gravity at Bcm and Ccm, the force from A at B_o
    const std::string b = row_of(json, "T_B");
    EXPECT_NE(b.find("\"about\":\"B_o\""), std::string::npos);
    EXPECT_EQ(count(b, "\"kind\":\"gravity\""), 2u);
    EXPECT_EQ(count(b, "\"kind\":\"joint\",\"label\":\"from A\",\"at\":\"B_o\""), 1u);
    EXPECT_EQ(count(b, "\"kind\":"), 4u);
    // S = {C} about C_o
    const std::string c = row_of(json, "T_C");
    EXPECT_NE(c.find("\"system\":[\"C\"],\"about\":\"C_o\""), std::string::npos);
    EXPECT_EQ(count(c, "\"kind\":"), 3u);
    // the torque on S is unknown, drawn at the joint, positive about +Nz
    EXPECT_NE(c.find("{\"kind\":\"torque\",\"label\":\"T_C\",\"at\":\"C_o\",\"vector\":[0,0,1],"
                     "\"unknown\":true}"),
              std::string::npos)
        << c;
    // the direction u = Nz, and the equation as TeX with the torque in it
    EXPECT_NE(c.find("\"direction\":[0,0,1]"), std::string::npos);
    // the row's unknown leads its equation
    EXPECT_NE(c.find("\"equation\":\"\\\\begin{aligned} 0 ={} \\u0026 T_{C}"), std::string::npos)
        << c;
    EXPECT_NE(c.find("\\\\begin{aligned}"), std::string::npos);
}

TEST(Report, PointsArePlacedAtTheConfiguration) {
    SitToStand s;
    s.content.configuration.clear();  // every angle 0: the chain stands straight up Ny
    const std::string json = render_report_json(s.content);
    // C_o at L_A + L_B up Ny (Winter's table: 0.4182 + 0.4165 = 0.8347 m, printed to 6 digits)
    EXPECT_NE(json.find("{\"name\":\"C_o\",\"at\":[0,0.8347,0]}"), std::string::npos);
    EXPECT_NE(json.find("\"planar\":true"), std::string::npos);
    // segments belong to the body whose frame their vector is fixed in: A_o to B_o is the shank
    EXPECT_NE(json.find("{\"body\":\"A\",\"from\":\"A_o\",\"to\":\"B_o\"}"), std::string::npos);
}

TEST(Report, HistoriesArePlottedAndTheirMotionAnimated) {
    SitToStand s;
    ReportHistory h;
    h.title = "inverse dynamics";
    h.table.add_column("t", "s");
    h.table.add_column("T_A", "N*m");
    h.table.columns[0] = {0, 0.5, 1};
    h.table.columns[1] = {1, 2, 3};
    h.coordinates = s.m.q;
    h.motion = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    s.content.histories.push_back(h);
    const std::string json = render_report_json(s.content);
    EXPECT_NE(json.find("\"title\":\"inverse "
                        "dynamics\",\"rows\":3,\"time\":[0,0.5,1],\"time_unit\":\"s\",\"series\":[{"
                        "\"name\":\"T_A\",\"unit\":\"N*m\","
                        "\"values\":[1,2,3]}]"),
              std::string::npos);
    std::size_t anim = json.find("\"animation\":{\"source\":\"inverse dynamics\"");
    ASSERT_NE(anim, std::string::npos);
    EXPECT_NE(json.find("\"time\":[0,0.5,1],\"frames\":[[", anim), std::string::npos);
}

TEST(Report, LongHistoriesAreThinnedForPlottingKeepingTheEnds) {
    SitToStand s;
    ReportHistory h;
    h.title = "simulation";
    h.table.add_column("t", "s");
    h.table.add_column("x", "m");
    for (int k = 0; k <= 100000; ++k) {
        h.table.columns[0].push_back(k * 1e-3);
        h.table.columns[1].push_back(k);
    }
    s.content.histories.push_back(h);
    const std::string json = render_report_json(s.content);
    std::size_t at = json.find("\"title\":\"simulation\",\"rows\":100001,\"time\":[0,0.051,0.102,");
    ASSERT_NE(at, std::string::npos);
    const std::size_t begin = json.find('[', at), end = json.find(']', at);
    // every 51st of 100001 rows is 1961 samples, and the last row: 1962 values
    EXPECT_EQ(count(json.substr(begin, end - begin), ",") + 1, 1962u);
    EXPECT_NE(json.find(",100]", at), std::string::npos);
}

TEST(Report, SameContentGivesTheSameBytes) {
    SitToStand s1, s2;
    EXPECT_EQ(render_report_html(s1.content, ""), render_report_html(s2.content, ""));
}

TEST(Report, PageHoldsTheDataAndTheViewerAndNoClosingScriptInsideTheData) {
    SitToStand s;
    s.content.title = "a</script>b";
    const std::string page = render_report_html(s.content, "");
    EXPECT_NE(page.find("<script type=\"application/json\" id=\"alembert-data\">{\"format\":1"),
              std::string::npos);
    EXPECT_NE(page.find("Alembert's report viewer"), std::string::npos);
    EXPECT_EQ(count(page, "</script>"), 2u);  // the data's and the viewer's
    EXPECT_NE(page.find("<title>a&lt;/script&gt;b - Alembert report</title>"), std::string::npos);
}

TEST(Report, WritesIndexHtmlWithoutLeavingTemporaries) {
    SitToStand s;
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "alembert_report_test";
    fs::remove_all(dir);
    const std::string index = write_report(s.content, (dir / "out").string());
    EXPECT_EQ(index, (dir / "out" / "index.html").string());
    std::ifstream in(index);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_NE(text.str().find("alembert-data"), std::string::npos);
    // with Debian's libjs-katex, KaTeX is inlined and its fonts copied beside the page
    if (std::filesystem::exists(default_katex_dir() + "/katex.min.js")) {
        EXPECT_NE(text.str().find("KaTeX parse error"), std::string::npos);
        EXPECT_TRUE(fs::exists(dir / "out" / "fonts" / "KaTeX_Main-Regular.woff2"));
    }
    for (const auto& e : fs::recursive_directory_iterator(dir))
        EXPECT_NE(e.path().extension(), ".tmp") << e.path();
    fs::remove_all(dir);
}

TEST(Report, WithoutKatexThePageStillWorksAndSaysHowToGetIt) {
    SitToStand s;
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "alembert_report_nokatex";
    fs::remove_all(dir);
    ::setenv("ALEMBERT_KATEX_DIR", (dir / "no-katex-here").c_str(), 1);
    const std::string index = write_report(s.content, dir.string());
    ::unsetenv("ALEMBERT_KATEX_DIR");
    std::ifstream in(index);
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_EQ(text.str().find(".katex{"), std::string::npos);            // no KaTeX style
    EXPECT_EQ(text.str().find("KaTeX parse error"), std::string::npos);  // no KaTeX script
    EXPECT_FALSE(fs::exists(dir / "fonts"));
    EXPECT_NE(text.str().find("install Debian's libjs-katex"),
              std::string::npos);  // the viewer's note
    fs::remove_all(dir);
}

TEST(Report, ErrorsNameTheProblemAndTheFix) {
    ReportContent none;
    try {
        (void)render_report_json(none);
        FAIL() << "expected ArgumentError";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("no model"), std::string::npos);
    }
    SitToStand s;
    namespace fs = std::filesystem;
    const fs::path file = fs::temp_directory_path() / "alembert_report_file";
    std::ofstream(file) << "x";
    try {
        (void)write_report(s.content, (file / "sub").string());
        FAIL() << "expected ArgumentError";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("cannot create the directory"), std::string::npos)
            << e.what();
    }
    fs::remove(file);
}

}  // namespace
}  // namespace alembert

namespace alembert {
namespace {

TEST(ReportLatex, TheRoadmapTableTheLoadsAndTheEquationsForAPaper) {
    SitToStand s;
    const std::string tex = render_report_latex(s.content);
    EXPECT_NE(tex.find("\\section*{MG road-map of sit\\_to\\_stand}"), std::string::npos)
        << tex.substr(0, 400);
    EXPECT_NE(
        tex.find("$T_{A}$ & rotate & Nz\\textgreater{} & $\\{A, B, C\\}$ & A\\_o & none \\\\"),
        std::string::npos)
        << tex;
    EXPECT_NE(
        tex.find("\\item $S = \\{C\\}$ (for $T_{C}$): T\\_C on C from B (unknown); gravity at Ccm; "
                 "joint force at C\\_o from B (unknown)."),
        std::string::npos);
    EXPECT_EQ(count(tex, "\\[ E_{T_{"), 3u);
    EXPECT_EQ(count(tex, "\\begin{aligned}"), count(tex, "\\end{aligned}"));
    EXPECT_NE(tex.find("\\end{document}"), std::string::npos);
}

}  // namespace
}  // namespace alembert
