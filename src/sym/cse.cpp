// SPDX-License-Identifier: MIT
// Common-subexpression naming over GiNaC trees.
#include "alembert/sym/cse.hpp"

#include <map>
#include <unordered_set>

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

std::vector<ex> calc_reached_intermediates(const SymbolTable& table, const std::vector<ex>& exprs) {
    // one walk over the DAG of all the expressions and the definitions they reach: a node
    // shared by several equations (most of a large model's) is entered once for all of them
    std::map<ex, std::size_t, ex_is_less> position;
    const std::vector<ex>& all = table.intermediates();
    for (std::size_t i = 0; i < all.size(); ++i) position.emplace(all[i], i);
    std::map<std::size_t, ex> reached;  // by dependency order
    std::unordered_set<const basic*> entered;
    // (op() of a sum may build a term anew: the nodes entered are kept alive while their
    // addresses are remembered)
    std::vector<ex> alive, stack(exprs.begin(), exprs.end());
    while (!stack.empty()) {
        ex x = std::move(stack.back());
        stack.pop_back();
        if (is_a<symbol>(x)) {
            auto it = position.find(x);
            if (it != position.end() && reached.emplace(it->second, x).second)
                stack.push_back(table.definition(x));
            continue;
        }
        if (x.nops() == 0 || !entered.insert(&ex_to<basic>(x)).second) continue;
        for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
        alive.push_back(std::move(x));
    }
    std::vector<ex> out;
    out.reserve(reached.size());
    for (auto& [i, z] : reached) out.push_back(z);
    return out;
}

std::size_t count_ops_with_intermediates(const SymbolTable& table, const std::vector<ex>& exprs) {
    std::vector<ex> measured(exprs.begin(), exprs.end());
    for (const ex& z : calc_reached_intermediates(table, exprs))
        measured.push_back(table.definition(z));
    return count_ops(measured);
}

}  // namespace alembert
