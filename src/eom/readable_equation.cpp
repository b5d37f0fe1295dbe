// SPDX-License-Identifier: MIT
#include "alembert/eom/readable_equation.hpp"

#include <algorithm>
#include <vector>

#include "alembert/sym/print.hpp"
#include "alembert/sym/symbol_table.hpp"

namespace alembert {

ex readable_equation(const System& sys, const ex& e, Simplifier& simplifier) {
    if (count_ops(e) > kReadableEquationOps) return e;
    const SymbolTable& st = sys.symbols();
    std::vector<ex> acc;
    for (const ex& s : symbols_of(e))
        if (st.owns(s) && st.kind(s) == SymbolKind::variable && st.derivative_order(s) == 2)
            acc.push_back(s);
    // by name, so the collection does not depend on the order symbols were made in
    std::sort(acc.begin(), acc.end(),
              [](const ex& a, const ex& b) { return to_string(a) < to_string(b); });
    const ex x = simplifier(e);
    return acc.empty() ? x : simplifier.collected(x, acc);
}

}  // namespace alembert
