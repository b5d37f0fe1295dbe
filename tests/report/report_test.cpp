// SPDX-License-Identifier: MIT
// The report's data: the sit-to-stand road-map with its free-body diagrams, histories, motion.
#include "alembert/report/report.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "alembert/eom/cross_check.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/error.hpp"
#include "alembert/mech/sample_models.hpp"
#include "alembert/sim/forward_dynamics.hpp"
#include "alembert/sym/print.hpp"

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
    EXPECT_NE(c.find("{\"kind\":\"torque\",\"label\":\"T_C\",\"at\":\"C_o\",\"on\":\"C\","
                     "\"vector\":[0,0,1],\"unknown\":true,\"role\":\"own\"}"),
              std::string::npos)
        << c;
    // about C_o: C's weight m_C g at Ccm has a moment about Nz (C leans at qA + qB + qC =
    // 0.15 rad), B's force at C_o passes through O and drops out; the points named are O and
    // where the loads act
    EXPECT_NE(c.find("{\"kind\":\"gravity\",\"label\":\"m_C g\",\"at\":\"Ccm\",\"on\":\"C\","),
              std::string::npos)
        << c;
    EXPECT_NE(c.find("\"unknown\":false,\"role\":\"known\"}"), std::string::npos) << c;
    EXPECT_NE(c.find("{\"kind\":\"joint\",\"label\":\"from B\",\"at\":\"C_o\",\"on\":\"C\","
                     "\"vector\":[],\"unknown\":true,\"role\":\"drops\"}"),
              std::string::npos)
        << c;
    EXPECT_NE(c.find("\"points\":[\"C_o\",\"Ccm\"]"), std::string::npos) << c;
    // {A, B, C}: the joints at B_o and C_o between S's bodies are named too
    EXPECT_NE(a.find("\"points\":[\"A_o\",\"B_o\",\"C_o\",\"Acm\",\"Bcm\",\"Ccm\"]"),
              std::string::npos)
        << a;
    // the direction u = Nz, and the equation as TeX with the torque in it
    EXPECT_NE(c.find("\"direction\":[0,0,1]"), std::string::npos);
    // the row solved for its unknown (T_C enters with coefficient 1), written breakable: no
    // \left( ... \right) group that KaTeX or TeX could not break a line inside
    EXPECT_NE(c.find("\"equation\":\"T_{C} = "), std::string::npos) << c;
    EXPECT_EQ(c.find("\\\\left("), std::string::npos) << c;
}

TEST(Report, APlanarModelsAnglesAreMarkedFromTheParentsAxisToTheBodys) {
    // qA turns A from N about z, qB B from A, qC C from B (the chain's links along their
    // frames' axes): each angle at its body's joint, from the parent's axis to the body's,
    // its value the coordinate's at the configuration
    SitToStand s;
    const std::string json = render_report_json(s.content);
    const std::size_t at = json.find("\"angles\":[");
    ASSERT_NE(at, std::string::npos);
    const std::string angles = json.substr(at, json.find("]}", json.find("\"name\":\"qC\"", at)) - at);
    for (const char* q : {"\"body\":\"A\",\"name\":\"qA\",\"at\":\"A_o\"",
                          "\"body\":\"B\",\"name\":\"qB\",\"at\":\"B_o\"",
                          "\"body\":\"C\",\"name\":\"qC\",\"at\":\"C_o\""})
        EXPECT_NE(angles.find(q), std::string::npos) << q << " in " << angles;
    EXPECT_NE(angles.find("\"value\":0.35}"), std::string::npos) << angles;
    EXPECT_NE(angles.find("\"value\":-1.2}"), std::string::npos) << angles;
    EXPECT_NE(angles.find("\"value\":1}"), std::string::npos) << angles;
}

// A rod of length L sliding down a frictionless wall and floor, its angle q from the wall: no
// point of the rod stays put when q changes, so the row of q'' is about the instantaneous
// centre IC_q, where the lines of the wall's and the floor's forces meet. By hand that is at
// (L sin q, L cos q): the foot moves along Nx, the top along Ny. The page's data places it
// there, for the diagram of that row only, and the TikZ picture marks and names it.
TEST(Report, AnAboutPointThePlannerLocatedOffTheModelIsDrawnWhereItIs) {
    System sys;
    SymbolTable& st = sys.symbols();
    TimeVariable q = st.add_variable("q");
    const ex m = st.add_constant("m"), L = st.add_constant("L"), g = st.add_constant("g");
    const ex N_w = st.add_unknown("N_w"), N_f = st.add_unknown("N_f");
    const Frame& N = sys.newtonian();
    RigidBody& A = sys.add_rigid_body("A");
    Point& A_w = sys.add_point("A_w", &A);
    A.body_frame().orient_axis(N, Axis::z, q.symbol());
    sys.point("A_o").set_pos(sys.origin(), L * GiNaC::sin(q.symbol()) * N.x());
    A.cm().set_pos(sys.point("A_o"), L / 2 * A.body_frame().y());
    A_w.set_pos(sys.point("A_o"), L * A.body_frame().y());
    A.set_mass(m);
    A.set_inertia(A.cm(), 0, 0, m * L * L / 12);
    sys.set_gravity(-g * N.y());
    sys.add_force(A_w, N_w * N.x(), "Nw");
    sys.add_force(sys.point("A_o"), N_f * N.y(), "Nf");
    ReportContent content;
    content.system = &sys;
    content.title = "rod";
    content.rows = plan_roadmap(sys, {q}, {q.d(2), N_w, N_f});
    ASSERT_FALSE(content.rows.empty());
    ASSERT_NE(content.rows[0].about, nullptr);
    ASSERT_EQ(content.rows[0].about->name(), "IC_q");
    content.coordinates = {q};
    const double qv = 0.6, Lv = 2.0;
    content.configuration[q.symbol()] = qv;
    content.configuration[L] = Lv;
    content.configuration[m] = 3.0;
    content.configuration[g] = 9.81;
    const std::string json = render_report_json(content);
    const std::string key = "{\"name\":\"IC_q\",\"at\":[";
    const std::size_t at = json.find(key);
    ASSERT_NE(at, std::string::npos) << json.substr(json.find("\"geometry\""), 600);
    double x = 0, y = 0, z = 0;
    ASSERT_EQ(std::sscanf(json.c_str() + at + key.size(), "%lf,%lf,%lf", &x, &y, &z), 3);
    EXPECT_NEAR(x, Lv * std::sin(qv), 1e-5);
    EXPECT_NEAR(y, Lv * std::cos(qv), 1e-5);
    EXPECT_NEAR(z, 0, 1e-12);
    EXPECT_NE(json.find("\"about_only\":true", at), std::string::npos);
    EXPECT_EQ(count(json, "{\"name\":\"IC_q\""), 1u);
    EXPECT_NE(row_of(json, "q''").find("\"about\":\"IC_q\""), std::string::npos);
    // the TikZ picture of the row of q'' marks O there and names it; the other rows' do not
    const std::string tex = render_report_latex(content);
    EXPECT_EQ(count(tex, "{$O$ = IC\\_q}"), 1u);
}

// A point placed by data (a force plate's centre of pressure from px, py, read with the
// plate's record) where the configuration lacks them has no place: it is not drawn, nor is the
// force at it, and the LaTeX caption says so; with the data given (the diagrams drawn at a row
// of the record) both are drawn, the point where the data put it and the force as they say.
TEST(Report, APointPlacedByDataTheConfigurationLacksIsNotDrawnNorTheLoadAtIt) {
    SitToStand s;
    System& sys = s.m.system;
    const ex px = sys.symbols().add_specified("px").symbol();
    const ex py = sys.symbols().add_specified("py").symbol();
    const ex Fy = sys.symbols().add_specified("Fy").symbol();
    Point& cop = sys.add_point("CoP", &sys.body("B"));
    cop.set_pos(sys.origin(), Vector(sys.newtonian(), Col3{px, py, 0}));
    sys.add_force(cop, Vector(sys.newtonian(), Col3{0, Fy, 0}), "plate");
    std::string json = render_report_json(s.content);
    EXPECT_EQ(json.find("{\"name\":\"CoP\",\"at\""), std::string::npos);
    // the rows whose S holds B (T_A, T_B: S = {A, B, C}, {B, C}) list the plate's force undrawn
    EXPECT_EQ(count(json, "\"label\":\"plate\",\"at\":\"CoP\""), 2u);
    EXPECT_EQ(count(json, "\"placed\":false"), 2u);
    const std::string tex = render_report_latex(s.content);
    EXPECT_EQ(count(tex, "Not drawn, acting where this configuration does not say: plate at CoP."), 2u);
    EXPECT_EQ(count(tex, "% load: plate"), 0u);
    s.content.configuration[px] = 0.2;
    s.content.configuration[py] = 0.3;
    s.content.configuration[Fy] = 300;
    json = render_report_json(s.content);
    EXPECT_NE(json.find("{\"name\":\"CoP\",\"at\":[0.2,0.3,0]}"), std::string::npos);
    EXPECT_EQ(count(json, "\"label\":\"plate\",\"at\":\"CoP\",\"on\":\"B\",\"vector\":[0,300,0]"), 2u);
    EXPECT_EQ(count(json, "\"placed\":false"), 0u);
    EXPECT_EQ(count(render_report_latex(s.content), "% load: plate"), 2u);
}

// A known load zero at the configuration (a specified push of 0 N there) is drawn along its
// positive sense, the push taken as 1: its data carry that sense.
TEST(Report, AKnownLoadZeroAtTheConfigurationCarriesItsPositiveSense) {
    SitToStand s;
    System& sys = s.m.system;
    const ex P = sys.symbols().add_specified("P").symbol();
    sys.add_force(sys.point("Ccm"), Vector(sys.newtonian(), Col3{-P, 0, 0}), "push");
    s.content.configuration[P] = 0;
    const std::string json = render_report_json(s.content);
    // every row's S (T_A: {A, B, C}, T_B: {B, C}, T_C: {C}) holds C: the push on each diagram, 0 N
    // here, its sense -Nx
    EXPECT_EQ(count(json, "\"label\":\"push\",\"at\":\"Ccm\",\"on\":\"C\",\"vector\":[0,0,0]"), 3u);
    EXPECT_EQ(count(json, "\"sense\":[-1,0,0]"), 3u);
    EXPECT_EQ(count(json, "\"given\":false"), 0u);
    const std::string tex = render_report_latex(s.content);
    EXPECT_EQ(count(tex, "{push $= 0$}"), 3u);
    EXPECT_EQ(count(tex, "Zero at this configuration, drawn in its positive sense: push."), 3u);
}

// A known load whose value the configuration does not give (a specified push, a damper's
// force where no speed is given) is drawn along its positive sense with no value: not the
// 0 the evaluation would take for what it lacks, on the page and in TikZ alike.
TEST(Report, AKnownLoadTheConfigurationGivesNoValueOfIsLabelledWithNone) {
    SitToStand s;
    System& sys = s.m.system;
    const ex P = sys.symbols().add_specified("P").symbol();
    sys.add_force(sys.point("Ccm"), Vector(sys.newtonian(), Col3{-P, 0, 0}), "push");
    // a rotational damper on C (coefficient 2): -2 qC' about Nz
    const ex qC1 = s.m.q[2].d(1);
    sys.add_torque(sys.body("C"), Vector(sys.newtonian(), Col3{0, 0, -2 * qC1}), "damper");
    std::string json = render_report_json(s.content);
    EXPECT_EQ(count(json, "\"label\":\"push\",\"at\":\"Ccm\",\"on\":\"C\",\"vector\":[],"), 3u);
    EXPECT_EQ(count(json, "\"label\":\"damper\",\"at\":\"C_o\",\"on\":\"C\",\"vector\":[],"), 3u);
    EXPECT_EQ(count(json, "\"given\":false"), 6u);
    EXPECT_EQ(count(json, "\"sense\":[-1,0,0]"), 3u);  // the push taken as 1
    EXPECT_EQ(count(json, "\"sense\":[0,0,-2]"), 3u);  // qC' taken as 1
    std::string tex = render_report_latex(s.content);
    EXPECT_EQ(count(tex, "$= 0$"), 0u);
    EXPECT_EQ(count(tex, "{push}"), 3u);
    EXPECT_EQ(count(tex, "{damper}"), 3u);
    EXPECT_EQ(count(tex, "Value not given at this configuration, drawn in its positive sense: push, damper."), 3u);
    EXPECT_EQ(count(tex, "Zero at this configuration"), 0u);
    // given: the push of 5 N along -Nx, the damper's -2 * 0.5 = -1 N*m about Nz
    s.content.configuration[P] = 5;
    s.content.configuration[qC1] = 0.5;
    json = render_report_json(s.content);
    EXPECT_EQ(count(json, "\"label\":\"push\",\"at\":\"Ccm\",\"on\":\"C\",\"vector\":[-5,0,0],"), 3u);
    EXPECT_EQ(count(json, "\"label\":\"damper\",\"at\":\"C_o\",\"on\":\"C\",\"vector\":[0,0,-1],"), 3u);
    EXPECT_EQ(count(json, "\"given\":false"), 0u);
    // the values the configuration gives besides the coordinates, named on the page and in TikZ
    EXPECT_NE(json.find("\"configuration_data\":[{\"name\":\"qC'\",\"value\":0.5,\"shown\":0.5,\"unit\":\"\"},"
                        "{\"name\":\"P\",\"value\":5,\"shown\":5,\"unit\":\"\"}]"),
              std::string::npos);
    tex = render_report_latex(s.content);
    EXPECT_EQ(count(tex, "Value not given"), 0u);
    EXPECT_NE(tex.find(", with qC' = 0.5, P = 5"), std::string::npos);
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

// Whether a model is planar is decided at random states, not by simplifying each point's Nz
// measure: a 24-link spatial chain's tip, measured in N, would expand into 2^24 terms. The
// page's geometry (no rows here) is written, the chain is seen as spatial, and its last
// mass centre placed 23.5 m below N_o; a planar chain of the same length is seen as planar.
TEST(Report, ALongSpatialChainsGeometryIsWrittenWithoutExpandingItsPositions) {
    for (ChainKind kind : {ChainKind::spatial, ChainKind::planar}) {
        SampleModel m = make_n_link_pendulum(24, kind);
        ReportContent content;
        content.system = &m.system;
        content.title = "chain";
        content.coordinates = m.q;
        const std::string json = render_report_json(content);
        EXPECT_NE(json.find(kind == ChainKind::spatial ? "\"planar\":false" : "\"planar\":true"),
                  std::string::npos);
        EXPECT_EQ(count(json, "\"segments\":["), 1u);
        EXPECT_NE(json.find("{\"name\":\"B24cm\",\"at\":[0,-23.5,0]}"), std::string::npos);
    }
}

// A history's title names its statement, line and table; each series carries its own unit
// (the page plots each unit on its own axis), and the page's <title> is the model's name.
TEST(Report, HistoriesArePlottedAndTheirMotionAnimated) {
    SitToStand s;
    ReportHistory h;
    h.line = 31;
    h.file = "out/torques.csv";
    h.title = report_history_title("inverse", h.line, h.file);
    EXPECT_EQ(h.title, "inverse at line 31 (out/torques.csv)");
    EXPECT_EQ(report_history_title("inverse", 0, "torques.csv"), "inverse (torques.csv)");
    h.table.add_column("t", "s");
    h.table.add_column("T_A", "N*m");
    h.table.add_column("F_Ac", "N");
    h.table.columns[0] = {0, 0.5, 1};
    h.table.columns[1] = {1, 2, 3};
    h.table.columns[2] = {-4, 5, 6};
    h.coordinates = s.m.q;
    h.motion = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    s.content.histories.push_back(h);
    const std::string json = render_report_json(s.content);
    EXPECT_NE(json.find("\"title\":\"inverse at line 31 (out/torques.csv)\",\"line\":31,"
                        "\"file\":\"out/torques.csv\",\"rows\":3,\"plotted_rows\":3,"
                        "\"time\":[0,0.5,1],\"time_unit\":\"s\",\"series\":["
                        "{\"name\":\"T_A\",\"unit\":\"N*m\",\"values\":[1,2,3]},"
                        "{\"name\":\"F_Ac\",\"unit\":\"N\",\"values\":[-4,5,6]}]"),
              std::string::npos)
        << json.substr(json.find("\"histories\":"), 300);
    std::size_t anim = json.find("\"animation\":{\"source\":\"inverse at line 31 (out/torques.csv)\"");
    ASSERT_NE(anim, std::string::npos);
    EXPECT_NE(json.find("\"time\":[0,0.5,1],\"frames\":[[", anim), std::string::npos);
    const std::string html = render_report_html(s.content, "", "");
    EXPECT_NE(html.find("<title>sit_to_stand</title>"), std::string::npos);
}

// the values of the JSON array after `key` (from `from` on), as numbers
std::vector<double> numbers_after(const std::string& json, const std::string& key,
                                  std::size_t from = 0) {
    std::size_t at = json.find(key, from);
    EXPECT_NE(at, std::string::npos) << key;
    if (at == std::string::npos) return {};
    std::size_t begin = json.find('[', at) + 1, end = json.find(']', begin);
    std::vector<double> out;
    std::stringstream cells(json.substr(begin, end - begin));
    for (std::string cell; std::getline(cells, cell, ',');) out.push_back(std::stod(cell));
    return out;
}

TEST(Report, LongHistoriesAreThinnedForPlottingKeepingTheEndsAndTheExtremes) {
    SitToStand s;
    ReportHistory h;
    h.title = "simulation";
    h.table.add_column("t", "s");
    h.table.add_column("x", "m");
    h.table.add_column("y", "m");
    // a smooth x and a y that is 0 but for one row: the spike must survive thinning
    for (int k = 0; k <= 100000; ++k) {
        h.table.columns[0].push_back(k * 1e-3);
        h.table.columns[1].push_back(std::sin(k * 1e-4));
        h.table.columns[2].push_back(k == 61234 ? 5.0 : 0.0);
    }
    s.content.histories.push_back(h);
    const std::string json = render_report_json(s.content);
    std::size_t at = json.find("\"title\":\"simulation\",\"line\":0,\"file\":\"\",\"rows\":100001,\"plotted_rows\":");
    ASSERT_NE(at, std::string::npos);
    const std::vector<double> t = numbers_after(json, "\"time\":", at);
    const std::vector<double> x = numbers_after(json, "\"values\":", at);
    const std::vector<double> y =
        numbers_after(json, "\"values\":", json.find("\"name\":\"y\"", at));
    ASSERT_EQ(t.size(), x.size());
    ASSERT_EQ(t.size(), y.size());
    EXPECT_LE(t.size(), 2002u);
    EXPECT_GE(t.size(), 1000u);
    EXPECT_EQ(t.front(), 0);
    EXPECT_EQ(t.back(), 100);
    EXPECT_TRUE(std::is_sorted(t.begin(), t.end()));
    EXPECT_EQ(*std::max_element(y.begin(), y.end()), 5.0);  // the one-row spike
    EXPECT_NEAR(t[std::max_element(y.begin(), y.end()) - y.begin()], 61.234, 1e-9);
    // x = sin(t/10) over 0..100 s: its greatest value 1 and least -1 are kept (to 6 digits)
    EXPECT_NEAR(*std::max_element(x.begin(), x.end()), 1.0, 1e-6);
    EXPECT_NEAR(*std::min_element(x.begin(), x.end()), -1.0, 1e-6);
}

TEST(Report, PlotControlChoosesTheSeriesOrSkipsThePlots) {
    SitToStand s;
    ReportHistory h;
    h.title = "simulation";
    for (const char* n : {"t", "qA", "qB", "energy"}) h.table.add_column(n, "");
    for (auto& c : h.table.columns) c = {0, 1, 2};
    s.content.histories.push_back(h);
    s.content.plotted = {"qB"};
    std::string json = render_report_json(s.content);
    const std::size_t from = json.find("\"histories\":");
    const std::string plots = json.substr(from, json.find("\"animation\":", from) - from);
    EXPECT_NE(plots.find("\"series\":[{\"name\":\"qB\""), std::string::npos);
    EXPECT_EQ(plots.find("\"name\":\"qA\""), std::string::npos);
    EXPECT_EQ(plots.find("\"name\":\"energy\""), std::string::npos);
    s.content.plotted.clear();
    s.content.plot_histories = false;
    json = render_report_json(s.content);
    EXPECT_NE(json.find("\"histories\":[]"), std::string::npos);
}

TEST(Report, ChecksMeasureEnergyDriftAndTheMethodsCompared) {
    SitToStand s;
    ReportHistory h;
    h.title = "simulation";
    h.table.add_column("t", "s");
    h.table.add_column("energy", "J");
    h.table.add_column("drift_loop", "m");
    h.table.columns[0] = {0, 1, 2, 3};
    h.table.columns[1] = {10, 10 + 2e-9, 10 - 4e-9, 10};  // changes by 4e-10 of its largest
    h.table.columns[2] = {0, 3e-7, -2e-3, 0};             // a drift of 2 mm fails the check
    s.content.histories.push_back(h);
    s.content.methods = compare_methods(s.m.system, s.m.q);
    std::vector<ReportCheck> checks = calc_report_checks(s.content);
    ASSERT_GE(checks.size(), 2u);
    EXPECT_EQ(checks[0].kind, "energy");
    EXPECT_NEAR(checks[0].value, 4e-9 / (10 + 2e-9), 1e-15);
    EXPECT_TRUE(checks[0].passed);
    EXPECT_EQ(checks[1].kind, "constraint");
    EXPECT_EQ(checks[1].value, 2e-3);
    EXPECT_EQ(checks[1].unit, "m");
    EXPECT_FALSE(checks[1].passed);
    // every other method against the road-map (Kane, Lagrange, Newton-Euler, ...), within 1e-8
    std::size_t methods = 0;
    for (const ReportCheck& c : checks)
        if (c.kind == "methods") {
            ++methods;
            EXPECT_TRUE(c.passed) << c.summary;
            EXPECT_LT(c.value, 1e-8);
        }
    ASSERT_GE(s.content.methods->methods.size(), 4u);
    EXPECT_EQ(methods, s.content.methods->methods.size() - 1);
    const std::string json = render_report_json(s.content);
    EXPECT_NE(
        json.find("\"checks\":[{\"kind\":\"energy\",\"name\":\"energy\",\"source\":\"simulation\""),
        std::string::npos);
}

TEST(Report, TheAnimationCarriesEachBodysAxesForThe3DView) {
    SitToStand s;
    ReportHistory h;
    h.title = "simulation";
    h.table.add_column("t", "s");
    h.table.columns[0] = {0, 1};
    h.coordinates = s.m.q;
    // qA = 0 then pi/2: A's x axis turns from Nx to Ny
    h.motion = {{0, 1.5707963267948966}, {0, 0}, {0, 0}};
    s.content.histories.push_back(h);
    const std::string json = render_report_json(s.content);
    EXPECT_NE(json.find("\"bodies\":[{\"name\":\"A\",\"cm\":\"Acm\",\"ellipsoid\":{"),
              std::string::npos);
    EXPECT_NE(json.find("{\"name\":\"C\",\"cm\":\"Ccm\",\"ellipsoid\":{"), std::string::npos);
    // A's inertia is I_A about Az alone (a segment in the plane): its uniform ellipsoid is the
    // flat ellipse a^2 = 5 (I_A + 0 - 0) / (2 m_A) in the x-y plane, no thickness along Az
    const SymbolTable& st = s.m.system.symbols();
    const double I_A = *st.value(st.symbol("I_A")), m_A = *st.value(st.symbol("m_A"));
    const std::size_t shell = json.find("\"ellipsoid\":", json.find("\"bodies\":[{\"name\":\"A\""));
    std::vector<double> axes = numbers_after(json, "\"axes\":", shell);
    const std::vector<double> directions = numbers_after(json, "\"directions\":", shell);
    ASSERT_EQ(axes.size(), 3u);
    ASSERT_EQ(directions.size(), 9u);
    std::vector<double> sorted = axes;
    std::sort(sorted.begin(), sorted.end());
    EXPECT_NEAR(sorted[0], 0, 1e-6);
    EXPECT_NEAR(sorted[1], std::sqrt(2.5 * I_A / m_A), 1e-5);
    EXPECT_NEAR(sorted[2], std::sqrt(2.5 * I_A / m_A), 1e-5);
    const int flat = static_cast<int>(std::min_element(axes.begin(), axes.end()) - axes.begin());
    EXPECT_NEAR(std::abs(directions[3 * flat + 2]), 1.0, 1e-6);  // the flat axis is along Az
    // gravity -g Ny: up is +Ny
    EXPECT_NE(json.find("\"up\":[0,"), std::string::npos);
    const std::size_t anim = json.find("\"animation\":");
    const std::vector<double> frame1 = numbers_after(json, "],[", json.find("\"frames\":", anim));
    const std::size_t points = frame1.size() - 27;  // 3 per point, then 9 per body
    ASSERT_EQ(points % 3, 0u);
    // A's axes at qA = pi/2: x along Ny, y along -Nx, z along Nz
    const std::vector<double> A(frame1.begin() + points, frame1.begin() + points + 9);
    const std::vector<double> expected{0, 1, 0, -1, 0, 0, 0, 0, 1};
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(A[k], expected[k], 1e-6) << k;
}

TEST(Report, ThreeJsIsInlinedOnlyWhereThereIsA3DView) {
    SitToStand s;
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "alembert_three";
    fs::create_directories(dir);
    std::ofstream(dir / "three.min.js") << "var THREE_MARKER = 1;";
    // planar and no motion: no 3D view, no three.js
    EXPECT_EQ(render_report_html(s.content, "", dir.string()).find("THREE_MARKER"),
              std::string::npos);
    ReportHistory h;
    h.title = "simulation";
    h.table.add_column("t", "s");
    h.table.columns[0] = {0, 1};
    h.coordinates = s.m.q;
    h.motion = {{0, 1}, {0, 0}, {0, 0}};
    s.content.histories.push_back(h);
    EXPECT_NE(render_report_html(s.content, "", dir.string()).find("THREE_MARKER"),
              std::string::npos);
    fs::remove_all(dir);
}

// the JSON strings between `begin` and the first `end` after it, unescaped
std::vector<std::string> json_strings(const std::string& json, const std::string& begin,
                                      const std::string& end) {
    std::vector<std::string> out;
    std::size_t at = json.find(begin);
    EXPECT_NE(at, std::string::npos) << begin;
    if (at == std::string::npos) return out;
    const std::size_t stop = json.find(end, at + begin.size());
    for (at += begin.size(); at < stop; ++at) {
        if (json[at] != '"') continue;
        std::string text;
        for (++at; json[at] != '"'; ++at) {
            if (json[at] != '\\') {
                text += json[at];
                continue;
            }
            const char c = json[++at];
            if (c == 'u') {
                text += static_cast<char>(std::stoi(json.substr(at + 1, 4), nullptr, 16));
                at += 4;
            } else {
                text += c == 'n' ? '\n' : c;
            }
        }
        out.push_back(text);
    }
    return out;
}

TEST(Report, MassMatrixAndForcingAgreeWithTheTriplePendulumDerivedByHand) {
    SitToStand s;
    EXPECT_EQ(render_report_json(s.content).find("\"matrices\""), std::string::npos);
    s.content.matrices = form_forward_equations(s.m.system, s.m.q);
    const std::string json = render_report_json(s.content);
    const std::vector<std::string> unknowns = json_strings(json, "\"matrices\":{\"unknowns\":", "]");
    const std::vector<std::string> M = json_strings(json, "\"M\":", "]]");
    const std::vector<std::string> f = json_strings(json, "\"f\":", "]");
    ASSERT_EQ(unknowns, (std::vector<std::string>{"qA''", "qB''", "qC''"}));
    ASSERT_EQ(M.size(), 9u);
    ASSERT_EQ(f.size(), 3u);
    // the matrices' own "tex" (the rows' derivations hold steps with "tex" too)
    const std::vector<std::string> tex =
        json_strings(json.substr(json.find("\"matrices\":{")), "\"tex\":", "}");
    ASSERT_EQ(tex.size(), 1u);
    // too wide for one line as a matrix: the equation with the accelerations' column, then each
    // entry on a line of its own (M_{ij} = ..., f_{i} = ...)
    EXPECT_EQ(count(tex[0], "\\begin{bmatrix}"), 1u);
    EXPECT_NE(tex[0].find(to_latex(s.m.q[2].d(2))), std::string::npos) << tex[0];
    EXPECT_EQ(count(tex[0], " \\newline M_{"), 9u);
    EXPECT_EQ(count(tex[0], " \\newline f_{"), 3u);

    // read the printed entries back: primes become _d, every name the model's own symbol
    const SymbolTable& st = s.m.system.symbols();
    GiNaC::symtab names;
    auto plain = [](std::string text) {
        for (std::size_t at = text.find('\''); at != std::string::npos; at = text.find('\''))
            text.replace(at, 1, "_d");
        return text;
    };
    for (SymbolKind k : {SymbolKind::constant, SymbolKind::unknown})
        for (const ex& x : st.symbols(k)) names[st.name(x)] = x;
    for (const TimeVariable& q : s.m.q)
        for (int k = 0; k <= 2; ++k) names[plain(to_string(q.d(k)))] = q.d(k);
    GiNaC::parser read(names, true);

    // by hand: absolute angles th_i = qA + ... (each body's y axis (-sin th, cos th) in N);
    // mass centre velocities J_i q' with columns l e'(th) (e' = (-cos th, -sin th)) summed
    // over the segments between the ankle and the joint turned; M = sum m J^T J + I w^T w;
    // f = torques + gravity - sum m J^T (accelerations at q'' = 0: -sum l th'^2 e(th))
    std::mt19937 rng(15);
    std::uniform_real_distribution<double> angle(-3, 3), value(0.2, 2.0);
    for (int trial = 0; trial < 5; ++trial) {
        exmap at;
        std::map<std::string, double> c;
        for (const ex& x : st.symbols(SymbolKind::constant)) at[x] = c[st.name(x)] = value(rng);
        for (const ex& x : st.symbols(SymbolKind::unknown)) at[x] = c[st.name(x)] = angle(rng);
        double q[3], qd[3];
        for (int i = 0; i < 3; ++i) {
            at[s.m.q[i].d(0)] = q[i] = angle(rng);
            at[s.m.q[i].d(1)] = qd[i] = angle(rng);
        }
        const char* n[3] = {"A", "B", "C"};
        const double th[3] = {q[0], q[0] + q[1], q[0] + q[1] + q[2]};
        const double thd[3] = {qd[0], qd[0] + qd[1], qd[0] + qd[1] + qd[2]};
        Eigen::Matrix3d Mh = Eigen::Matrix3d::Zero();
        Eigen::Vector3d fh(c["T_A"], c["T_B"], c["T_C"]);
        for (int i = 0; i < 3; ++i) {
            // body i: segments j < i of length L_j, then d_i
            auto length = [&](int j) { return j < i ? c[std::string("L_") + n[j]] : c[std::string("d_") + n[i]]; };
            Eigen::Matrix<double, 2, 3> J = Eigen::Matrix<double, 2, 3>::Zero();
            Eigen::Vector2d a0 = Eigen::Vector2d::Zero();
            for (int j = 0; j <= i; ++j) {
                const Eigen::Vector2d e(-std::sin(th[j]), std::cos(th[j]));
                const Eigen::Vector2d ed(-std::cos(th[j]), -std::sin(th[j]));
                for (int k = 0; k <= j; ++k) J.col(k) += length(j) * ed;
                a0 -= length(j) * thd[j] * thd[j] * e;
            }
            Eigen::RowVector3d w = Eigen::RowVector3d::Zero();
            for (int k = 0; k <= i; ++k) w(k) = 1;
            const double mass = c[std::string("m_") + n[i]], I = c[std::string("I_") + n[i]];
            Mh += mass * J.transpose() * J + I * w.transpose() * w;
            fh += J.transpose() * (mass * Eigen::Vector2d(0, -c["g"]) - mass * a0);
        }
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                const double got = st.evaluate(read(plain(M[3 * i + j])), at);
                EXPECT_NEAR(got, Mh(i, j), 1e-12 * (1 + std::abs(Mh(i, j))))
                    << "M(" << i << "," << j << ") = " << M[3 * i + j];
            }
            const double got = st.evaluate(read(plain(f[i])), at);
            EXPECT_NEAR(got, fh(i), 1e-12 * (1 + std::abs(fh(i)))) << "f(" << i << ") = " << f[i];
        }
    }
    // the same matrices typeset in roadmap.tex
    const std::string latex = render_report_latex(s.content);
    EXPECT_NE(latex.find("\\subsection*{Mass matrix and forcing}"), std::string::npos);
    // each line a paragraph of its own there
    std::size_t lines = 0;
    for (std::size_t start = 0, end = 0; end != std::string::npos; start = end + 10, ++lines) {
        end = tex[0].find(" \\newline ", start);
        const std::string line = tex[0].substr(start, end == std::string::npos ? end : end - start);
        EXPECT_NE(latex.find("\\eqline{" + line + "}"), std::string::npos) << line;
    }
    EXPECT_EQ(lines, 13u);
}

TEST(Report, SameContentGivesTheSameBytes) {
    SitToStand s1, s2;
    EXPECT_EQ(render_report_html(s1.content, ""), render_report_html(s2.content, ""));
}

// GiNaC orders the terms of sums and products by its symbols' serial numbers and hashes: the
// page must not follow that order, so it is the same whatever the process made before
TEST(Report, SameContentGivesTheSameBytesWhateverWasMadeBefore) {
    std::string first;
    {
        SitToStand s;
        first = render_report_html(s.content, "");
    }
    for (int round = 0; round < 3; ++round) {
        std::vector<GiNaC::symbol> unrelated;
        for (int k = 0; k < 1000 + 777 * round; ++k) unrelated.emplace_back("d" + std::to_string(k));
        SampleModel other = make_n_link_pendulum(2 + round);
        (void)plan_roadmap(other.system, other.q, other.unknowns);
        SitToStand s;
        const std::string again = render_report_html(s.content, "");
        EXPECT_TRUE(again == first) << "the page differs after unrelated symbols, round " << round;
    }
}

TEST(Report, PageHoldsTheDataAndTheViewerAndNoClosingScriptInsideTheData) {
    SitToStand s;
    s.content.title = "a</script>b";
    const std::string page = render_report_html(s.content, "");
    EXPECT_NE(page.find("<script type=\"application/json\" id=\"alembert-data\">{\"format\":1"),
              std::string::npos);
    EXPECT_NE(page.find("Alembert's report viewer"), std::string::npos);
    EXPECT_EQ(count(page, "</script>"), 2u);  // the data's and the viewer's
    EXPECT_NE(page.find("<title>a&lt;/script&gt;b</title>"), std::string::npos);  // the model's name
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
    EXPECT_NE(tex.find("$T_{A}$ & rotate & \\raggedright Nz\\textgreater{} & \\raggedright "
                       "$\\{A,\\allowbreak B,\\allowbreak C\\}$ & \\raggedright A\\_\\allowbreak{}o & none "
                       "\\tabularnewline"),
              std::string::npos)
        << tex;
    EXPECT_NE(tex.find("\\paragraph{Row 3: $S = \\{C\\}$ for $T_{C}$.} T\\_C on C from B (unknown); "
                       "gravity at Ccm; joint force at C\\_o from B (unknown)."),
              std::string::npos);
    // one TikZ picture per row, each with an arrow per load on S: {A,B,C}: T_A, 3 weights, the
    // ground's force at A_o; {B,C}: T_B, 2 weights, A's force; {C}: T_C, its weight, B's force
    EXPECT_EQ(count(tex, "\\begin{tikzpicture}"), 3u);
    std::vector<std::size_t> loads;
    for (std::size_t at = tex.find("\\begin{tikzpicture}"); at != std::string::npos;
         at = tex.find("\\begin{tikzpicture}", at + 1))
        loads.push_back(count(tex.substr(at, tex.find("\\end{tikzpicture}", at) - at), "% load: "));
    EXPECT_EQ(loads, (std::vector<std::size_t>{5, 4, 3}));
    EXPECT_EQ(count(tex, "{$O$ = "), 3u);  // each about point marked and named
    // the weights labelled m g as the model names them; the row's torque highlighted, the
    // joint's force through O dashed, the caption saying so
    EXPECT_EQ(count(tex, "{$m_{A} \\, g$}"), 1u) << tex;
    EXPECT_EQ(count(tex, "{$m_{C} \\, g$}"), 3u);
    EXPECT_EQ(count(tex, "Highlighted: solved for in this row"), 3u);
    EXPECT_EQ(count(tex, "Dashed: loads $E_{"), 3u);
    EXPECT_EQ(count(tex, "% angle: "), 3u + 2u + 1u);  // S's rotations: qA, qB, qC; qB, qC; qC
    // each row's diagram, its caption and its equation (solved for the torque) in one box that
    // does not float away from them
    EXPECT_EQ(count(tex, "\\begin{minipage}{\\linewidth}"), 3u);
    EXPECT_EQ(count(tex, ": free-body diagram of $S = "), 3u);
    for (const char* row : {"A", "B", "C"}) {
        const std::string name = std::string("\\eqline{E_{T_{") + row + "}}\\colon\\ T_{" + row + "} = ";
        const std::size_t at = tex.find(name);
        EXPECT_NE(at, std::string::npos) << name;
        EXPECT_GT(at, tex.find(std::string("Figure ") + static_cast<char>('1' + (row[0] - 'A'))));
        EXPECT_LT(at, tex.find("\\end{minipage}", tex.find(std::string("Figure ") +
                                                           static_cast<char>('1' + (row[0] - 'A')))));
    }
    EXPECT_NE(tex.find("\\end{document}"), std::string::npos);
}

}  // namespace
}  // namespace alembert

namespace alembert {
namespace {
// the (dx, dy) of every gravity arrow in roadmap.tex's diagrams (TikZ's y points up)
std::vector<std::pair<double, double>> gravity_arrows(const std::string& tex) {
    std::vector<std::pair<double, double>> out;
    std::istringstream in(tex);
    std::string line;
    bool next = false;
    while (std::getline(in, line)) {
        if (next) {
            const std::size_t at = line.find("++(");
            if (at != std::string::npos) {
                double dx = 0, dy = 0;
                char comma = 0;
                std::istringstream v(line.substr(at + 3));
                v >> dx >> comma >> dy;
                out.emplace_back(dx, dy);
            }
        }
        next = line.rfind("% load: ", 0) == 0 && line.size() > 2 && line.substr(line.size() - 2) == " g";
    }
    return out;
}
}  // namespace

TEST(Report, GravityPointsDownThePageWhicheverAxisIsUp) {
    // the arm has Nz up (gravity -g Nz); the chain has Ny up: both drawn with gravity down
    SampleModel arm = make_kuka_iiwa14();
    SampleModel chain = make_n_link_pendulum(3, ChainKind::spatial);
    for (SampleModel* m : {&arm, &chain}) {
        ReportContent content;
        content.system = &m->system;
        content.title = "up";
        content.coordinates = m->q;
        content.rows = plan_roadmap(m->system, m->q, m->unknowns);
        for (std::size_t i = 0; i < m->q.size(); ++i)
            content.configuration[m->q[i].symbol()] = 0.3 + 0.1 * static_cast<double>(i);
        const auto arrows = gravity_arrows(render_report_latex(content));
        ASSERT_FALSE(arrows.empty());
        for (const auto& [dx, dy] : arrows) {
            EXPECT_LT(dy, -0.5);
            EXPECT_LE(std::abs(dx), 0.01) << dx << ", " << dy;
        }
        // the page's "up" is against gravity
        const std::string json = render_report_json(content);
        const bool z_up = json.find("\"up\":[0,0,") != std::string::npos;
        EXPECT_EQ(z_up, m == &arm) << json.substr(json.find("\"up\":"), 30);
    }
}

}  // namespace alembert

namespace alembert {
namespace {

TEST(ReportLatex, ARootOfALongSumIsNamedOnItsOwnLineAndTheRestLeftWhole) {
    // a spring's pull over its length sqrt(...): the sum under the root is too long to leave
    // unbroken inside a fraction, so it is named w1 on the next line; nothing else is named
    SitToStand s;
    SymbolTable& st = s.m.system.symbols();
    const ex qA = s.m.q[0].symbol(), qB = s.m.q[1].symbol(), qC = s.m.q[2].symbol();
    const ex L_A = st.symbol("L_A"), L_B = st.symbol("L_B"), d_C = st.symbol("d_C"), g = st.symbol("g"),
             m_A = st.symbol("m_A"), T_A = st.symbol("T_A");
    const ex length2 = L_A * L_A + L_B * L_B + 2 * L_A * L_B * GiNaC::cos(qB) + d_C * d_C +
                       2 * d_C * L_B * GiNaC::cos(qC) + 2 * L_A * d_C * GiNaC::cos(qB + qC);
    const ex e = T_A - g * L_A * m_A * GiNaC::sin(qA) * L_B * d_C / GiNaC::sqrt(length2);
    s.content.equation_sets.push_back({"P", "Kane's method", 1, {e}, {}});
    const std::string tex = render_report_latex(s.content);
    const std::size_t at = tex.find("\\eqline{\\mathrm{P}[1]\\colon\\ 0 = ");
    ASSERT_NE(at, std::string::npos) << tex;
    const std::size_t end = tex.find("\\end{eqlines}", at);
    const std::string shown = tex.substr(at, end - at);
    EXPECT_NE(shown.find("\\sqrt{w1}"), std::string::npos) << shown;
    EXPECT_NE(shown.find("\n\\eqline{\\text{with } w1 = "), std::string::npos) << shown;
    EXPECT_EQ(shown.find("w2"), std::string::npos) << shown;
    EXPECT_EQ(count(shown, "\\eqline{"), 2u) << shown;
}

}  // namespace
}  // namespace alembert

namespace alembert {
namespace {

// A linearize-like sweep of k = 0, 1, ..., count - 1 N/m: re_1 = -k/10, re_2 = 0, im_1 =
// sqrt(k), im_2 = -sqrt(k), im_3 = 1e-20 (round-off of 0); `extra` more real parts k + i
ReportSweep sample_sweep(std::size_t count, std::size_t extra = 0) {
    ReportSweep w;
    w.title = "linearize at line 7 (sweep/eigenvalues.csv)";
    w.file = "sweep/eigenvalues.csv";
    Table& t = w.table;
    t.add_column("k", "N/m");
    for (const char* n : {"re_1", "re_2"}) t.add_column(n, "1/s");
    for (std::size_t i = 0; i < extra; ++i) t.add_column("re_" + std::to_string(3 + i), "1/s");
    for (const char* n : {"im_1", "im_2", "im_3"}) t.add_column(n, "1/s");
    for (std::size_t r = 0; r < count; ++r) {
        const double k = static_cast<double>(r);
        std::vector<double> row{k, -k / 10, 0};
        for (std::size_t i = 0; i < extra; ++i) row.push_back(k + static_cast<double>(i));
        row.insert(row.end(), {std::sqrt(k), -std::sqrt(k), 1e-20});
        for (std::size_t c = 0; c < row.size(); ++c) t.columns[c].push_back(row[c]);
    }
    w.axes.assign(2 + extra, "real part");
    w.axes.insert(w.axes.end(), 3, "imaginary part");
    return w;
}

// the rows of the tables in `tex` (a cell $x$ or $m\cdot 10^{e}$ each) as numbers
std::vector<std::vector<double>> table_numbers(const std::string& tex) {
    std::vector<std::vector<double>> rows;
    std::istringstream in(tex);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("$", 0) != 0 || line.find(" \\\\") == std::string::npos) continue;
        std::vector<double> row;
        std::istringstream cells(line.substr(0, line.find(" \\\\")));
        for (std::string c; std::getline(cells, c, '&');) {
            double m = 0;
            int e = 0;
            const std::size_t dollar = c.find('$');
            const int got = std::sscanf(c.c_str() + dollar, "$%lf\\cdot 10^{%d}$", &m, &e);
            row.push_back(got >= 1 ? m * std::pow(10.0, got == 2 ? e : 0) : NAN);
        }
        rows.push_back(row);
    }
    return rows;
}

TEST(ReportLatex, ALongSweepIsTabulatedAtAtMost25SamplesSayingWhichAndPlottedPerAxis) {
    SitToStand s;
    s.content.results.push_back(
        {7, "linearize K at x = 0 for k = 0 to 102 step 1", "swept k", sample_sweep(103)});
    const std::string tex = render_report_latex(s.content);
    EXPECT_EQ(tex, render_report_latex(s.content));  // same content, same bytes
    EXPECT_NE(tex.find("\\usepackage{pgfplots}"), std::string::npos);
    const std::string part = tex.substr(tex.find("Line 7:\n"));
    // a plot per axis against k, re_2 and im_3 (0 at every sample) one line at 0 each
    EXPECT_EQ(count(part, "\\begin{axis}"), 2u);
    EXPECT_EQ(count(part, "xlabel={k [N/m]}"), 2u);
    EXPECT_NE(part.find("\\addlegendentry{re\\_2: 0}"), std::string::npos);
    EXPECT_NE(part.find("\\addlegendentry{im\\_3: 0}"), std::string::npos);
    // the table: every 5th of the 103 samples and the last (22 rows), the series 0 throughout
    // left out and named, and the round-off said
    EXPECT_NE(
        part.find("the values at 22 of the 103 samples, every 5th from the first and the last"),
        std::string::npos)
        << part.substr(part.find("Table:"), 400);
    EXPECT_NE(part.find("k [N/m] & re\\_1 & im\\_1 & im\\_2 \\\\"), std::string::npos);
    EXPECT_NE(part.find("re\\_2, im\\_3 are 0 at every sample, not listed."), std::string::npos);
    EXPECT_NE(part.find("are round-off, written 0."), std::string::npos);
    const std::vector<std::vector<double>> rows = table_numbers(part);
    ASSERT_EQ(rows.size(), 22u);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const double k = i + 1 < rows.size() ? 5.0 * static_cast<double>(i) : 102.0;
        ASSERT_EQ(rows[i].size(), 4u);
        EXPECT_EQ(rows[i][0], k);
        EXPECT_NEAR(rows[i][1], -k / 10, 1e-6 * std::max(1.0, k / 10));
        EXPECT_NEAR(rows[i][2], std::sqrt(k), 1e-6 * std::max(1.0, std::sqrt(k)));
        EXPECT_NEAR(rows[i][3], -std::sqrt(k), 1e-6 * std::max(1.0, std::sqrt(k)));
    }
    // without plots: the table alone, and no pgfplots
    s.content.plot_histories = false;
    const std::string bare = render_report_latex(s.content);
    EXPECT_EQ(bare.find("pgfplots"), std::string::npos);
    EXPECT_EQ(bare.find("\\begin{axis}"), std::string::npos);
    EXPECT_EQ(table_numbers(bare.substr(bare.find("Line 7:\n"))).size(), 22u);
}

TEST(ReportLatex, ASweepsPlotsHoldTenSeriesEachAndASingleSampleIsTabulatedOnly) {
    SitToStand s;
    // 1 + 12 real parts not 0 throughout: two plots of 7 and 6 (as the page shares them)
    s.content.results.push_back({7, "linearize", "", sample_sweep(4, 12)});
    std::string tex = render_report_latex(s.content);
    std::string part = tex.substr(tex.find("Line 7:\n"));
    EXPECT_EQ(count(part, "\\begin{axis}"), 3u);
    EXPECT_EQ(count(part, "real parts, 1/s, 1 of 2, against k"), 1u);
    EXPECT_EQ(count(part, "real parts, 1/s, 2 of 2, against k"), 1u);
    const std::size_t second = part.find("\\begin{axis}", part.find("\\begin{axis}") + 1);
    EXPECT_EQ(count(part.substr(0, second), "% series: "), 7u);
    // one sample: nothing to draw a line through, its values tabulated
    s.content.results.back().sweep = sample_sweep(1);
    tex = render_report_latex(s.content);
    part = tex.substr(tex.find("Line 7:\n"));
    EXPECT_EQ(count(part, "\\begin{axis}"), 0u);
    EXPECT_NE(part.find("the values at its one sample"), std::string::npos);
    // a model without sweeps needs no pgfplots
    SitToStand plain;
    EXPECT_EQ(render_report_latex(plain.content).find("pgfplots"), std::string::npos);
}

}  // namespace
}  // namespace alembert
