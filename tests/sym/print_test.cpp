// SPDX-License-Identifier: MIT
// The printer: primes and an order independent of symbol creation order.
#include "alembert/sym/print.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <random>

#include "alembert/sym/simplify.hpp"
#include "alembert/sym/symbol_table.hpp"
#include "support/expect.hpp"

using namespace alembert;
using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;

namespace {
// the same expression built in a table whose symbols are created in the given order
std::string print_in_order(bool reversed) {
    SymbolTable s;
    std::vector<std::string> names{"qA", "qB", "m", "L"};
    if (reversed) std::reverse(names.begin(), names.end());
    for (const auto& n : names) {
        if (n[0] == 'q') s.add_variable(n);
        else s.add_constant(n);
    }
    TimeVariable qA = s.variable("qA"), qB = s.variable("qB");
    ex m = s.symbol("m"), L = s.symbol("L");
    ex e = m * L * L * qA.d(2) + m * L * sin(qB) * pow(qB.d(1), 2) - 3 * cos(qA + qB) / 2 +
           (qA.d(1) + qB.d(1)) * m;
    return to_string(e);
}
}  // namespace

TEST(Print, DerivativesPrintWithPrimes) {
    SymbolTable s;
    TimeVariable q = s.add_variable("qA", 2);
    EXPECT_EQ(to_string(q.d(1)), "qA'");
    EXPECT_EQ(to_string(q.d(2)), "qA''");
    EXPECT_EQ(to_string(pow(q.d(1), 2)), "qA'^2");
}

TEST(Print, OrderDoesNotDependOnSymbolCreationOrder) {
    EXPECT_EQ(print_in_order(false), print_in_order(true));
}

TEST(Print, SimpleFormsReadAsWritten) {
    SymbolTable s;
    ex a = s.add_constant("a"), b = s.add_constant("b");
    EXPECT_EQ(to_string(a - b), "a - b");
    EXPECT_EQ(to_string(-a), "-a");
    EXPECT_EQ(to_string(a / 2), "a/2");
    EXPECT_EQ(to_string(a / b), "a/b");
    EXPECT_EQ(to_string(GiNaC::sqrt(a)), "sqrt(a)");
    EXPECT_EQ(to_string(b * (a + b)), "b*(a + b)");
    EXPECT_EQ(to_string(GiNaC::numeric(1, 3)), "1/3");
    EXPECT_EQ(to_string(GiNaC::ex(0.25)), "0.25");
}

TEST(Print, SignsOfSumsAndTrigArgumentsDoNotDependOnHowTheyWereBuilt) {
    // GiNaC may hold a*(b - c) as -a*(c - b), cos(b - c) as cos(c - b), depending on its
    // internal term order; each pair is one value and must print one way
    SymbolTable s;
    ex a = s.add_constant("a"), b = s.add_constant("b"), c = s.add_constant("c");
    EXPECT_EQ(to_string(a * (b - c)), to_string(-a * (c - b)));
    EXPECT_EQ(to_string(a * (b - c)), "a*(b - c)");
    EXPECT_EQ(to_string(cos(c - b)), "cos(b - c)");
    EXPECT_EQ(to_string(sin(c - b)), "-sin(b - c)");
    EXPECT_EQ(to_string(a * sin(c - b)), to_string(-a * sin(b - c)));
    EXPECT_EQ(to_string(pow(c - b, 2)), "(b - c)^2");
    EXPECT_EQ(to_string(a * pow(c - b, 3)), to_string(-a * pow(b - c, 3)));
    EXPECT_EQ(to_string(a + sin(c - b)), "a - sin(b - c)");
}

namespace {

// the value of `text` (as printed, names without primes) at the point `at`, read back with
// GiNaC's parser; names missing from `at` get a value from their spelling
double value_of(const std::string& text, GiNaC::symtab& names, std::map<std::string, double>& at) {
    GiNaC::parser reader(names);
    ex e = reader(text);
    names = reader.get_syms();
    GiNaC::exmap values;
    for (const auto& [name, sym] : names) {
        if (!at.count(name)) at[name] = 0.3 + 0.1 * static_cast<double>(std::hash<std::string>{}(name) % 13);
        values[sym] = at[name];
    }
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(values))).to_double();
}

// e_{k+1} = a_k*(e_k - b_k) + cos(q_k - e_k)*c_k: a sum in a product at every level, where
// deciding a product's sign once printed each sum twice per level (2^depth prints)
ex nested(const std::vector<ex>& a, int depth) {
    ex e = a[0];
    for (int k = 0; k < depth; ++k)
        e = a[k % a.size()] * (e - a[(k + 1) % a.size()]) +
            cos(a[(k + 2) % a.size()] - a[(k + 3) % a.size()]) * a[(k + 4) % a.size()];
    return e;
}

}  // namespace

TEST(Print, DeepNestingPrintsWithoutExponentialCostAndReadsBackToTheSameValue) {
    // 400 levels: the printer that decided each sum's sign by printing it twice would take
    // about 2^400 steps here, so this test not finishing is the regression it guards against
    SymbolTable s;
    std::vector<ex> a;
    for (int i = 0; i < 7; ++i) a.push_back(s.add_constant("a" + std::to_string(i)));
    ex e = nested(a, 400);
    std::string text = to_string(e);
    GiNaC::symtab names;
    std::map<std::string, double> at;
    const double printed = value_of(text, names, at);
    GiNaC::exmap values;
    for (std::size_t i = 0; i < a.size(); ++i) values[a[i]] = at.at("a" + std::to_string(i));
    const double formed = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(values))).to_double();
    EXPECT_NEAR(printed, formed, 1e-9 * std::max(1.0, std::abs(formed)));
}

TEST(Print, SharedSubexpressionsAreCountedAndScannedOncePerNode) {
    // a DAG whose tree has 2^80 leaves: count_ops and symbols_of must walk its 80 nodes
    SymbolTable s;
    ex x = s.add_constant("x"), y = s.add_constant("y");
    ex e = x;
    for (int k = 0; k < 80; ++k) e = sin(e) * x + cos(e) * y;
    EXPECT_EQ(symbols_of(e).size(), 2u);
    // the count saturates rather than wrapping
    EXPECT_EQ(count_ops(e), std::numeric_limits<std::size_t>::max());
    ex small = x;
    for (int k = 0; k < 3; ++k) small = sin(small) * x + cos(small) * y;
    // 4 ops per level on top of two copies of the level below: 2*(2*(2*0 + 5) + 5) + 5
    EXPECT_EQ(count_ops(small), 35u);
}

TEST(Print, AbbreviatedLinesAreShortDefinedBeforeUseAndMeanTheExpression) {
    SymbolTable s;
    std::vector<ex> a;
    for (int i = 0; i < 7; ++i) a.push_back(s.add_constant("a" + std::to_string(i)));
    ex wide = 0;
    for (int i = 0; i < 300; ++i) wide += (i % 5 + 1) * a[i % 7] * a[(i / 7) % 7] * sin(a[(i * 3) % 7] + i);
    std::vector<ex> exprs{nested(a, 60), wide, nested(a, 30) * wide};
    AbbreviatedText t = abbreviate(exprs, 100, "w");
    ASSERT_EQ(t.results.size(), exprs.size());
    GiNaC::symtab names;
    std::map<std::string, double> at;
    std::size_t next = 0;
    for (std::size_t i = 0; i < exprs.size(); ++i) {
        for (; next < t.defined_before[i]; ++next) {
            const std::string& line = t.definitions[next];
            EXPECT_LE(line.size(), 110u) << line;
            const std::size_t eq = line.find(" = ");
            ASSERT_NE(eq, std::string::npos);
            const std::string name = line.substr(0, eq);
            EXPECT_EQ(name, "w" + std::to_string(next + 1));
            // defined before use: the name is not yet known to the reader
            EXPECT_FALSE(at.count(name)) << name << " used before its definition";
            at[name] = value_of(line.substr(eq + 3), names, at);
        }
        EXPECT_LE(t.results[i].size(), 110u) << t.results[i];
        const double printed = value_of(t.results[i], names, at);
        GiNaC::exmap values;
        for (std::size_t k = 0; k < a.size(); ++k) values[a[k]] = at.at("a" + std::to_string(k));
        const double formed = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(exprs[i].subs(values))).to_double();
        EXPECT_NEAR(printed, formed, 1e-9 * std::max(1.0, std::abs(formed))) << "expression " << i;
    }
    EXPECT_EQ(next, t.definitions.size());
}

namespace {
// random expressions over a few symbols that share subexpressions (each new node built from
// two earlier ones), with sums that lead negative inside products and trigonometric
// arguments, powers and quotients: the cases where the printer decides a sign by printing
std::vector<ex> shared_random_expressions(unsigned seed, int nodes) {
    std::mt19937 rng(seed);
    std::vector<ex> pool{GiNaC::symbol("a"), GiNaC::symbol("b"), GiNaC::symbol("c"),
                         GiNaC::symbol("qA"), GiNaC::symbol("qB'")};
    const auto pick = [&] { return pool[std::uniform_int_distribution<std::size_t>(0, pool.size() - 1)(rng)]; };
    for (int i = 0; i < nodes; ++i) {
        const ex x = pick(), y = pick();
        const int k = std::uniform_int_distribution<int>(-3, 3)(rng);
        switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
            case 0: pool.push_back(x + k * y); break;
            case 1: pool.push_back(x * (y - pick())); break;
            case 2: pool.push_back(sin(x - y) * cos(k * y + pick())); break;
            case 3: pool.push_back(pow(x - 2 * y, 2 + (k & 1))); break;
            case 4: pool.push_back((x + y) / (pick() - k)); break;
            default: pool.push_back(-x + GiNaC::numeric(k, 2) * y); break;
        }
    }
    return pool;
}
}  // namespace

TEST(Print, OneTextPrinterForManyExpressionsGivesToStringsTexts) {
    // the memo of a TextPrinter spans calls: a node printed as part of one expression is looked
    // up when another holds it, with the text a printer of its own writes
    for (unsigned seed : {1u, 2u, 3u}) {
        const std::vector<ex> pool = shared_random_expressions(seed, 60);
        std::vector<ex> order;
        GiNaC::exset seen;
        for (const ex& e : pool)
            for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
                if (seen.insert(*it).second) order.push_back(*it);
        // largest first (the memo then serves the parts), then the parts in random order
        std::reverse(order.begin(), order.end());
        std::shuffle(order.begin() + static_cast<std::ptrdiff_t>(order.size() / 2), order.end(),
                     std::mt19937(seed));
        TextPrinter text;
        for (const ex& e : order) ASSERT_EQ(text(e), to_string(e)) << "seed " << seed;
        for (const ex& e : order) ASSERT_EQ(text(e), to_string(e)) << "again, seed " << seed;
    }
}

TEST(Print, AbbreviationsMeasuredByOneTextPrinterAcrossCallsMeanTheirExpressions) {
    // a report keeps one printer for all its abbreviated vectors: whatever that printer printed
    // before (the parts shared between calls are looked up), each result with its named parts
    // written back is the expression
    for (unsigned seed : {1u, 2u, 3u}) {
        const std::vector<ex> pool = shared_random_expressions(seed, 64);
        GiNaC::exmap at;  // a random point, the same for every batch
        std::mt19937 rng(seed);
        for (std::size_t i = 0; i < 5; ++i)
            at[pool[i]] = std::uniform_real_distribution<double>(0.3, 1.7)(rng);
        TextPrinter shared;
        for (std::size_t start = 0; start + 8 <= pool.size(); start += 8) {
            const std::vector<ex> batch(pool.end() - static_cast<std::ptrdiff_t>(start) - 8,
                                        pool.end() - static_cast<std::ptrdiff_t>(start));
            const AbbreviatedForm f = abbreviate_form(batch, shared, 30, "w");
            ASSERT_EQ(f.results.size(), batch.size());
            for (std::size_t i = 0; i < batch.size(); ++i) {
                ex want;
                try {
                    want = GiNaC::evalf(batch[i].subs(at));
                } catch (const std::exception&) {
                    continue;  // a denominator of the random expression vanishes there
                }
                // the named parts' values in order (each uses earlier ones), then the result's
                GiNaC::exmap values = at;
                for (std::size_t d = 0; d < f.defined_before[i]; ++d)
                    values[f.definitions[d].first] =
                        GiNaC::evalf(f.definitions[d].second.subs(values));
                const ex got = GiNaC::evalf(f.results[i].subs(values));
                ASSERT_TRUE(GiNaC::is_a<GiNaC::numeric>(got) && GiNaC::is_a<GiNaC::numeric>(want));
                const double g = GiNaC::ex_to<GiNaC::numeric>(got).to_double();
                const double w = GiNaC::ex_to<GiNaC::numeric>(want).to_double();
                EXPECT_NEAR(g, w, 1e-9 * std::max(1.0, std::abs(w)))
                    << "seed " << seed << ", " << to_string(batch[i]);
            }
        }
    }
}
