// SPDX-License-Identifier: MIT
// The equations a script's page shows, read back from the page and checked by meaning against
// the equations the script formed (numbers at random states, never the printed order): Kane's
// equations of a model in generalized speeds solved for the speeds' rates, and a statics row
// gathered by its unknown loads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "support/script_dir.hpp"

namespace report_page_equations {

namespace {

using alembert::test::digits17;
using alembert::test::read_text;
using alembert::test::ScriptInDir;
using alembert::test::TempDir;

// ---- the page's JSON ---------------------------------------------------------------------

// the JSON string that starts at page[at] (its opening quote), unescaped; `at` moves past it
std::string json_string_at(const std::string& page, std::size_t& at) {
    if (at >= page.size() || page[at] != '"') throw std::runtime_error("no string at " + std::to_string(at));
    std::string out;
    for (++at; at < page.size() && page[at] != '"'; ++at) {
        if (page[at] != '\\') {
            out += page[at];
            continue;
        }
        const char c = page[++at];
        if (c == 'n') out += '\n';
        else if (c == 't') out += '\t';
        else if (c == 'u') {
            out += static_cast<char>(std::stoi(page.substr(at + 1, 4), nullptr, 16));  // <, >, & only
            at += 4;
        } else {
            out += c;
        }
    }
    ++at;
    return out;
}

// the strings of the JSON array of strings that starts at page[at] ('[')
std::vector<std::string> json_strings_at(const std::string& page, std::size_t at) {
    std::vector<std::string> out;
    if (page.at(at) != '[') throw std::runtime_error("no array at " + std::to_string(at));
    ++at;
    while (page.at(at) != ']') {
        out.push_back(json_string_at(page, at));
        if (page.at(at) == ',') ++at;
    }
    return out;
}

// ---- the TeX of an equation read back as a script expression -------------------------------

// An equation as the page typesets it (alembert::to_latex and the report's layout: sums with
// " + " and " - ", products joined by "\,", \frac, \sqrt, powers ^{...}, \sin(...), names with
// subscripts _{...} and primes {u1}', lines after \newline naming parts "w1 = ...") read back as
// an expression in the script's syntax, with explicit parentheses. Anything else is an error.
class TexReader {
public:
    // terms written as a sum: t1 + t2 - (t3) ...
    static std::string joined(const std::vector<std::string>& terms) {
        std::string s;
        for (const std::string& t : terms)
            s += s.empty() ? t : t[0] == '-' ? " - " + t.substr(1) : " + " + t;
        return s;
    }

    struct Relation {
        std::string lhs;                 ///< the name solved for, or "0"
        std::vector<std::string> terms;  ///< the terms of the right side, "-(...)" when subtracted
        std::string rhs() const { return "(" + joined(terms) + ")"; }
    };

    static Relation read(const std::string& tex) {
        std::vector<std::string> lines;
        const std::string sep = " \\newline ";
        std::size_t start = 0;
        for (std::size_t at = tex.find(sep); at != std::string::npos; at = tex.find(sep, start)) {
            lines.push_back(tex.substr(start, at - start));
            start = at + sep.size();
        }
        lines.push_back(tex.substr(start));
        TexReader r;
        // the named parts first, each from those before it
        for (std::size_t i = 1; i < lines.size(); ++i) {
            r.s_ = lines[i];
            r.i_ = 0;
            r.eat("\\text{with }");
            const std::string name = r.name();
            r.expect("=");
            r.parts_.emplace_back(name, "(" + r.sum_text() + ")");
            r.expect_end();
        }
        r.s_ = lines.at(0);
        r.i_ = 0;
        Relation out;
        out.lhs = r.eat("0 ") ? "0" : r.primary();
        r.expect("=");
        out.terms = r.sum();
        r.expect_end();
        return out;
    }

private:
    std::string s_;
    std::size_t i_ = 0;
    std::vector<std::pair<std::string, std::string>> parts_;

    [[noreturn]] void fail(const std::string& what) const {
        throw std::runtime_error(what + " at column " + std::to_string(i_) + " of: " + s_);
    }
    void skip() {
        while (i_ < s_.size() && s_[i_] == ' ') ++i_;
    }
    bool eat(const std::string& t) {
        skip();
        if (s_.compare(i_, t.size(), t) != 0) return false;
        i_ += t.size();
        return true;
    }
    void expect(const std::string& t) {
        if (!eat(t)) fail("expected '" + t + "'");
    }
    void expect_end() {
        skip();
        if (i_ != s_.size()) fail("unread text");
    }
    bool at_letter() const { return i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_])); }

    // the terms of a sum, each with its sign ("-..." for a term subtracted)
    std::vector<std::string> sum() {
        std::vector<std::string> terms;
        std::string sign = eat("-") ? "-" : "";
        for (;;) {
            const std::string p = product();
            terms.push_back(sign.empty() ? p : "-(" + p + ")");
            if (eat("+")) sign = "";
            else if (eat("-")) sign = "-";
            else return terms;
        }
    }
    std::string sum_text() { return joined(sum()); }
    std::string product() {
        std::string p = factor();
        while (eat("\\,")) p += "*" + factor();
        return p;
    }
    std::string factor() {
        const std::string base = primary();
        if (!eat("^{")) return base;
        const std::string power = sum_text();
        expect("}");
        return base + "^(" + power + ")";
    }
    std::string group(const std::string& close) {
        const std::string s = sum_text();
        expect(close);
        return "(" + s + ")";
    }
    std::string primary() {
        if (eat("\\frac{")) {
            const std::string num = group("}");
            expect("{");
            return "(" + num + "/" + group("}") + ")";
        }
        if (eat("\\sqrt{")) return "sqrt" + group("}");
        if (eat("\\left(")) return group("\\right)");
        if (eat("(")) return group(")");
        if (eat("\\left|")) return "abs" + group("\\right|");
        if (eat("|")) return "abs" + group("|");
        for (const char* f : {"sinh", "cosh", "tanh", "sin", "cos", "tan", "exp", "log"})
            if (eat(std::string("\\") + f)) return f + arguments();
        if (eat("\\operatorname{")) {
            const std::string f = name();
            expect("}");
            return f + arguments();
        }
        if (eat("\\pi")) return "pi";
        if (eat("{")) {  // a primed name: {u1}'
            std::string n = name();
            expect("}");
            while (i_ < s_.size() && s_[i_] == '\'') n += s_[i_++];
            return n;
        }
        skip();
        if (i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.')) {
            const std::size_t from = i_;
            while (i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '.' ||
                                      s_[i_] == 'e' || ((s_[i_] == '-' || s_[i_] == '+') && s_[i_ - 1] == 'e')))
                ++i_;
            return s_.substr(from, i_ - from);
        }
        if (at_letter()) {
            const std::string n = name();
            for (const auto& [w, part] : parts_)
                if (w == n) return part;
            return n;
        }
        fail("expected a factor");
    }
    std::string arguments() {
        const bool left = eat("\\left(");
        if (!left) expect("(");
        std::string args = sum_text();
        while (eat(",")) args += ", " + sum_text();
        expect(left ? "\\right)" : ")");
        return "(" + args + ")";
    }
    // m, u1, m_{A}, ankle_{angle\_l}: the script's name
    std::string name() {
        skip();
        std::string n;
        while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) ||
                                  (s_[i_] == '\\' && i_ + 1 < s_.size() && s_[i_ + 1] == '_'))) {
            if (s_[i_] == '\\') ++i_;
            n += s_[i_++];
        }
        if (s_.compare(i_, 2, "_{") == 0) {
            i_ += 2;
            n += "_";
            while (i_ < s_.size() && s_[i_] != '}') {
                if (s_[i_] == '\\') ++i_;
                n += s_[i_++];
            }
            expect("}");
        }
        if (n.empty()) fail("expected a name");
        return n;
    }
};

// whether the script expression `e` holds the name `n` (not as part of a longer name)
bool holds_name(const std::string& e, const std::string& n) {
    const auto part = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '\''; };
    for (std::size_t at = e.find(n); at != std::string::npos; at = e.find(n, at + 1))
        if ((at == 0 || !part(e[at - 1])) && (at + n.size() == e.size() || !part(e[at + n.size()]))) return true;
    return false;
}

int terms_holding(const std::vector<std::string>& terms, const std::string& n) {
    int k = 0;
    for (const std::string& t : terms) k += holds_name(t, n) ? 1 : 0;
    return k;
}

// the number `evaluate e at values` prints (digits 17)
double value_at(ScriptInDir& r, const std::string& e, const std::string& values) {
    r.out.str("");
    // 1*(...): `evaluate (` would be read as a call of a function named evaluate
    r.run("evaluate 1*" + e + " at " + values + "\n");
    const std::string o = r.out.str();
    const std::size_t p = o.find("= ");
    if (p == std::string::npos) {
        ADD_FAILURE() << "no value for " << e << " in " << o;
        return NAN;
    }
    return std::stod(o.substr(p + 2));
}

// values for `names` in `unit`, each drawn from [-1.5, 1.5], written for a script's `at`
std::string random_values(std::mt19937& rng, const std::vector<std::string>& names, const std::string& unit) {
    std::uniform_real_distribution<double> u(-1.5, 1.5);
    std::string s;
    for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n + " = " + digits17(u(rng)) + " " + unit;
    return s;
}

// The rolling disk of examples/rolling_disk: heading q1, lean q2, spin q3, contact point at
// x, y; Kane's method with the angular velocity measures in the lean frame as speeds, the
// no-slip constraints eliminating u4 = x', u5 = y'.
const char* const kRollingDisk = R"(newtonian N
frame Y, L
body D
point P; point D_P on D
constant m = 2 kg, r = 0.3 m, g = 9.81 m/s^2
variable q1' rad, q2' rad, q3' rad, x' m, y' m
variable u1' rad/s, u2' rad/s, u3' rad/s, u4' m/s, u5' m/s
rotate Y from N about z by q1
rotate L from Y about x by q2
rotate D from L about y by q3
translate P from N_o by x*Nx> + y*Ny>
translate Dcm from P by r*Lz>
translate D_P from Dcm by -r*Lz>
velocity D_P in N from Dcm fixed on D
mass D = m
inertia D = m*r^2/4, m*r^2/2, m*r^2/4 in L
gravity -g*Nz>
w> = angvel(D, N)
kane K for q1, q2, q3, x, y speeds u1, u2, u3, u4, u5 \
  kinematics [u1 - dot(w>, Lx>), u2 - dot(w>, Ly>), u3 - dot(w>, Lz>), u4 - x', u5 - y'] \
  constraints [dot(vel(D_P, N), Nx>), dot(vel(D_P, N), Ny>)] dependent u4, u5
digits 17
report to "rep"
)";

}  // namespace

TEST(ReportPageEquations, AModelInGeneralizedSpeedsShowsKanesEquationsSolvedForTheRates) {
    TempDir dir;
    ScriptInDir r(dir.path);
    r.run(kRollingDisk);
    const std::string page = read_text(dir.path / "rep" / "index.html");
    // the note names the equations shown in place of a road-map, and says nothing of
    // declaring the coordinates with their second derivatives
    EXPECT_NE(page.find("This model is written in generalized speeds: the page shows its equations of motion "
                        "(K by Kane's method, in u1', u2', u3') below, in place of a road-map"),
              std::string::npos);
    EXPECT_EQ(page.find("with order 2"), std::string::npos);
    const std::size_t set = page.find("{\"name\":\"K\",\"method\":\"Kane's method\",\"line\":");
    ASSERT_NE(set, std::string::npos);
    const std::string key = "\"equations\":";
    const std::vector<std::string> shown = json_strings_at(page, page.find(key, set) + key.size());
    ASSERT_EQ(shown.size(), 3u) << "one equation for each independent speed";
    // each shown as u_i' = R, for a different i; K[k] with u_i' replaced by R is zero at
    // random states (K[k] is linear in u_i', with a nonzero coefficient there)
    std::vector<std::string> solved_for;
    std::mt19937 rng(20261127);
    for (std::size_t k = 0; k < shown.size(); ++k) {
        TexReader::Relation e;
        try {
            e = TexReader::read(shown[k]);
        } catch (const std::exception& x) {
            ADD_FAILURE() << x.what();
            continue;
        }
        const std::vector<std::string> rates{"u1'", "u2'", "u3'"};
        ASSERT_NE(std::find(rates.begin(), rates.end(), e.lhs), rates.end()) << shown[k];
        EXPECT_EQ(std::find(solved_for.begin(), solved_for.end(), e.lhs), solved_for.end()) << shown[k];
        solved_for.push_back(e.lhs);
        EXPECT_FALSE(holds_name(e.rhs(), e.lhs)) << shown[k];
        const std::string K = "K[" + std::to_string(k + 1) + "]";
        for (int trial = 0; trial < 3; ++trial) {
            std::vector<std::string> other_rates;
            for (const std::string& u : rates)
                if (u != e.lhs) other_rates.push_back(u);
            const std::string values = random_values(rng, {"q1", "q2", "q3"}, "rad") + ", " +
                                       random_values(rng, {"x", "y"}, "m") + ", " +
                                       random_values(rng, {"u1", "u2", "u3"}, "rad/s") + ", " +
                                       random_values(rng, {"u4", "u5"}, "m/s") + ", " +
                                       random_values(rng, other_rates, "rad/s^2");
            const double residual = value_at(r, "replace(" + K + ", " + e.lhs + " = " + e.rhs() + ")", values);
            const double coefficient = value_at(r, "coef(" + K + ", " + e.lhs + ")", values);
            const double rate = value_at(r, e.rhs(), values);
            EXPECT_GT(std::abs(coefficient), 1e-3) << K;
            EXPECT_LE(std::abs(residual), 1e-12 * std::abs(coefficient) * std::max(1.0, std::abs(rate)))
                << K << " shown as " << shown[k] << " at " << values;
        }
    }
}

TEST(ReportPageEquations, AFourBarStaticsRowIsGatheredByItsUnknownLoadsAndMeansTheRow) {
    // the four-bar of examples/four_bar_linkage held still by the crank's torque T, the
    // coupler and rocker joined by the pin force F_x Nx> + F_y Ny>
    TempDir dir;
    ScriptInDir r(dir.path);
    r.run(read_text(std::filesystem::path(ALEMBERT_SOURCE_DIR) / "examples" / "four_bar_linkage" / "model.alb") +
          "digits 17\nreport to \"rep\"\n");
    const std::string page = read_text(dir.path / "rep" / "index.html");
    const std::size_t begin = page.find("\"roadmap\":["), end = page.find("\"equation_sets\":[");
    ASSERT_NE(begin, std::string::npos);
    ASSERT_NE(end, std::string::npos);
    const std::string key = "\"equation\":";
    std::mt19937 rng(20261128);
    int rows = 0, gathered = 0;
    for (std::size_t at = page.find(key, begin); at < end; at = page.find(key, at)) {
        at += key.size();
        const std::string tex = json_string_at(page, at);
        ++rows;
        TexReader::Relation e;
        try {
            e = TexReader::read(tex);
        } catch (const std::exception& x) {
            ADD_FAILURE() << x.what();
            continue;
        }
        // each unknown load in one term at most (or alone on the left)
        for (const char* load : {"T", "F_x", "F_y"})
            EXPECT_LE(terms_holding(e.terms, load) + (e.lhs == load ? 1 : 0), 1) << load << " in " << tex;
        if (terms_holding(e.terms, "F_x") == 1 && terms_holding(e.terms, "F_y") == 1) ++gathered;
        // the row as formed, S[k]: equal to the right side of 0 = ..., or zero with the
        // solved-for unknown replaced by the right side of x = ...
        const std::string S = "S[" + std::to_string(rows) + "]";
        for (int trial = 0; trial < 3; ++trial) {
            const std::string values = random_values(rng, {"qA", "qB", "qC"}, "rad") + ", " +
                                       random_values(rng, {"T"}, "N*m") + ", " +
                                       random_values(rng, {"F_x", "F_y"}, "N");
            const double shown = value_at(r, e.rhs(), values), formed = value_at(r, S, values);
            if (e.lhs == "0") {
                EXPECT_NEAR(shown, formed, 1e-12 * std::max({1.0, std::abs(shown), std::abs(formed)}))
                    << S << " shown as " << tex << " at " << values;
                continue;
            }
            const double residual = value_at(r, "replace(" + S + ", " + e.lhs + " = " + e.rhs() + ")", values);
            const double coefficient = value_at(r, "coef(" + S + ", " + e.lhs + ")", values);
            EXPECT_GT(std::abs(coefficient), 1e-3) << S;
            EXPECT_LE(std::abs(residual), 1e-12 * std::abs(coefficient) * std::max(1.0, std::abs(shown)))
                << S << " shown as " << tex << " at " << values;
        }
    }
    EXPECT_EQ(rows, 5) << "a row for each of T, F_x, F_y, qB, qC";
    EXPECT_GE(gathered, 1) << "a row with F_x in one term of its right side and F_y in one";
}

}  // namespace report_page_equations
