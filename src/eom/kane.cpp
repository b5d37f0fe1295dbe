// SPDX-License-Identifier: MIT
// Kane's method: partial velocities, generalized active and inertia forces; chosen speeds,
// motion constraints (Kane's elimination) and auxiliary speeds.
#include "alembert/eom/kane.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <numeric>
#include <string>

#include "alembert/eom/inertia_forces.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/simplify.hpp"
#include "expression_lists.hpp"

namespace alembert {

namespace {

// generalized forces of the loads (all of them, or only those without a potential)
std::vector<ex> active_forces(const System& sys, const std::vector<TimeVariable>& q,
                              bool include_gravity, bool include_conservative) {
    const Frame& N = sys.newtonian();
    std::vector<ex> F(q.size(), 0);
    std::map<const Point*, Vector> v;
    std::map<const Frame*, Vector> w;
    auto vel = [&](const Point* P) -> const Vector& {
        auto it = v.find(P);
        return it != v.end() ? it->second : v.emplace(P, P->vel_in(N)).first->second;
    };
    auto angvel = [&](const Frame* B) -> const Vector& {
        auto it = w.find(B);
        return it != w.end() ? it->second : w.emplace(B, B->ang_vel_in(N)).first->second;
    };
    for (const Load& l : sys.loads()) {
        if (l.conservative && !include_conservative) continue;
        for (std::size_t r = 0; r < q.size(); ++r) {
            const ex& u = q[r].d(1);
            if (l.kind == LoadKind::force) {
                F[r] += dot(vel(l.point).diff(u), l.vector);
            } else if (l.on->frame()) {
                F[r] += dot(angvel(l.on->frame()).diff(u), l.vector);
            }
        }
    }
    if (include_gravity && !sys.gravity().is_zero())
        for (const Body* b : sys.bodies())
            for (std::size_t r = 0; r < q.size(); ++r)
                F[r] += dot(vel(&b->cm()).diff(q[r].d(1)), b->mass() * sys.gravity());
    return F;
}

}  // namespace

std::vector<ex> form_generalized_active_forces(const System& sys,
                                               const std::vector<TimeVariable>& q,
                                               LoadSelection which) {
    bool all = which == LoadSelection::all;
    return active_forces(sys, q, all, all);
}

std::vector<ex> form_kane_equations(const System& sys, const std::vector<TimeVariable>& q) {
    detail::require_distinct_coordinates(q, "form_kane_equations()");
    const Frame& N = sys.newtonian();
    std::vector<ex> E = active_forces(sys, q, true, true);
    for (const Body* b : sys.bodies()) {
        InertiaLoads star = calc_inertia_loads(*b, N);
        Vector v = b->cm().vel_in(N);
        Vector w = b->frame() ? b->frame()->ang_vel_in(N) : Vector();
        for (std::size_t r = 0; r < q.size(); ++r) {
            const ex& u = q[r].d(1);
            E[r] += dot(v.diff(u), star.force);
            if (!star.torque.is_zero()) E[r] += dot(w.diff(u), star.torque);
        }
    }
    return E;
}

// ======================================================================================
// Kane's method with chosen speeds, motion constraints and auxiliary speeds
// ======================================================================================

namespace {

using GiNaC::is_a;
using detail::contains;
using detail::index_of;

const std::string kFn = "form_kane_equations(): ";

std::string name_of(const SymbolTable& st, const ex& s) {
    return st.owns(s) ? st.name(s) : to_string(s);
}

std::string quoted_list(const SymbolTable& st, const std::vector<ex>& xs) {
    std::string out;
    for (const ex& x : xs) out += (out.empty() ? "'" : ", '") + name_of(st, x) + "'";
    return out;
}

std::string to_string_list(const std::vector<ex>& xs) {
    std::string out;
    for (const ex& x : xs) out += (out.empty() ? "'" : ", '") + to_string(x) + "'";
    return out;
}

// the symbol must be a time-varying variable of the table; `role` names it in messages
void require_variable(const SymbolTable& st, const ex& s, const std::string& role) {
    if (!is_a<GiNaC::symbol>(s) || !st.owns(s) || st.kind(s) != SymbolKind::variable)
        throw ArgumentError(kFn + role + " '" + to_string(s) +
                            "' is not a variable of the model's symbol table; declare it with "
                            "SymbolTable::add_variable()");
}

// q -> q', u -> u': the next declared derivative of a variable
ex rate_of(const SymbolTable& st, const ex& s, const std::string& role) {
    require_variable(st, s, role);
    TimeVariable tv = st.variable(st.name(st.base(s)));
    int k = st.derivative_order(s);
    if (tv.order() < k + 1)
        throw ModelError(kFn + "the time derivative of " + role + " '" + st.name(s) +
                         "' is not declared; declare it with SymbolTable::add_variable(\"" +
                         tv.name() + "\", " + std::to_string(k + 1) + ") or a higher order");
    return tv.d(k + 1);
}

void require_distinct(const SymbolTable& st, const std::vector<ex>& xs, const std::string& list) {
    for (std::size_t i = 0; i < xs.size(); ++i)
        for (std::size_t j = i + 1; j < xs.size(); ++j)
            if (xs[i].is_equal(xs[j]))
                throw ArgumentError(kFn + "'" + name_of(st, xs[i]) + "' is listed twice in " +
                                    list + "; list it once");
}

// `e` with the replacements `m` applied. An intermediate z whose definition depends on a
// replaced symbol is redefined once per substitution (memoized), as a new intermediate
// z~ = definition(z) with `m` applied, instead of expanding every intermediate into the
// expression: a chain of intermediates (velocities and their rates, the dependent speeds
// solved by elimination) then substitutes in time linear in its length. Redefinitions that
// hold solve-level symbols (accelerations) keep them explicit (SymbolTable::name_if_large).
class Substitution {
public:
    Substitution(SymbolTable& st, const exmap& m) : st_(st), m_(m) {
        for (const auto& kv : m_) keys_.push_back(kv.first);
    }
    ex operator()(const ex& e) {
        if (m_.empty()) return e;
        exmap z_map = m_;
        bool changed = false;
        for (const ex& s : symbols_of(e)) {
            if (m_.count(s)) changed = true;
            if (!st_.owns(s) || st_.kind(s) != SymbolKind::intermediate) continue;
            ex r = redefine(s);
            if (!r.is_equal(s)) {
                z_map[s] = r;
                changed = true;
            }
        }
        return changed ? e.subs(z_map, GiNaC::subs_options::no_pattern) : e;
    }
    Vector operator()(const Vector& v) {
        if (m_.empty()) return v;
        return v.map([&](const ex& e) { return (*this)(e); });
    }

private:
    ex redefine(const ex& z) {
        auto it = memo_.find(z);
        if (it != memo_.end()) return it->second;
        bool depends = false;
        for (const ex& k : keys_) depends = depends || st_.depends_on(z, k);
        ex r = z;
        if (depends) {
            ex d = (*this)(st_.definition(z));
            r = d.is_equal(st_.definition(z)) ? z : st_.name_if_large(d, 4);
        }
        memo_.emplace(z, r);
        return r;
    }
    SymbolTable& st_;
    const exmap& m_;
    std::vector<ex> keys_;
    std::map<ex, ex, GiNaC::ex_is_less> memo_;
};

ex substitute(SymbolTable& st, const ex& e, const exmap& m) { return Substitution(st, m)(e); }

Vector substitute(SymbolTable& st, const Vector& v, const exmap& m) {
    return Substitution(st, m)(v);
}

// residuals E_i linear in x, as A x = b (E = b - A x); `what` names one equation in messages
void linear_form(const SymbolTable& st, const std::vector<ex>& E, const std::vector<ex>& x,
                 const std::string& what, const std::string& fix, GiNaC::matrix& A,
                 GiNaC::matrix& b) {
    A = GiNaC::matrix(static_cast<unsigned>(E.size()), static_cast<unsigned>(x.size()));
    b = GiNaC::matrix(static_cast<unsigned>(E.size()), 1);
    exmap zero;
    for (const ex& xj : x) zero[xj] = 0;
    for (unsigned i = 0; i < E.size(); ++i) {
        for (unsigned j = 0; j < x.size(); ++j) {
            ex a = E[i].diff(GiNaC::ex_to<GiNaC::symbol>(x[j]));
            for (const ex& xk : x)
                if (a.has(xk))
                    throw SolveError(kFn + what + " " + std::to_string(i + 1) +
                                     " is not linear in '" + name_of(st, x[j]) +
                                     "' (its coefficient holds '" + name_of(st, xk) + "'); " +
                                     fix);
            A(i, j) = -a;
        }
        b(i, 0) = E[i].subs(zero);
    }
}

// throws if a velocity holds the rate of a variable that is neither a speed nor auxiliary
void check_rates(const SymbolTable& st, const Vector& v, const GiNaC::exset& allowed,
                 const std::string& whose) {
    for (const auto& part : v.components())
        for (int i = 0; i < 3; ++i)
            for (const ex& s : symbols_of(part.second[i]))
                if (st.owns(s) && st.kind(s) == SymbolKind::variable &&
                    st.derivative_order(s) >= 1 && !allowed.count(s))
                    throw ModelError(kFn + whose + " holds '" + st.name(s) +
                                     "', which is neither a speed nor the rate of a listed "
                                     "coordinate; add '" + st.name(st.base(s)) +
                                     "' to the coordinates (with a kinematic equation when "
                                     "speeds are chosen)");
}

ex maybe_simplify(const ex& e, bool on) { return on ? simplify(e) : e; }

}  // namespace

namespace detail {

GiNaC::matrix solve_by_blocks(const GiNaC::matrix& A, const GiNaC::matrix& B,
                              const std::vector<ex>& unknowns, const std::string& what) {
    const unsigned n = A.rows(), k = B.cols();
    ALEMBERT_ASSERT(A.cols() == n && B.rows() == n && unknowns.size() == n);
    // union the unknowns that share an equation
    std::vector<unsigned> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](unsigned j) {
        while (parent[j] != j) j = parent[j] = parent[parent[j]];
        return j;
    };
    std::vector<std::vector<unsigned>> cols_of_row(n);
    for (unsigned i = 0; i < n; ++i) {
        for (unsigned j = 0; j < n; ++j)
            if (!GiNaC::expand(A(i, j)).is_zero()) cols_of_row[i].push_back(j);
        if (cols_of_row[i].empty())
            throw SolveError(what + ": equation " + std::to_string(i + 1) +
                             " holds none of the unknowns (" + to_string_list(unknowns) + ")");
        for (unsigned j : cols_of_row[i]) parent[find(j)] = find(cols_of_row[i][0]);
    }
    std::map<unsigned, std::vector<unsigned>> cols, rows;
    for (unsigned j = 0; j < n; ++j) cols[find(j)].push_back(j);
    for (unsigned i = 0; i < n; ++i) rows[find(cols_of_row[i][0])].push_back(i);

    // solve each block on its own
    GiNaC::matrix X(n, k);
    for (const auto& [root, c] : cols) {
        const std::vector<unsigned>& r = rows[root];
        std::vector<ex> block_unknowns;
        for (unsigned j : c) block_unknowns.push_back(unknowns[j]);
        const unsigned m = static_cast<unsigned>(c.size());
        auto singular = [&](const std::string& why) {
            return SolveError(what + ": the equations for " + to_string_list(block_unknowns) +
                              " " + why);
        };
        if (r.size() != c.size())
            throw singular("are " + std::to_string(r.size()) + " for " + std::to_string(m) +
                           " unknowns (singular coefficient matrix)");
        GiNaC::matrix Ab(m, m), Bb(m, k), vars(m, k);
        for (unsigned a = 0; a < m; ++a) {
            for (unsigned b = 0; b < m; ++b) Ab(a, b) = A(r[a], c[b]);
            for (unsigned j = 0; j < k; ++j) {
                Bb(a, j) = B(r[a], j);
                vars(a, j) = GiNaC::symbol("x" + std::to_string(a) + "_" + std::to_string(j));
            }
        }
        if (equal(Ab.determinant(), 0))
            throw singular("have a singular coefficient matrix (zero determinant)");
        GiNaC::matrix Xb;
        try {
            Xb = Ab.solve(vars, Bb, GiNaC::solve_algo::gauss);
        } catch (const std::exception& e) {
            throw singular(std::string("cannot be solved (") + e.what() + ")");
        }
        for (unsigned a = 0; a < m; ++a)
            for (unsigned j = 0; j < k; ++j) X(c[a], j) = simplify(GiNaC::normal(Xb(a, j)));
    }
    return X;
}

}  // namespace detail

namespace {

// values for the pivot choice: every variable, specified and t at 0 (the reference
// configuration, where models are usually linearized), constants at their values, or at
// fixed pseudo-random values in [0.5, 1.5] when they have none; `scatter` moves everything
// to pseudo-random values instead (a pivot that vanishes at the reference configuration)
exmap pivot_point(const SymbolTable& st, const GiNaC::exset& leaves, bool scatter) {
    exmap at;
    std::uint64_t seed = 0x9e3779b97f4a7c15ULL;
    auto next = [&]() {
        seed ^= seed << 13, seed ^= seed >> 7, seed ^= seed << 17;
        return 0.5 + static_cast<double>(seed % 1000003) / 1000003.0;
    };
    for (const ex& s : leaves) {
        double random = next();
        if (scatter) {
            at[s] = random;
            continue;
        }
        std::optional<double> v = st.owns(s) ? st.value(s) : std::nullopt;
        if (st.owns(s) && st.kind(s) == SymbolKind::constant)
            at[s] = v ? *v : random;
        else
            at[s] = 0;
    }
    return at;
}

double magnitude_at(const SymbolTable& st, const ex& e, const exmap& at) {
    try {
        return std::abs(st.evaluate(e, at));
    } catch (const std::exception&) {
        return 0;  // not finite there (a division by zero): not a usable pivot
    }
}

}  // namespace

namespace detail {

bool is_large(const GiNaC::matrix& A, const GiNaC::matrix& B) {
    constexpr std::size_t kLargeOps = 400;  // beyond this, closed-form solving swells
    std::size_t ops = 0;
    for (const GiNaC::matrix* M : {&A, &B})
        for (unsigned i = 0; i < M->rows(); ++i)
            for (unsigned j = 0; j < M->cols(); ++j) ops += count_ops((*M)(i, j));
    return ops > kLargeOps;
}

GiNaC::matrix solve_by_elimination(SymbolTable& st, const GiNaC::matrix& A,
                                   const GiNaC::matrix& B, const std::vector<ex>& unknowns,
                                   const std::string& what) {
    // entries larger than this are named, in large systems; small ones stay written out
    const std::size_t kNameOps =
        is_large(A, B) ? 6 : std::numeric_limits<std::size_t>::max();
    const unsigned n = A.rows(), k = B.cols();
    ALEMBERT_ASSERT(A.cols() == n && B.rows() == n && unknowns.size() == n);
    GiNaC::exset leaves;
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j)
            for (const ex& s : st.calc_leaf_symbols(A(i, j))) leaves.insert(s);
    const exmap reference = pivot_point(st, leaves, false);
    const exmap scattered = pivot_point(st, leaves, true);
    std::vector<std::vector<ex>> a(n, std::vector<ex>(n)), b(n, std::vector<ex>(k));
    for (unsigned i = 0; i < n; ++i) {
        for (unsigned j = 0; j < n; ++j) a[i][j] = st.name_if_large(A(i, j), kNameOps);
        for (unsigned j = 0; j < k; ++j) b[i][j] = st.name_if_large(B(i, j), kNameOps);
    }
    // forward elimination, rows pivoted on the largest magnitude at the reference
    // configuration (at scattered values when every candidate vanishes there)
    std::vector<unsigned> row(n);
    std::iota(row.begin(), row.end(), 0u);
    for (unsigned c = 0; c < n; ++c) {
        unsigned best = n;
        double best_value = 0;
        for (const exmap* at : {&reference, &scattered}) {
            for (unsigned i = c; i < n; ++i) {
                double v = magnitude_at(st, a[row[i]][c], *at);
                if (v > best_value) best = i, best_value = v;
            }
            if (best_value > 1e-9) break;
            best = n, best_value = 0;
        }
        if (best == n)
            throw SolveError(what + ": the equations for " + to_string_list(unknowns) +
                             " have a singular coefficient matrix (no pivot for '" +
                             to_string(unknowns[c]) + "')");
        std::swap(row[c], row[best]);
        const std::vector<ex>& p = a[row[c]];
        const ex& pb = p[c];
        for (unsigned i = c + 1; i < n; ++i) {
            std::vector<ex>& r = a[row[i]];
            if (r[c].is_zero()) continue;
            ex f = st.name_if_large(r[c] / pb, kNameOps);
            for (unsigned j = c + 1; j < n; ++j)
                if (!p[j].is_zero()) r[j] = st.name_if_large(r[j] - f * p[j], kNameOps);
            for (unsigned j = 0; j < k; ++j)
                if (!b[row[c]][j].is_zero())
                    b[row[i]][j] = st.name_if_large(b[row[i]][j] - f * b[row[c]][j], kNameOps);
            r[c] = 0;
        }
    }
    // back substitution
    GiNaC::matrix X(n, k);
    for (unsigned c = n; c-- > 0;) {
        const std::vector<ex>& p = a[row[c]];
        for (unsigned j = 0; j < k; ++j) {
            ex v = b[row[c]][j];
            for (unsigned l = c + 1; l < n; ++l)
                if (!p[l].is_zero()) v -= p[l] * X(l, j);
            X(c, j) = st.name_if_large(v / p[c], kNameOps);
        }
    }
    return X;
}

}  // namespace detail

KaneEquations form_kane_equations(const System& sys, const KaneOptions& o) {
    const Frame& N = sys.newtonian();
    SymbolTable& st = N.symbols();
    KaneEquations out;

    // ---- coordinates, speeds and their rates
    const std::size_t n = o.coordinates.size();
    ALEMBERT_CHECK_ARG(n > 0, std::string(kFn) + "no coordinates were given; list the "
                                                 "generalized coordinates in "
                                                 "KaneOptions::coordinates");
    std::vector<ex> qd;
    for (const TimeVariable& q : o.coordinates) {
        out.coordinates.push_back(q.symbol());
        qd.push_back(rate_of(st, q.symbol(), "coordinate"));
    }
    out.coordinate_rate_symbols = qd;
    require_distinct(st, out.coordinates, "the coordinates");
    const bool chosen = !o.speeds.empty();
    if (chosen && o.kinematic_equations.empty())
        throw ArgumentError(std::string(kFn) + "speeds " + quoted_list(st, o.speeds) +
                            " were given without kinematic equations; give one kinematic "
                            "differential equation per coordinate relating q' to the speeds");
    if (!chosen && !o.kinematic_equations.empty())
        throw ArgumentError(std::string(kFn) + "kinematic equations were given without speeds; "
                            "list the speeds they define in KaneOptions::speeds");
    out.speeds = chosen ? o.speeds : qd;
    const std::vector<ex>& U = out.speeds;
    std::vector<ex> Ud;
    for (const ex& u : U) Ud.push_back(rate_of(st, u, "speed"));
    require_distinct(st, U, "the speeds");
    if (chosen)
        for (const ex& u : U)
            if (contains(out.coordinates, u) || contains(qd, u) ||
                (st.kind(u) == SymbolKind::variable &&
                 contains(out.coordinates, st.base(u))))
                throw ArgumentError(std::string(kFn) + "speed '" + name_of(st, u) +
                                    "' is a coordinate or its rate; declare a separate speed "
                                    "(add_variable(\"u1\", 1)) with a kinematic equation such "
                                    "as u1 - q1'");
    out.auxiliary_speeds = o.auxiliary_speeds;
    exmap aux0;
    for (const ex& a : o.auxiliary_speeds) {
        require_variable(st, a, "auxiliary speed");
        if (contains(U, a) || contains(out.coordinates, a) || contains(qd, a))
            throw ArgumentError(std::string(kFn) + "auxiliary speed '" + name_of(st, a) +
                                "' is also a speed or coordinate; declare a separate variable "
                                "for it");
        aux0[a] = 0;
        TimeVariable tv = st.variable(st.name(st.base(a)));
        for (int k = st.derivative_order(a) + 1; k <= tv.order(); ++k) aux0[tv.d(k)] = 0;
    }
    require_distinct(st, o.auxiliary_speeds, "the auxiliary speeds");

    // ---- kinematic differential equations solved for q'
    exmap kmap;  // q' -> k(q, u, t)
    if (chosen) {
        if (o.kinematic_equations.size() != n)
            throw ArgumentError(std::string(kFn) + std::to_string(o.kinematic_equations.size()) +
                                " kinematic equations for " + std::to_string(n) +
                                " coordinates " + quoted_list(st, out.coordinates) +
                                "; give one per coordinate");
        std::vector<ex> K;
        for (std::size_t i = 0; i < n; ++i) {
            ex e = st.expand_intermediates(o.kinematic_equations[i]);
            for (const ex& s : symbols_of(e)) {
                if (aux0.count(s))
                    throw ArgumentError(std::string(kFn) + "kinematic equation " +
                                        std::to_string(i + 1) + " holds auxiliary speed '" +
                                        name_of(st, s) +
                                        "'; auxiliary speeds belong in velocities only");
                if (st.owns(s) && st.kind(s) == SymbolKind::variable &&
                    st.derivative_order(s) >= 1 && !contains(qd, s) && !contains(U, s))
                    throw ArgumentError(std::string(kFn) + "kinematic equation " +
                                        std::to_string(i + 1) + " holds '" + st.name(s) +
                                        "'; kinematic equations relate the coordinate rates q' "
                                        "to the speeds u, q and t only");
            }
            K.push_back(e);
        }
        GiNaC::matrix A, b;
        linear_form(st, K, qd, "kinematic equation",
                    "kinematic differential equations must be linear in q'", A, b);
        GiNaC::matrix X = detail::solve_by_blocks(
            A, b, qd, std::string(kFn) + "the kinematic equations cannot be solved for q'");
        for (std::size_t i = 0; i < n; ++i) kmap[qd[i]] = X(static_cast<unsigned>(i), 0);
        out.kinematic_equations = o.kinematic_equations;
    }
    exmap kmap_aux0 = kmap;  // q' -> k, auxiliary speeds -> 0
    for (const auto& kv : aux0) kmap_aux0[kv.first] = kv.second;

    // ---- motion constraints solved for the dependent speeds, auxiliary speeds present
    const std::size_t m = o.motion_constraints.size();
    if (o.dependent_speeds.size() != m)
        throw ArgumentError(std::string(kFn) + std::to_string(m) + " motion constraints and " +
                            std::to_string(o.dependent_speeds.size()) + " dependent speeds (" +
                            quoted_list(st, o.dependent_speeds) +
                            "); name one dependent speed per constraint");
    require_distinct(st, o.dependent_speeds, "the dependent speeds");
    for (const ex& s : o.dependent_speeds)
        if (!contains(U, s))
            throw ArgumentError(std::string(kFn) + "dependent speed '" + name_of(st, s) +
                                "' is not one of the speeds " + quoted_list(st, U) +
                                "; name dependent speeds among them");
    std::vector<ex> ind, ind_rates, dep_rates;
    for (std::size_t r = 0; r < U.size(); ++r) {
        if (contains(o.dependent_speeds, U[r])) continue;
        ind.push_back(U[r]);
        ind_rates.push_back(Ud[r]);
    }
    for (const ex& s : o.dependent_speeds) dep_rates.push_back(Ud[index_of(U, s)]);
    out.independent_speeds = ind;
    out.dependent_speeds = o.dependent_speeds;
    out.motion_constraints = o.motion_constraints;
    const std::size_t na = o.auxiliary_speeds.size();
    exmap depmap;  // u_s -> sum A_sr u_r + B_s (auxiliary speeds zero)
    out.constraint_coefficients = GiNaC::matrix(static_cast<unsigned>(m),
                                                static_cast<unsigned>(ind.size()));
    out.auxiliary_constraint_coefficients =
        GiNaC::matrix(static_cast<unsigned>(m), static_cast<unsigned>(na));
    // constraints too large to solve in closed form leave results that simplification would
    // normalise at great cost (every entry over the pivots' intermediates): past such a solve
    // nothing is simplified, as with simplify = false
    bool large_constraints = false;
    if (m > 0) {
        // the speeds and auxiliary speeds a constraint may hold (Kane 1985, sec. 5.7: the
        // auxiliary motion must leave every listed constraint satisfied)
        std::vector<ex> UA = U;
        UA.insert(UA.end(), o.auxiliary_speeds.begin(), o.auxiliary_speeds.end());
        std::vector<ex> C;
        for (std::size_t i = 0; i < m; ++i) {
            ex c = substitute(st, st.expand_intermediates(o.motion_constraints[i]), kmap);
            for (const ex& s : symbols_of(c))
                if (st.owns(s) && st.kind(s) == SymbolKind::variable &&
                    st.derivative_order(s) >= 1 && !contains(UA, s))
                    throw ArgumentError(std::string(kFn) + "motion constraint " +
                                        std::to_string(i + 1) + " holds '" + st.name(s) +
                                        "'; motion constraints relate the speeds and auxiliary "
                                        "speeds (and q, t) only: no accelerations, no rates of "
                                        "unlisted coordinates");
            C.push_back(c);
        }
        GiNaC::matrix A, b;
        linear_form(st, C, UA, "motion constraint",
                    "write each constraint as a sum of speeds times functions of q and t", A, b);
        // split into dependent and other columns: A_dep u_dep = b - A_ind u_ind - A_aux u~
        GiNaC::matrix Adep(static_cast<unsigned>(m), static_cast<unsigned>(m)),
            rhs(static_cast<unsigned>(m), 1);
        for (unsigned i = 0; i < m; ++i) {
            ex r = b(i, 0);
            for (std::size_t j = 0; j < UA.size(); ++j) {
                std::size_t s = index_of(o.dependent_speeds, UA[j]);
                if (s < m) Adep(i, static_cast<unsigned>(s)) = A(i, static_cast<unsigned>(j));
                else r -= A(i, static_cast<unsigned>(j)) * UA[j];
            }
            rhs(i, 0) = r;
        }
        for (unsigned s = 0; s < m; ++s) {
            bool used = false;
            for (unsigned i = 0; i < m; ++i) used = used || !GiNaC::expand(Adep(i, s)).is_zero();
            if (!used)
                throw ArgumentError(std::string(kFn) + "dependent speed '" +
                                    name_of(st, o.dependent_speeds[s]) +
                                    "' appears in no motion constraint; name a speed that the "
                                    "constraints hold");
        }
        // u_s = sum A_sr u_r + sum C_sa u~_a + B_s; the motion itself has u~ = 0
        const std::string singular =
            std::string(kFn) +
            "the motion constraints cannot be solved for the dependent speeds; name other "
            "dependent speeds (their coefficient matrix must be invertible)";
        large_constraints = detail::is_large(Adep, rhs);
        if (o.simplify && !large_constraints) {
            // small systems: solved in closed form, each entry normalised and simplified
            GiNaC::matrix X = detail::solve_by_blocks(Adep, rhs, o.dependent_speeds, singular);
            for (unsigned s = 0; s < m; ++s) {
                ex value = na == 0 ? X(s, 0) : maybe_simplify(X(s, 0).subs(aux0), o.simplify);
                depmap[o.dependent_speeds[s]] = value;
                out.dependent_speed_values.push_back(value);
                for (unsigned r = 0; r < ind.size(); ++r)
                    out.constraint_coefficients(s, r) =
                        simplify(X(s, 0).diff(GiNaC::ex_to<GiNaC::symbol>(ind[r])));
                for (unsigned a = 0; a < na; ++a)
                    out.auxiliary_constraint_coefficients(s, a) = simplify(
                        X(s, 0).diff(GiNaC::ex_to<GiNaC::symbol>(o.auxiliary_speeds[a])));
            }
        } else {
            // large systems, or no simplification asked for: elimination with named
            // intermediates, one right-hand side per independent and auxiliary speed plus
            // the rest, so A_sr and C_sa come out directly and nothing is normalised
            const unsigned k = static_cast<unsigned>(ind.size() + na + 1);
            GiNaC::matrix R(static_cast<unsigned>(m), k);
            for (unsigned i = 0; i < m; ++i) {
                for (unsigned r = 0; r < ind.size(); ++r)
                    R(i, r) = -A(i, static_cast<unsigned>(index_of(UA, ind[r])));
                for (unsigned a = 0; a < na; ++a)
                    R(i, static_cast<unsigned>(ind.size()) + a) =
                        -A(i, static_cast<unsigned>(index_of(UA, o.auxiliary_speeds[a])));
                R(i, k - 1) = b(i, 0);
            }
            GiNaC::matrix X =
                detail::solve_by_elimination(st, Adep, R, o.dependent_speeds, singular);
            for (unsigned s = 0; s < m; ++s) {
                ex value = X(s, k - 1);
                for (unsigned r = 0; r < ind.size(); ++r) {
                    out.constraint_coefficients(s, r) = X(s, r);
                    value += X(s, r) * ind[r];
                }
                for (unsigned a = 0; a < na; ++a)
                    out.auxiliary_constraint_coefficients(s, a) =
                        X(s, static_cast<unsigned>(ind.size()) + a);
                depmap[o.dependent_speeds[s]] = value;
                out.dependent_speed_values.push_back(value);
            }
        }
    }

    const bool tidy = o.simplify && !large_constraints;

    // ---- coordinate rates and dependent-speed rates in the independent speeds
    exmap rate_map;  // q' -> k(q, u_r, t) with the dependent speeds replaced
    for (std::size_t i = 0; i < n; ++i) {
        ex k = chosen ? substitute(st, kmap.at(qd[i]), depmap) : substitute(st, qd[i], depmap);
        k = maybe_simplify(k, tidy && m > 0);
        out.coordinate_rates.push_back(k);
        if (!k.is_equal(qd[i])) rate_map[qd[i]] = k;
    }
    exmap elim = depmap;  // u_s -> ..., u_s' -> ...
    Substitution by_rates(st, rate_map);
    for (std::size_t s = 0; s < m; ++s) {
        ex g = maybe_simplify(by_rates(st.dt(out.dependent_speed_values[s])), tidy);
        out.dependent_speed_rates.push_back(g);
        elim[dep_rates[s]] = g;
    }

    // ---- velocities and angular velocities in terms of the speeds
    GiNaC::exset allowed(U.begin(), U.end());
    allowed.insert(o.auxiliary_speeds.begin(), o.auxiliary_speeds.end());
    std::map<const Point*, Vector> vel;
    std::map<const Frame*, Vector> angvel;
    Substitution by_k(st, kmap), by_aux0(st, aux0);
    auto vel_of = [&](const Point* P) -> const Vector& {
        auto it = vel.find(P);
        if (it != vel.end()) return it->second;
        Vector v = by_k(P->vel_in(N));
        check_rates(st, v, allowed, "the velocity of point '" + P->name() + "' in '" +
                                        N.name() + "'");
        return vel.emplace(P, std::move(v)).first->second;
    };
    auto angvel_of = [&](const Frame* B) -> const Vector& {
        auto it = angvel.find(B);
        if (it != angvel.end()) return it->second;
        Vector w = by_k(B->ang_vel_in(N));
        check_rates(st, w, allowed, "the angular velocity of frame '" + B->name() + "' in '" +
                                        N.name() + "'");
        return angvel.emplace(B, std::move(w)).first->second;
    };
    std::vector<ex> S = U;  // every speed whose partial velocities are taken
    S.insert(S.end(), o.auxiliary_speeds.begin(), o.auxiliary_speeds.end());
    const std::size_t p = U.size();

    // ---- generalized active forces F_r = sum v_r . F + w_r . T, gravity at mass centres
    std::vector<ex> F(S.size(), 0), Fs(S.size(), 0);
    for (const Load& l : sys.loads()) {
        Vector L = substitute(st, l.vector, kmap_aux0);
        if (l.kind == LoadKind::force) {
            const Vector& v = vel_of(l.point);
            for (std::size_t r = 0; r < S.size(); ++r) F[r] += dot(v.diff(S[r]), L);
        } else if (l.on->frame()) {
            const Vector& w = angvel_of(l.on->frame());
            for (std::size_t r = 0; r < S.size(); ++r) F[r] += dot(w.diff(S[r]), L);
        }
    }
    if (!sys.gravity().is_zero())
        for (const Body* b : sys.bodies()) {
            Vector W = b->mass() * sys.gravity();
            const Vector& v = vel_of(&b->cm());
            for (std::size_t r = 0; r < S.size(); ++r) F[r] += dot(v.diff(S[r]), W);
        }

    // ---- generalized inertia forces F_r* = sum v_r . R* + w_r . T*, at zero auxiliary speeds
    for (const Body* b : sys.bodies()) {
        const Vector& v = vel_of(&b->cm());
        Vector a = by_k(by_aux0(v).dt_in(N));
        Vector Rstar = -(b->mass() * a);
        Vector w, Tstar;
        if (const auto* rb = dynamic_cast<const RigidBody*>(b)) {
            const Frame& B = *rb->frame();
            w = angvel_of(&B);
            Vector w0 = by_aux0(w);
            Vector alpha = by_k(w0.dt_in(B));
            const Dyadic& I = rb->inertia();
            Tstar = -(dot(I, alpha) + cross(w0, dot(I, w0)));
        }
        for (std::size_t r = 0; r < S.size(); ++r) {
            Fs[r] += dot(v.diff(S[r]), Rstar);
            if (!Tstar.is_zero()) Fs[r] += dot(w.diff(S[r]), Tstar);
        }
    }
    for (std::size_t r = 0; r < p; ++r) {
        out.unconstrained_active_forces.push_back(maybe_simplify(F[r], tidy));
        out.unconstrained_inertia_forces.push_back(maybe_simplify(Fs[r], tidy));
    }

    // ---- Kane's elimination: F~_r = F_r + sum_s F_s A_sr, likewise F~_r*
    Substitution by_elim(st, elim);
    for (std::size_t r = 0; r < ind.size(); ++r) {
        std::size_t ri = index_of(U, ind[r]);
        ex Ft = F[ri], Fst = Fs[ri];
        for (std::size_t s = 0; s < m; ++s) {
            std::size_t si = index_of(U, o.dependent_speeds[s]);
            const ex& Asr = out.constraint_coefficients(static_cast<unsigned>(s),
                                                        static_cast<unsigned>(r));
            Ft += Asr * F[si];
            Fst += Asr * Fs[si];
        }
        Ft = maybe_simplify(by_elim(Ft), tidy);
        Fst = maybe_simplify(by_elim(Fst), tidy);
        out.active_forces.push_back(Ft);
        out.inertia_forces.push_back(Fst);
        out.residuals.push_back(tidy ? collect_in(Ft + Fst, ind_rates) : Ft + Fst);
    }

    // ---- auxiliary equations: F~_a = F_a + sum_s F_s C_sa, likewise F~_a*, at u~ = u~' = 0
    for (std::size_t a = 0; a < na; ++a) {
        ex Ft = F[p + a], Fst = Fs[p + a];
        for (std::size_t s = 0; s < m; ++s) {
            std::size_t si = index_of(U, o.dependent_speeds[s]);
            const ex& Csa = out.auxiliary_constraint_coefficients(static_cast<unsigned>(s),
                                                                  static_cast<unsigned>(a));
            Ft += Csa * F[si];
            Fst += Csa * Fs[si];
        }
        ex Ea = maybe_simplify(by_aux0(by_elim(Ft + Fst)), tidy);
        // an auxiliary motion that moves no loaded point and no mass brings out nothing
        if (equal(Ea, 0))
            throw ModelError(
                std::string(kFn) + "auxiliary speed '" + name_of(st, o.auxiliary_speeds[a]) +
                "' gives the equation 0 = 0: with the motion constraints solved it moves no "
                "point a load acts on and no mass. Add it to the velocity of the point the "
                "constraint force acts on (Point::set_vel) or to an angular velocity "
                "(Frame::set_ang_vel), or write it into the constraint that force enforces as "
                "its violation, e.g. dot(v_NP - v_NQ, Nx>) - " +
                name_of(st, o.auxiliary_speeds[a]));
        out.auxiliary_equations.push_back(Ea);
    }

    // ---- mass-matrix form M u' = f
    out.dynamics = form_linear_system(out.residuals, ind_rates);
    for (unsigned j = 0; j < ind.size(); ++j) {
        bool used = false;
        for (unsigned i = 0; i < ind.size(); ++i) {
            if (tidy) out.dynamics.A(i, j) = simplify(out.dynamics.A(i, j));
            used = used || !out.dynamics.A(i, j).is_zero();
        }
        if (!used)
            throw ModelError(std::string(kFn) + "speed '" + name_of(st, ind[j]) +
                             "' moves no mass (its rate appears in no equation); check the "
                             "kinematic equations and the velocities that should hold it");
    }
    if (tidy)
        for (unsigned i = 0; i < ind.size(); ++i)
            out.dynamics.b(i, 0) = simplify(out.dynamics.b(i, 0));
    return out;
}

}  // namespace alembert
