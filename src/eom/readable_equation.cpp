// SPDX-License-Identifier: MIT
#include "alembert/eom/readable_equation.hpp"

#include <algorithm>
#include <vector>

#include "alembert/eom/zero_test.hpp"
#include "alembert/sym/print.hpp"
#include "alembert/sym/symbol_table.hpp"

namespace alembert {

namespace {

// the accelerations `e` holds, by name, so that what is collected does not depend on the
// order symbols were made in
std::vector<ex> accelerations_of(const SymbolTable& st, const ex& e) {
    std::vector<ex> acc;
    for (const ex& s : symbols_of(e))
        if (st.owns(s) && st.kind(s) == SymbolKind::variable && st.derivative_order(s) == 2)
            acc.push_back(s);
    std::sort(acc.begin(), acc.end(),
              [](const ex& a, const ex& b) { return to_string(a) < to_string(b); });
    return acc;
}

// a number, or a product of powers of the model's constants: the same at every state
bool is_constant_monomial(const SymbolTable& st, const ex& a) {
    if (GiNaC::is_a<GiNaC::numeric>(a)) return true;
    if (GiNaC::is_a<GiNaC::symbol>(a))
        return st.owns(a) && st.kind(a) == SymbolKind::constant;
    if (GiNaC::is_a<GiNaC::power>(a))
        return GiNaC::is_a<GiNaC::numeric>(a.op(1)) && is_constant_monomial(st, a.op(0));
    if (GiNaC::is_a<GiNaC::mul>(a)) {
        for (std::size_t i = 0; i < a.nops(); ++i)
            if (!is_constant_monomial(st, a.op(i))) return false;
        return true;
    }
    return false;
}

}  // namespace

ex readable_equation(const System& sys, const ex& e, Simplifier& simplifier) {
    if (count_ops(e) > kReadableEquationOps) return e;
    const std::vector<ex> acc = accelerations_of(sys.symbols(), e);
    const ex x = simplifier(e);
    return acc.empty() ? x : simplifier.collected(x, acc);
}

ReadableRelation calc_solved_equation(const System& sys, const ex& e, const ex& unknown,
                                      Simplifier& simplifier) {
    if (count_ops(e) > kReadableEquationOps) return {0, e};
    const SymbolTable& st = sys.symbols();
    const ex x = readable_equation(sys, e, simplifier);
    if (GiNaC::is_a<GiNaC::symbol>(unknown) && x.has(unknown)) {
        // e = a*unknown + b, read off the collected form's terms (no expansion): a term holding
        // the unknown other than as a factor to the first power leaves it in b, and b.has()
        // refuses the solution
        const ex a = x.coeff(unknown, 1), b = x.coeff(unknown, 0);
        if (!a.has(unknown) && !b.has(unknown) && is_constant_monomial(st, a) &&
            !is_zero_at_random_states(st, a) &&
            is_zero_at_random_states(st, x - (a * unknown + b))) {
            const ex rhs = -b / a;  // a number or a monomial: GiNaC distributes it over b's terms
            const std::vector<ex> acc = accelerations_of(st, rhs);
            return {unknown, factor_common(acc.empty() ? simplifier(GiNaC::expand(rhs))
                                                       : simplifier.collected(rhs, acc))};
        }
    }
    return {0, factor_common(x)};
}

}  // namespace alembert
