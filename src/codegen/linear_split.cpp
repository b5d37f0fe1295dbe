// SPDX-License-Identifier: MIT
// Private to codegen: expressions linear in some symbols split into coefficients and the rest.
#include "linear_split.hpp"

#include <map>
#include <unordered_map>

#include "alembert/eom/kane.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"

namespace alembert::detail {

namespace {

using namespace GiNaC;

// e = rest + sum_j c_j x_j, the c_j sparse by index
struct Split {
    ex rest;
    std::map<unsigned, ex> c;
};

struct Nonlinear {
    unsigned unknown;
};

struct SameTree {
    bool operator()(const ex& a, const ex& b) const { return a.compare(b) == 0; }
};

class Splitter {
public:
    Splitter(const SymbolTable& table, const std::vector<ex>& unknowns) : table_(table) {
        for (unsigned j = 0; j < unknowns.size(); ++j) index_.emplace(unknowns[j], j);
    }

    const Split& split(const ex& e) {
        auto it = memo_.find(e);
        if (it != memo_.end()) return it->second;
        Split s = compute(e);
        return memo_.emplace(e, std::move(s)).first->second;
    }

private:
    Split compute(const ex& e) {
        if (is_a<numeric>(e) || is_a<constant>(e)) return {e, {}};
        if (is_a<symbol>(e)) {
            auto j = index_.find(e);
            if (j != index_.end()) return {0, {{j->second, 1}}};
            // an intermediate whose definition holds an unknown is replaced by its split
            if (table_.owns(e) && table_.kind(e) == SymbolKind::intermediate) {
                const Split& d = split(table_.definition(e));
                if (!d.c.empty()) return d;
            }
            return {e, {}};
        }
        if (is_a<add>(e)) {
            Split s{0, {}};
            exvector rest;
            bool changed = false;
            for (std::size_t i = 0; i < e.nops(); ++i) {
                const Split& t = split(e.op(i));
                changed = changed || !t.c.empty() || !are_ex_trivially_equal(t.rest, e.op(i));
                rest.push_back(t.rest);
                for (const auto& [j, c] : t.c) s.c[j] = s.c.count(j) ? s.c[j] + c : c;
            }
            s.rest = changed ? ex(add(rest)) : e;
            return s;
        }
        if (is_a<mul>(e)) {
            // one factor at most may hold the unknowns (a split without unknowns is the factor
            // itself, so the others are kept as they are)
            std::size_t which = e.nops();
            for (std::size_t i = 0; i < e.nops(); ++i) {
                const Split& f = split(e.op(i));
                if (f.c.empty()) continue;
                if (which != e.nops()) throw Nonlinear{f.c.begin()->first};
                which = i;
            }
            if (which == e.nops()) return {e, {}};
            exvector factors;
            for (std::size_t i = 0; i < e.nops(); ++i)
                if (i != which) factors.push_back(e.op(i));
            const ex others = mul(factors);
            const Split& f = split(e.op(which));
            Split s{others * f.rest, {}};
            for (const auto& [j, c] : f.c) s.c[j] = others * c;
            return s;
        }
        // powers and functions of the unknowns are not linear; of anything else, kept
        for (std::size_t i = 0; i < e.nops(); ++i) {
            const Split& a = split(e.op(i));
            if (!a.c.empty()) throw Nonlinear{a.c.begin()->first};
        }
        return {e, {}};
    }

    const SymbolTable& table_;
    std::unordered_map<ex, unsigned, std::hash<ex>, SameTree> index_;
    std::unordered_map<ex, Split, std::hash<ex>, SameTree> memo_;
};

}  // namespace

LinearSystem split_linear(const SymbolTable& table, const std::vector<ex>& residuals,
                          const std::vector<ex>& unknowns, const char* who) {
    const auto n = static_cast<unsigned>(residuals.size());
    const auto m = static_cast<unsigned>(unknowns.size());
    LinearSystem s{matrix(n, m), matrix(n, 1), unknowns};
    Splitter splitter(table, unknowns);
    for (unsigned i = 0; i < n; ++i) {
        try {
            const Split& e = splitter.split(residuals[i]);
            s.b(i, 0) = e.rest;
            for (const auto& [j, c] : e.c) s.A(i, j) = -c;
        } catch (const Nonlinear& bad) {
            throw SolveError(std::string(who) + ": equation " + std::to_string(i + 1) +
                             " is not linear in '" + to_string(unknowns[bad.unknown]) +
                             "'; give equations linear in the accelerations and the loads");
        }
    }
    return s;
}

std::vector<ex> solve_for_loads(const SymbolTable& table, const std::vector<ex>& E,
                                const std::vector<ex>& loads, const char* who) {
    const auto n = static_cast<unsigned>(loads.size());
    LinearSystem L = split_linear(table, E, loads, who);
    bool numeric = true;
    for (unsigned i = 0; i < n && numeric; ++i)
        for (unsigned j = 0; j < n && numeric; ++j) numeric = GiNaC::is_a<GiNaC::numeric>(L.A(i, j));
    std::vector<ex> u;
    if (numeric && !L.A.determinant().is_zero()) {
        GiNaC::matrix Ainv = L.A.inverse();
        for (unsigned i = 0; i < n; ++i) {
            ex s = 0;
            for (unsigned j = 0; j < n; ++j)
                if (!Ainv(i, j).is_zero()) s += Ainv(i, j) * L.b(j, 0);
            u.push_back(s);
        }
        return u;
    }
    GiNaC::matrix X = solve_by_blocks(L.A, L.b, loads, std::string(who) + ": inverse dynamics");
    for (unsigned i = 0; i < n; ++i) u.push_back(X(i, 0));
    return u;
}

}  // namespace alembert::detail
