// SPDX-License-Identifier: MIT
// Common-subexpression naming over GiNaC trees.
#include "alembert/sym/cse.hpp"

#include <map>

#include "alembert/sym/simplify.hpp"

namespace alembert {

using namespace GiNaC;

namespace {

using Counts = std::map<ex, std::size_t, ex_is_less>;

bool trivial(const ex& e) { return is_a<symbol>(e) || is_a<numeric>(e); }

// occurrences of each subexpression; a repeated subtree's children are counted once only
void count(const ex& e, Counts& c) {
    if (trivial(e)) return;
    if (++c[e] > 1) return;
    for (std::size_t i = 0; i < e.nops(); ++i) count(e.op(i), c);
}

struct Replacer : map_function {
    SymbolTable& table;
    const Counts& counts;
    std::size_t min_ops;
    std::map<ex, ex, ex_is_less> done;
    std::vector<ex> created;

    Replacer(SymbolTable& t, const Counts& c, std::size_t m) : table(t), counts(c), min_ops(m) {}

    ex operator()(const ex& e) override {
        if (trivial(e)) return e;
        auto it = done.find(e);
        if (it != done.end()) return it->second;
        ex inner = e.map(*this);
        ex out = inner;
        auto c = counts.find(e);
        if (c != counts.end() && c->second >= 2 && count_ops(inner) >= min_ops) {
            out = table.add_intermediate(inner);
            created.push_back(out);
        }
        done.emplace(e, out);
        return out;
    }
};

}  // namespace

std::vector<ex> introduce_intermediates(SymbolTable& table, std::vector<ex>& exprs,
                                        std::size_t min_ops) {
    Counts counts;
    for (const ex& e : exprs) count(e, counts);
    Replacer r(table, counts, min_ops);
    for (ex& e : exprs) e = r(e);
    return r.created;
}

std::size_t count_ops_with_intermediates(const SymbolTable& table, const std::vector<ex>& exprs) {
    std::size_t n = 0;
    exset seen;
    std::vector<ex> stack(exprs.begin(), exprs.end());
    while (!stack.empty()) {
        ex e = stack.back();
        stack.pop_back();
        n += count_ops(e);
        for (const ex& s : symbols_of(e))
            if (table.owns(s) && table.kind(s) == SymbolKind::intermediate && seen.insert(s).second)
                stack.push_back(table.definition(s));
    }
    return n;
}

}  // namespace alembert
