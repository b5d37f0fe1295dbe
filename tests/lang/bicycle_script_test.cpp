// SPDX-License-Identifier: MIT
// The Whipple bicycle written as a script (examples/bicycle/model.alb) against Meijaard,
// Papadopoulos, Ruina & Schwab (2007): every Table 2 eigenvalue read from the sweep's
// eigenvalues.csv, and the weave and capsize speeds from the script's own linearization.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Dense>
#include <ginac/ginac.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "alembert/lang/interpreter.hpp"
#include "alembert/mech/system.hpp"
#include "alembert/sim/table.hpp"
#include "support/meijaard2007.hpp"

namespace bicycle_script_test {

namespace fs = std::filesystem;
using namespace alembert::lang;
using alembert::test::kMeijaardCapsizeSpeed, alembert::test::kMeijaardTable2,
    alembert::test::kMeijaardWeaveSpeed, alembert::test::MeijaardTable2Row;
using GiNaC::ex;

using Eigenvalues = std::vector<std::complex<double>>;

Eigenvalues sorted(Eigenvalues z) {
    std::sort(z.begin(), z.end(), [](auto a, auto b) {
        return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
    });
    return z;
}

// the text after `prefix` up to the end of its line, on the n-th line (0-based) holding it
std::string line_after(const std::string& text, const std::string& prefix, int n = 0) {
    std::size_t p = text.find(prefix);
    for (int i = 0; i < n && p != std::string::npos; ++i) p = text.find(prefix, p + 1);
    if (p == std::string::npos) {
        ADD_FAILURE() << "no line " << n + 1 << " with '" << prefix << "' in the transcript";
        return "";
    }
    p += prefix.size();
    return text.substr(p, text.find('\n', p) - p);
}

// "  [a, b(c, d), e]" as its entries
std::vector<std::string> matrix_row(const std::string& line) {
    std::vector<std::string> out;
    const std::size_t open = line.find('['), close = line.rfind(']');
    int depth = 0;
    std::string entry;
    for (std::size_t i = open + 1; i < close; ++i) {
        const char ch = line[i];
        depth += ch == '(' ? 1 : ch == ')' ? -1 : 0;
        if (ch == ',' && depth == 0) out.push_back(entry), entry.clear();
        else entry += ch;
    }
    out.push_back(entry);
    return out;
}

// the script run once, its transcript at 17 digits and its eigenvalues.csv
struct BicycleRun {
    fs::path dir;
    std::ostringstream out, err;
    Interpreter interp{out, err, false};
    RunStatus status = RunStatus::internal_error;
    std::string transcript;
    alembert::Table sweep{};
    double seconds = 0;

    BicycleRun() {
        std::string t = (fs::temp_directory_path() / "alembert-bicycle-XXXXXX").string();
        dir = ::mkdtemp(t.data());
        const fs::path script = fs::path(ALEMBERT_SOURCE_DIR) / "examples" / "bicycle" / "model.alb";
        std::ifstream in(script);
        std::ostringstream text;
        text << in.rdbuf();
        interp.set_output_dir(dir.string());
        interp.set_digits(17);
        const auto t0 = std::chrono::steady_clock::now();
        status = interp.run(text.str(), script.string());
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        transcript = out.str();
        if (status == RunStatus::ok) sweep = alembert::read_csv((dir / "speed_sweep" / "eigenvalues.csv").string());
    }
    ~BicycleRun() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    // every eigenvalue of the sweep's row at speed v (9 states: 5 exact zeros and the 4 of
    // lean and steer)
    Eigenvalues sweep_eigenvalues(double v) const {
        const std::size_t n = (sweep.names.size() - 1) / 2;
        for (std::size_t r = 0; r < sweep.row_count(); ++r)
            if (sweep.columns[0][r] == v) {
                Eigenvalues z;
                for (std::size_t k = 1; k <= n; ++k)
                    z.emplace_back(sweep.columns[sweep.column_index("re_" + std::to_string(k))][r],
                                   sweep.columns[sweep.column_index("im_" + std::to_string(k))][r]);
                return z;
            }
        ADD_FAILURE() << "no row v = " << v << " in eigenvalues.csv";
        return {};
    }
};

// The state matrix A the script printed (symbolic in v and the constants of Table 1), read
// back; its lean and steer block (states q2, q5, u2, u5) evaluated at any speed.
struct PrintedA {
    std::vector<std::string> states;
    std::vector<std::vector<ex>> A;  // the constants' values put in: functions of v alone
    ex v;

    explicit PrintedA(const BicycleRun& run) {
        const alembert::SymbolTable& table = run.interp.system()->symbols();
        GiNaC::symtab names;
        for (const ex& c : table.symbols(alembert::SymbolKind::constant)) names[table.name(c)] = c;
        v = names.at("v");
        GiNaC::exmap values = table.constant_values();
        GiNaC::parser reader(names, true);  // strict: a name the table does not hold is an error
        std::string list = line_after(run.transcript, "states (");
        list = list.substr(0, list.find(')'));
        for (std::size_t p = 0; p != std::string::npos;) {
            std::size_t q = list.find(", ", p);
            states.push_back(list.substr(p, q == std::string::npos ? q : q - p));
            p = q == std::string::npos ? q : q + 2;
        }
        std::istringstream in(run.transcript.substr(run.transcript.find("\nA =\n") + 5));
        std::string line;
        for (std::size_t i = 0; i < states.size() && std::getline(in, line); ++i) {
            A.emplace_back();
            for (const std::string& e : matrix_row(line)) A.back().push_back(GiNaC::evalf(reader(e).subs(values)));
        }
    }
    Eigenvalues lean_steer_eigenvalues(double speed) const {
        std::vector<std::size_t> idx;
        for (const char* s : {"q2", "q5", "u2", "u5"})
            idx.push_back(static_cast<std::size_t>(std::find(states.begin(), states.end(), s) - states.begin()));
        Eigen::Matrix4d M;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                ex e = GiNaC::evalf(A.at(idx[i]).at(idx[j]).subs(v == speed));
                M(i, j) = GiNaC::ex_to<GiNaC::numeric>(e).to_double();
            }
        Eigen::EigenSolver<Eigen::Matrix4d> es(M, false);
        Eigenvalues z;
        for (int i = 0; i < 4; ++i) z.push_back(es.eigenvalues()(i));
        return sorted(z);
    }
};

// where f changes sign between lo and hi, by bisection to 1e-13
double crossing(const std::function<double(double)>& f, double lo, double hi) {
    const bool low_positive = f(lo) > 0;
    EXPECT_NE(low_positive, f(hi) > 0) << "no sign change between " << lo << " and " << hi;
    while (hi - lo > 1e-13) {
        const double mid = 0.5 * (lo + hi);
        ((f(mid) > 0) == low_positive ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

void check_sweep_against_table2(const BicycleRun& b) {
    ASSERT_EQ(b.sweep.row_count(), 11u);
    double worst = 0;
    for (const MeijaardTable2Row& row : kMeijaardTable2) {
        // the yaw, the wheels' angles, the pitch and the rear wheel's rate give exact zeros;
        // the other four are lean and steer
        Eigenvalues all = b.sweep_eigenvalues(row.v), got;
        for (const auto& z : all)
            if (z != 0.0) got.push_back(z);
        ASSERT_EQ(all.size(), 9u);
        ASSERT_EQ(got.size(), 4u) << "v = " << row.v;
        got = sorted(got);
        const Eigenvalues want = sorted({row.eig[0], row.eig[1], row.eig[2], row.eig[3]});
        for (int i = 0; i < 4; ++i) {
            worst = std::max(worst, std::abs(got[i] - want[i]));
            EXPECT_LT(std::abs(got[i] - want[i]), 1e-10)
                << "v = " << row.v << ": eigenvalue " << got[i] << ", published " << want[i];
        }
    }
    std::printf("largest difference from Table 2: %.2e\n", worst);
}

void check_speeds_from_printed_A(const BicycleRun& b) {
    // The sweep brackets both speeds between its samples ("bisection between 4 and 5 m/s");
    // inside each bracket the speed is found here by bisection on the eigenvalues of the A the
    // script printed (the linearization is the script's; the root finding is the test's)
    PrintedA A(b);
    ASSERT_EQ(A.states.size(), 9u);
    ASSERT_EQ(A.A.size(), 9u);
    // the A read back gives the sweep's eigenvalues
    for (double v : {0.0, 3.0, 7.0}) {
        Eigenvalues csv;
        for (const auto& z : b.sweep_eigenvalues(v))
            if (z != 0.0) csv.push_back(z);
        Eigenvalues printed = A.lean_steer_eigenvalues(v);
        ASSERT_EQ(csv.size(), 4u);
        csv = sorted(csv);
        for (int i = 0; i < 4; ++i) EXPECT_LT(std::abs(printed[i] - csv[i]), 1e-10) << "v = " << v;
    }
    auto bracket = [&](int n) {
        const std::string between = line_after(b.transcript, "(bisection between ", n);
        double lo = 0, hi = 0;
        EXPECT_EQ(std::sscanf(between.c_str(), "%lf and %lf", &lo, &hi), 2) << between;
        return std::pair{lo, hi};
    };
    // the weave pair's real part (the largest among complex eigenvalues) and the capsize
    // eigenvalue's (the largest real one)
    auto weave = [&](double v) {
        double re = -1e300;
        for (auto z : A.lean_steer_eigenvalues(v))
            if (std::abs(z.imag()) > 1e-9) re = std::max(re, z.real());
        return re;
    };
    auto capsize = [&](double v) {
        double re = -1e300;
        for (auto z : A.lean_steer_eigenvalues(v))
            if (std::abs(z.imag()) <= 1e-9) re = std::max(re, z.real());
        return re;
    };
    const auto [wlo, whi] = bracket(0);
    const auto [clo, chi] = bracket(1);
    const double vw = crossing(weave, wlo, whi), vc = crossing(capsize, clo, chi);
    std::printf("weave speed %.14f m/s, capsize speed %.14f m/s\n", vw, vc);
    EXPECT_NEAR(vw, kMeijaardWeaveSpeed, 1e-8);
    EXPECT_NEAR(vc, kMeijaardCapsizeSpeed, 1e-8);
}

void check_speeds_the_sweep_reports(const BicycleRun& b) {
    // What the transcript says: "a real part crosses zero at v = ...". The sweep bisects on
    // its verdict (a real part above zero_real_part_tolerance(A)), then moves the point to the
    // zero of the crossing mode's real part; before that step each speed was off by the
    // tolerance over the real part's slope (1e-5 m/s for the weave, 2.5e-4 for the capsize).
    const std::string weave = line_after(b.transcript, "a real part crosses zero at v = ", 0);
    const std::string capsize = line_after(b.transcript, "a real part crosses zero at v = ", 1);
    EXPECT_NE(weave.find("unstable below, marginally stable above"), std::string::npos) << weave;
    EXPECT_NE(capsize.find("marginally stable below, unstable above"), std::string::npos) << capsize;
    const double vw = std::stod(weave), vc = std::stod(capsize);
    std::printf("the sweep's crossings: weave %.14f m/s (%+.1e), capsize %.14f m/s (%+.1e)\n", vw,
                vw - kMeijaardWeaveSpeed, vc, vc - kMeijaardCapsizeSpeed);
    EXPECT_NEAR(vw, kMeijaardWeaveSpeed, 1e-8);
    EXPECT_NEAR(vc, kMeijaardCapsizeSpeed, 1e-8);
}

// one test: the script takes about ten seconds (most of it linearize), and each
// test case runs in a process of its own
TEST(BicycleScript, MatchesMeijaard2007) {
    BicycleRun b;
    ASSERT_EQ(b.status, RunStatus::ok) << b.err.str();
    std::printf("examples/bicycle/model.alb ran in %.1f s\n", b.seconds);
    {
        SCOPED_TRACE("the sweep's eigenvalues against Table 2");
        check_sweep_against_table2(b);
    }
    {
        SCOPED_TRACE("the weave and capsize speeds from the printed A");
        check_speeds_from_printed_A(b);
    }
    {
        SCOPED_TRACE("the weave and capsize speeds the sweep prints");
        check_speeds_the_sweep_reports(b);
    }
}

}  // namespace bicycle_script_test
