// SPDX-License-Identifier: MIT
// Linearization: `linearize` about an operating point, with eigenvalues and a stability
// verdict, the second-order form, a pole-placing gain and a sweep over a constant: its
// meaning, then its grammar and table (linearize_statements()).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "alembert/lang/parser.hpp"
#include "alembert/sym/cse.hpp"
#include "interpreter_impl.hpp"
#include "statement_parser.hpp"

namespace alembert::lang {

namespace {

using Kind = Value::Kind;

bool linearize_contains(const std::vector<ex>& list, const ex& x) {
    return std::any_of(list.begin(), list.end(), [&](const ex& y) { return y.is_equal(x); });
}

std::string linearize_name_list(const SymbolTable& table, const std::vector<ex>& xs) {
    std::string out;
    for (std::size_t i = 0; i < xs.size(); ++i) out += (i ? ", " : "") + table.name(xs[i]);
    return out;
}

// a symbolic matrix as rows "  [a, b, c]"
std::string linearize_matrix_text(const GiNaC::matrix& A) {
    std::string out;
    for (unsigned i = 0; i < A.rows(); ++i) {
        out += "  [";
        for (unsigned j = 0; j < A.cols(); ++j) out += (j ? ", " : "") + to_string(A(i, j));
        out += "]\n";
    }
    return out;
}

// a complex number as the transcript prints numbers: a, b*i, a + b*i
std::string linearize_vector_text(const Transcript& t, const Eigen::VectorXd& v) {
    std::string out;
    for (Eigen::Index i = 0; i < v.size(); ++i) out += (i ? ", " : "") + t.number(v(i));
    return out;
}

std::string complex_text(const Transcript& t, std::complex<double> z) {
    const std::string re = t.number(z.real()), im = t.number(std::abs(z.imag()));
    if (im == "0") return re;
    const std::string sign = z.imag() < 0 ? "-" : "+";
    if (re == "0") return (sign == "-" ? "-" : "") + im + "i";
    return re + " " + sign + " " + im + "i";
}

// the numbers of a symbolic matrix with the constants' values and `extra`
Eigen::MatrixXd linearize_numbers(const SymbolTable& table, const GiNaC::matrix& A, const exmap& extra) {
    Eigen::MatrixXd out(A.rows(), A.cols());
    for (unsigned i = 0; i < A.rows(); ++i)
        for (unsigned j = 0; j < A.cols(); ++j) out(i, j) = table.evaluate(A(i, j), extra);
    return out;
}

// eigenvalues, eigenvectors over the states and the verdict, as the transcript prints them
std::string eigen_text(const Transcript& t, const SymbolTable& table, const std::vector<ex>& states,
                       const Eigen::MatrixXd& A, const std::string& title) {
    EigenAnalysis e = calc_eigen(A);
    const double tol = zero_real_part_tolerance(A);
    std::ostringstream out;
    out << title << " (1/s) and eigenvectors over (" << linearize_name_list(table, states) << "):\n";
    std::vector<std::string> texts;
    std::size_t width = 0;
    for (const auto& l : e.values) {
        texts.push_back(complex_text(t, l));
        width = std::max(width, texts.back().size());
    }
    for (std::size_t k = 0; k < e.values.size(); ++k) {
        out << "  lambda" << k + 1 << " = " << texts[k] << std::string(width - texts[k].size(), ' ') << "  (";
        for (Eigen::Index i = 0; i < e.vectors.rows(); ++i)
            out << (i ? ", " : "") << complex_text(t, e.vectors(i, static_cast<Eigen::Index>(k)));
        out << ")\n";
    }
    switch (classify_stability(e.values, tol)) {
        case Stability::unstable: {
            out << "unstable: lambda1 = " << texts[0] << " has a positive real part";
            break;
        }
        case Stability::asymptotically_stable:
            out << "asymptotically stable: every real part is negative (the largest is "
                << t.number(e.values.empty() ? 0.0 : e.values[0].real()) << ")";
            break;
        case Stability::marginal: {
            std::size_t on_axis = 0;
            for (const auto& l : e.values) on_axis += std::abs(l.real()) <= tol ? 1 : 0;
            out << "marginally stable to first order: no real part is positive, " << on_axis
                << " on the imaginary axis (within " << t.number(tol)
                << "); the linearization does not decide stability";
            break;
        }
    }
    return out.str();
}

void run_linearize(Interpreter::Impl& m, const Statement& s) {
    System& sys = m.model(s.location);
    const SymbolTable& table = sys.symbols();
    const Word& n = s.word("name");
    StepIndicator busy("linearize " + n.text);

    // ---- the equations: formed by kane or lagrange, and still what the name holds
    auto formed = m.formed.find(n.text);
    auto held = m.values.find(n.text);
    bool current = formed != m.formed.end() && held != m.values.end() && held->second.kind == Kind::array &&
                   held->second.a.size() == formed->second.residuals.size();
    for (std::size_t i = 0; current && i < held->second.a.size(); ++i)
        current = held->second.a[i].is_equal(formed->second.residuals[i]);
    if (!current)
        throw ScriptError(n.location, "'" + n.text + "' holds no equations of motion formed by kane or lagrange",
                          "form them first: kane " + n.text + " for q1, q2 (or lagrange " + n.text + " for q1, q2)");
    const FormedEquations& fe = formed->second;
    FirstOrderEquations f = m.guard(n.location, [&] {
        return fe.kane ? to_first_order(*fe.kane) : to_first_order(fe.residuals, fe.coordinates);
    });

    // ---- inputs and the operating point (states not given: 0; loads not given: 0)
    LinearizeOptions o;
    if (s.lists.count("inputs")) {
        Interpreter::Impl::require_each_once(s.lists.at("inputs"), "input");
        for (const Word& w : s.lists.at("inputs")) {
            ex r = m.symbol(w, "an input");
            SymbolKind k = table.kind(r);
            if (!(k == SymbolKind::unknown || (k == SymbolKind::specified && table.derivative_order(r) == 0)))
                throw ScriptError(w.location, "'" + w.text + "' is not an input: inputs are load measures or specified quantities",
                                  "declare it with 'unknown' and use it in a force or torque (unknown F N)");
            o.inputs.push_back(r);
        }
    }
    exmap op;
    std::string given;
    for (const Binding& b : s.bindings.at("at")) {
        ex x = m.symbol(b.name, "a state or an input");
        SymbolKind k = table.kind(x);
        if (!linearize_contains(f.states, x) && k != SymbolKind::unknown && k != SymbolKind::specified)
            throw ScriptError(b.name.location, "'" + b.name.text + "' is not a state of " + n.text,
                              "give values to its states (" + linearize_name_list(table, f.states) + ") and inputs");
        if (op.count(x))
            throw ScriptError(b.name.location, "'" + b.name.text + "' is given twice", "give each value once");
        ex value = m.quantity_expression(b.quantity, m.symbol_dimension(b.name.text), "the value of " + b.name.text);
        for (const ex& v : table.symbols(SymbolKind::variable))
            if (table.depends_on(value, v))
                throw ScriptError(b.quantity.value->location,
                                  "the value of " + b.name.text + " holds the variable " + table.name(v),
                                  "give numbers or constants (a constant can be swept with for)");
        op[x] = value;
        given += (given.empty() ? "" : ", ") + b.name.text + " = " + to_string(value);
    }
    std::vector<ex> zeroed;
    for (const ex& x : f.states)
        if (!op.count(x)) op[x] = 0, zeroed.push_back(x);
    for (const ex& u : table.symbols(SymbolKind::unknown))
        if (!op.count(u)) op[u] = 0;
    for (const ex& r : o.inputs)
        if (!op.count(r)) op[r] = 0;
    if (s.has_word("parameter") && count_ops_with_intermediates(table, f.residuals) > m.print_limit) {
        // a sweep of equations too large to print (past --print-limit): the constants other
        // than the swept one take their values before linearizing, so A is formed in numbers
        // and the swept constant alone (kept symbolic in all 26 constants of a bicycle, solving
        // for the rates took a minute and a half); smaller models keep A symbolic
        const ex swept = m.symbol(s.word("parameter"), "a constant");
        exmap values;
        for (const ex& c : table.symbols(SymbolKind::constant))
            if (!c.is_equal(swept) && !op.count(c))
                if (const auto value = table.value(c)) values[c] = GiNaC::numeric(*value);
        for (auto& [x, v] : op) v = v.subs(values, GiNaC::subs_options::no_pattern);  // u3 = v/r_R
        op.insert(values.begin(), values.end());
    }
    o.operating_point = op;
    LinearizedEquations lin = m.guard(n.location, [&] { return linearize(table, f, o); },
                                      "choose another operating point, or other coordinates");

    // ---- A and B, and the rates at a steady motion
    std::ostringstream out;
    out << n.text << " linearized at " << given;
    if (!zeroed.empty()) out << " (and " << linearize_name_list(table, zeroed) << " = 0)";
    out << "\nstates (" << linearize_name_list(table, lin.states) << ")"
        << (o.inputs.empty() ? "" : ", inputs (" + linearize_name_list(table, o.inputs) + ")")
        << ": d/dt dx = A dx" << (o.inputs.empty() ? "" : " + B dr") << "\n";
    // the rates at the operating point: of coordinates only (a steady motion), or of speeds too
    std::vector<ex> speeds;
    if (fe.kane) speeds = fe.kane->independent_speeds;
    else
        for (const TimeVariable& q : fe.coordinates) speeds.push_back(q.d(1));
    std::string rates;
    bool accelerating = false;
    for (std::size_t i = 0; i < lin.states.size(); ++i)
        if (!lin.operating_rates[i].is_zero()) {
            rates += (rates.empty() ? "" : ", ") + table.name(f.rates[i]) + " = " + to_string(lin.operating_rates[i]);
            accelerating = accelerating || linearize_contains(speeds, lin.states[i]);
        }
    if (!rates.empty())
        out << (accelerating ? "not an equilibrium or a steady motion: " : "a steady motion: ") << rates << "\n";
    out << "A =\n" << linearize_matrix_text(lin.A);
    if (!o.inputs.empty()) out << "B =\n" << linearize_matrix_text(lin.B);

    // ---- the second-order form
    if (s.flag("second")) {
        if (fe.kane)
            throw ScriptError(s.word("second").location,
                              "the second-order form needs equations in the coordinates' second derivatives; " +
                                  n.text + " has chosen speeds",
                              "form them with kane " + n.text + " for q1, q2 (no speeds) or lagrange");
        SecondOrderLinearization so = m.guard(n.location, [&] {
            return linearize_second_order(table, fe.residuals, fe.coordinates, o);
        });
        out << "M q'' + C q' + K q = " << (o.inputs.empty() ? "0" : "H r") << ", q = ("
            << linearize_name_list(table, so.coordinates) << ")\n";
        out << "M (mass) =\n" << linearize_matrix_text(so.M) << "C (damping, gyroscopic) =\n"
            << linearize_matrix_text(so.C) << "K (stiffness) =\n" << linearize_matrix_text(so.K);
        if (!o.inputs.empty()) out << "H (input) =\n" << linearize_matrix_text(so.H);
    }

    const std::string no_value_hint = "give every constant a value (constant c = 2 kg) or sweep it with for";
    if (!s.has_word("parameter")) {
        // ---- eigenvalues at the constants' values
        Eigen::MatrixXd A = m.guard(n.location, [&] { return linearize_numbers(table, lin.A, {}); }, no_value_hint);
        out << m.guard(n.location, [&] { return eigen_text(m.transcript, table, lin.states, A, "eigenvalues"); });

        // ---- a gain that places the poles
        if (s.expr_lists.count("poles")) {
            const Word& g = s.word("gains");
            if (o.inputs.size() != 1)
                throw ScriptError(g.location, "pole placement needs exactly one input, not " + std::to_string(o.inputs.size()),
                                  "name the input: inputs F");
            auto it = m.names.find(g.text);
            if (is_reserved(g.text) || (it != m.names.end() && it->second.kind != NameKind::value))
                throw ScriptError(g.location, "'" + g.text + "' cannot name the gains", "choose another name");
            std::vector<std::complex<double>> poles;
            for (const ExprPtr& e : s.expr_lists.at("poles")) {
                Value v = m.eval(*e);
                ex x = GiNaC::evalf(v.s);
                if (v.kind != Kind::scalar || !GiNaC::is_a<GiNaC::numeric>(x) || !GiNaC::ex_to<GiNaC::numeric>(x).is_real())
                    throw ScriptError(e->location, "a pole must be a real number (in 1/s)", "write poles -2, -3, -4, -5");
                poles.emplace_back(GiNaC::ex_to<GiNaC::numeric>(x).to_double(), 0.0);
            }
            if (poles.size() != lin.states.size())
                throw ScriptError(s.expr_lists.at("poles").front()->location,
                                  std::to_string(poles.size()) + " poles for " + std::to_string(lin.states.size()) + " states",
                                  "give one pole per state (" + linearize_name_list(table, lin.states) + ")");
            Eigen::MatrixXd B = m.guard(n.location, [&] { return linearize_numbers(table, lin.B, {}); }, no_value_hint);
            Eigen::RowVectorXd k = m.guard(g.location, [&] { return place_poles(A, B.col(0), poles); });
            std::vector<ex> gains;
            std::string law;
            out << "\n" << g.text << " = [";
            for (Eigen::Index i = 0; i < k.size(); ++i) {
                gains.push_back(k(i));
                out << (i ? ", " : "") << m.transcript.number(k(i));
                law += (i ? " + " : "") + g.text + "[" + std::to_string(i + 1) + "]*" + table.name(lin.states[static_cast<std::size_t>(i)]);
            }
            out << "]: " << table.name(o.inputs[0]) << " = -(" << law << ") places the poles (Ackermann's formula)\n";
            Value gv;
            gv.kind = Kind::array;
            gv.a = gains;
            m.values[g.text] = gv;
            m.names[g.text] = {NameKind::value, g.location};
            Eigen::MatrixXd closed = A - B.col(0) * k;
            out << m.guard(g.location, [&] {
                return eigen_text(m.transcript, table, lin.states, closed, "closed-loop eigenvalues");
            });
        }
        // ---- the linear-quadratic regulator's gain
        if (s.expr_lists.count("lqr")) {
            const Word& g = s.word("gains");
            if (o.inputs.empty())
                throw ScriptError(s.word("lqr").location, "the regulator needs inputs", "name them: inputs F");
            auto it = m.names.find(g.text);
            if (is_reserved(g.text) || (it != m.names.end() && it->second.kind != NameKind::value))
                throw ScriptError(g.location, "'" + g.text + "' cannot name the gains", "choose another name");
            auto weights = [&](const char* role, std::size_t count, const std::string& what, bool strict) {
                const auto& list = s.expr_lists.at(role);
                if (list.size() != count)
                    throw ScriptError(list.front()->location,
                                      std::to_string(list.size()) + " " + what + " weights for " + std::to_string(count) +
                                          " " + what + "s",
                                      "give one weight per " + what + (std::string(role) == "lqr"
                                                                           ? " (" + linearize_name_list(table, lin.states) + ")"
                                                                           : " (" + linearize_name_list(table, o.inputs) + ")"));
                Eigen::VectorXd w(static_cast<Eigen::Index>(count));
                for (std::size_t i = 0; i < count; ++i) {
                    Value v = m.eval(*list[i]);
                    if (v.kind != Kind::scalar)
                        throw ScriptError(list[i]->location, "a weight must be a number", "write lqr 10, 100, 1, 1 and 0.1");
                    double d = m.guard(list[i]->location, [&] { return table.evaluate(v.s); },
                                       "a weight is a number, or constants with values");
                    if (strict ? !(d > 0) : !(d >= 0))
                        throw ScriptError(list[i]->location,
                                          "a weight on " + std::string(strict ? "an input must be greater than 0" : "a state must be 0 or more"),
                                          strict ? "give each input a positive weight" : "give each state a weight >= 0");
                    w(static_cast<Eigen::Index>(i)) = d;
                }
                return w;
            };
            const Eigen::VectorXd q = weights("lqr", lin.states.size(), "state", false);
            const Eigen::VectorXd r = weights("lqr_inputs", o.inputs.size(), "input", true);
            Eigen::MatrixXd B = m.guard(n.location, [&] { return linearize_numbers(table, lin.B, {}); }, no_value_hint);
            Eigen::MatrixXd Q = q.asDiagonal(), R = r.asDiagonal();
            LqrSolution lqr = m.guard(g.location, [&] { return solve_lqr(A, B, Q, R); });
            std::vector<ex> gains;
            out << "\n" << g.text << " = [";
            for (Eigen::Index i = 0; i < lqr.K.rows(); ++i)
                for (Eigen::Index j = 0; j < lqr.K.cols(); ++j) {
                    gains.push_back(lqr.K(i, j));
                    out << (j ? ", " : i ? "; " : "") << m.transcript.number(lqr.K(i, j));
                }
            out << "]: ";
            const std::size_t ns = lin.states.size();
            for (std::size_t i = 0; i < o.inputs.size(); ++i) {
                std::string law;
                for (std::size_t j = 0; j < ns; ++j)
                    law += (j ? " + " : "") + g.text + "[" + std::to_string(i * ns + j + 1) + "]*" + table.name(lin.states[j]);
                out << (i ? ", " : "") << table.name(o.inputs[i]) << " = -(" << law << ")";
            }
            // the residual's order of magnitude
            // (1e-12 or its order above that), so transcripts do not carry round-off digits
            const int bound = static_cast<int>(std::ceil(std::log10(std::max(lqr.relative_residual, 1e-12))));
            out << " minimises the integral of x^T Q x + r^T R r (Q = diag(" << linearize_vector_text(m.transcript, q)
                << "), R = diag(" << linearize_vector_text(m.transcript, r)
                << ")); the Riccati equation A^T P + P A - P B R^-1 B^T P + Q = 0 holds to 1e" << bound
                << " relative\n";
            Value gv;
            gv.kind = Kind::array;
            gv.a = gains;
            m.values[g.text] = gv;
            m.names[g.text] = {NameKind::value, g.location};
            Eigen::MatrixXd closed = A - B * lqr.K;
            out << m.guard(g.location, [&] {
                return eigen_text(m.transcript, table, lin.states, closed, "closed-loop eigenvalues");
            });
        }
        m.transcript.result(out.str());
        return;
    }

    // ---- a sweep over a constant: eigenvalues to CSV and a plot, and where stability changes
    const Word& pw = s.word("parameter");
    ex p = m.symbol(pw, "a constant");
    if (table.kind(p) != SymbolKind::constant)
        throw ScriptError(pw.location, "'" + pw.text + "' is not a constant; a sweep varies a constant",
                          "declare it with constant " + pw.text + " and use it in the model or after at");
    const Dimension d = m.symbol_dimension(pw.text);
    auto value_of = [&](const char* role, const std::string& what) {
        const Quantity& q = s.quantities.at(role);
        double x = m.number_of(q, d, what, q.value->location);
        if (!std::isfinite(x)) throw ScriptError(q.value->location, what + " must be finite", "");
        return x;
    };
    const double from = value_of("from", "the first value of " + pw.text), to = value_of("to", "the last value of " + pw.text),
                 step = value_of("step", "the step of " + pw.text);
    const Quantity& sq = s.quantities.at("step");
    if (!(step > 0) || !(to > from))
        throw ScriptError(sq.value->location, "a sweep goes up from its first value to its last in positive steps",
                          "write for " + pw.text + " = 0 to 10 step 0.5");
    const double count = std::floor((to - from) / step * (1 + 1e-12)) + 1;
    if (count > 10001)
        throw ScriptError(sq.value->location, "the sweep has " + format_number(count) + " values, more than 10001",
                          "take a larger step");
    std::vector<double> samples;
    for (int i = 0; i < static_cast<int>(count); ++i) samples.push_back(from + i * step);
    auto A_of = [&](double v) { return linearize_numbers(table, lin.A, {{p, v}}); };
    std::optional<Unit> shown = m.display_unit(pw.text);
    const double scale = shown ? shown->scale : 1.0;
    const std::string unit = shown ? " " + shown->text : "";

    Table t;
    const std::size_t N = lin.states.size();
    t.add_column(pw.text, shown ? shown->text : "");
    PlotOptions plot_options{.title = "real parts of the eigenvalues of " + n.text + " against " + pw.text};
    for (std::size_t k = 0; k < N; ++k) {
        t.add_column("re_" + std::to_string(k + 1), "1/s");
        plot_options.y.push_back("re_" + std::to_string(k + 1));
    }
    for (std::size_t k = 0; k < N; ++k) t.add_column("im_" + std::to_string(k + 1), "1/s");
    std::vector<bool> unstable_at;
    m.guard(pw.location, [&] {
        for (double v : samples) {
            Eigen::MatrixXd A = A_of(v);
            EigenAnalysis e = calc_eigen(A);
            unstable_at.push_back(classify_stability(e.values, zero_real_part_tolerance(A)) == Stability::unstable);
            t.columns[0].push_back(v / scale);
            for (std::size_t k = 0; k < N; ++k) {
                t.columns[1 + k].push_back(e.values[k].real());
                t.columns[1 + N + k].push_back(e.values[k].imag());
            }
        }
    }, no_value_hint);
    out << "swept " << pw.text << " = " << m.transcript.number(from / scale) << " to " << m.transcript.number(to / scale)
        << unit << " in steps of " << m.transcript.number(step / scale) << unit << " (" << samples.size() << " values)";
    std::string written;  // the table's file, for the report's plot of the sweep
    if (!m.model_only) {
        const std::string dir = m.output_path(s);
        PlotResult plot = m.guard(s.location, [&] { return write_table_and_plot(t, dir, "eigenvalues", plot_options); });
        written = (std::filesystem::path(dir) / "eigenvalues.csv").string();
        out << "\nwrote eigenvalues.csv";
        for (const std::string& file : plot.files) out << ", " << std::filesystem::path(file).filename().string();
        if (!plot.drawn) out << " (no plot: " << plot.message << ")";
    }
    std::vector<std::string> axes(N, "real part");
    axes.insert(axes.end(), N, "imaginary part");
    m.record_sweep("linearize", s.location.line, written, t, std::move(axes));
    std::vector<StabilityChange> changes = m.guard(pw.location, [&] { return find_stability_changes(A_of, samples); });
    if (changes.empty())
        out << "\n" << (unstable_at.front() ? "unstable" : "not unstable") << " throughout: no real part crosses zero";
    for (const StabilityChange& c : changes) {
        // the verdict on the side that is not unstable, from the sample nearest that side
        std::size_t i = 0;
        while (i + 1 < samples.size() && samples[i + 1] <= c.at) ++i;
        const double other = c.becomes_unstable ? samples[i] : samples[std::min(i + 1, samples.size() - 1)];
        Eigen::MatrixXd A = A_of(other);
        const char* calm = classify_stability(calc_eigen(A).values, zero_real_part_tolerance(A)) == Stability::marginal
                               ? "marginally stable" : "asymptotically stable";
        out << "\na real part crosses zero at " << pw.text << " = " << m.transcript.number(c.at / scale) << unit << ": "
            << (c.becomes_unstable ? std::string(calm) + " below, unstable above"
                                   : std::string("unstable below, ") + calm + " above")
            << " (bisection between " << m.transcript.number(samples[i] / scale) << " and "
            << m.transcript.number(samples[std::min(i + 1, samples.size() - 1)] / scale) << unit << ")";
    }
    m.transcript.result(out.str());
}

void parse_linearize(StatementParser& p, Statement& s) {
    s.words["name"] = p.name("the equations to linearize (formed by kane or lagrange)");
    p.expect_word("at", "and the operating point (linearize K at q = 0, q' = 0)");
    s.bindings["at"] = p.bindings("a state or an input (linearize K at q = 0, q' = 0)");
    while (!p.at_end()) {
        if (p.accept_word("inputs")) {
            s.lists["inputs"] = p.name_list("an input (a load measure)");
        } else if (p.at_word("second")) {
            s.words["second"] = p.take_word();
            p.expect_word("order", "(second order)");
            s.flags["second"] = true;
        } else if (p.at_word("poles")) {
            s.words["poles"] = p.take_word();
            s.expr_lists["poles"] = p.expression_list();
            p.expect_word("gains", "and a name for the gains (poles -2, -3, -4, -5 gains G)");
            s.words["gains"] = p.name("a name for the gains");
        } else if (p.at_word("lqr")) {
            s.words["lqr"] = p.take_word();
            s.expr_lists["lqr"] = p.expression_list();
            p.expect_word("and", "and the input weights (lqr 10, 100, 1, 1 and 0.1 gains G)");
            s.expr_lists["lqr_inputs"] = p.expression_list();
            p.expect_word("gains", "and a name for the gains (lqr 10, 100, 1, 1 and 0.1 gains G)");
            s.words["gains"] = p.name("a name for the gains");
        } else if (p.accept_word("for")) {
            s.words["parameter"] = p.name("a constant to sweep");
            p.expect_punct("=", "and its range (for Omega = 0 to 10 step 0.5)");
            s.quantities["from"] = p.quantity();
            p.expect_word("to", "and the last value (for Omega = 0 to 10 step 0.5)");
            s.quantities["to"] = p.quantity();
            p.expect_word("step", "and the step (for Omega = 0 to 10 step 0.5)");
            s.quantities["step"] = p.quantity();
        } else if (p.accept_word("to")) {
            s.words["to"] = p.text("the output directory");
        } else {
            p.fail_expected("'inputs', 'second order', 'poles', 'lqr', 'for' or 'to'");
        }
    }
    if (s.expr_lists.count("poles") && s.expr_lists.count("lqr"))
        throw ScriptError(s.word("lqr").location, "one gain per statement: poles or lqr, not both",
                          "linearize once with poles, and again with lqr");
    if (s.expr_lists.count("lqr") && s.words.count("parameter"))
        throw ScriptError(s.word("lqr").location, "a gain is computed at one operating point, not over a sweep",
                          "linearize once with lqr, and sweep in another statement");
    if (s.expr_lists.count("poles") && s.words.count("parameter"))
        throw ScriptError(s.word("poles").location, "a gain is placed at one operating point, not over a sweep",
                          "linearize once with poles, and sweep in another statement");
}

}  // namespace

// ---- the statements ----------------------------------------------------------------------

std::vector<StatementSpec> linearize_statements() {
    const std::string_view family = "Linearization";
    return {
        {.keyword = "linearize", .family = family,
         .help = "linearizes equations of motion about an operating point: A, B, eigenvalues, stability",
         .forms = {{"`linearize` *K* `at` *state = value, ...* [`inputs` *r...*] [`second order`]",
                    "linearize K at x = 0, th = 0, x' = 0, th' = 0 inputs F",
                    "`to_first_order` + `linearize`, then `calc_eigen`: prints A, B (M, C, K, H with `second order`), eigenvalues and eigenvectors, and a stability verdict (states not given are 0)"},
                   {"`linearize` *K* `at` ... `inputs` *r* `poles` *p1, ..., pn* `gains` *G*",
                    "linearize K at th = 0 inputs F poles -2, -3, -4, -5 gains G",
                    "`place_poles` (Ackermann's formula): G such that r = -(G[1]*x1 + ...) places the poles; prints the closed-loop eigenvalues"},
                   {"`linearize` *K* `at` ... `inputs` *r...* `lqr` *q1, ..., qn* `and` *r1, ..., rm* `gains` *G*",
                    "linearize K at th = 0 inputs F lqr 10, 100, 1, 1 and 0.1 gains G",
                    "`solve_lqr` (the Riccati equation's stable solution, residual checked): G minimising the integral of x^T Q x + r^T R r with Q, R diagonal (weights in the states' and inputs' SI units); r_i = -(G[(i-1)n+1]*x1 + ...); prints the closed-loop eigenvalues"},
                   {"`linearize` *K* `at` ... `for` *c* `=` *a* `to` *b* `step` *h* [`to` *\"dir\"*]",
                    "linearize K at q2 = 0, u1 = 0, u2 = Omega, u3 = 0 for Omega = 0 to 10 step 0.5",
                    "a sweep of the constant c: `eigenvalues.csv` (real and imaginary parts), a plot of the real parts, and the values of c where a real part crosses zero (`find_stability_changes`: bisection)"}},
         .clauses = {"at", "inputs", "second", "poles", "lqr", "and", "gains", "for", "step", "to"},
         .parse = parse_linearize, .run = run_linearize},
    };
}

}  // namespace alembert::lang
