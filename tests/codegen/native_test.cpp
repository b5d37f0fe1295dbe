// SPDX-License-Identifier: MIT
// The compiled fast path agrees with the tape, caches its library, takes parameters, and
// falls back to the tape with a reason when it cannot compile.
#include "alembert/codegen/native.hpp"

#include "alembert/error.hpp"

#include <utility>
#include <vector>
#include "harness.hpp"
#include "support/expect.hpp"

using namespace alembert;
using namespace alembert::test;

namespace {

// the planar chain's Kane mass matrix and forcing as functions of t, q, q', loads
struct Tape {
    CodegenCase c = planar_chain_case(4);
    std::vector<ex> inputs, outputs;
    Tape() {
        const SymbolTable& T = c.table();
        inputs.push_back(T.time());
        for (const TimeVariable& q : c.equations.coordinates) inputs.push_back(q.d(0));
        for (const TimeVariable& q : c.equations.coordinates) inputs.push_back(q.d(1));
        inputs.insert(inputs.end(), c.equations.loads.begin(), c.equations.loads.end());
        const LinearSystem& D = *c.equations.mass_forcing;
        for (unsigned i = 0; i < D.A.rows(); ++i)
            for (unsigned j = 0; j < D.A.cols(); ++j) outputs.push_back(D.A(i, j));
        for (unsigned i = 0; i < D.b.rows(); ++i) outputs.push_back(D.b(i, 0));
    }
    CompiledExpressions compile(std::vector<ex> parameters = {}) const {
        return CompiledExpressions(c.table(), inputs, outputs, std::move(parameters));
    }
    std::vector<std::vector<double>> states(int count) const {
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> d(-2, 2);
        std::vector<std::vector<double>> out(static_cast<std::size_t>(count));
        for (auto& s : out)
            for (std::size_t i = 0; i < inputs.size(); ++i) s.push_back(d(rng));
        return out;
    }
};

void expect_same(const NativeExpressions& f, const CompiledExpressions& tape,
                 const std::vector<double>& at, double tol) {
    std::vector<double> a(tape.output_count()), b(tape.output_count());
    f(at.data(), a.data());
    tape.evaluate(at.data(), b.data());
    double scale = 1;
    for (double x : b) scale = std::max(scale, std::fabs(x));
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], tol * scale) << k;
}

}  // namespace

TEST(NativeExpressions, CompiledCodeAgreesWithTheTapeAndIsCached) {
    Tape t;
    ScratchDir cache("native-cache");
    // on_compile is told before and after the compiler runs, and not when the library is cached
    std::vector<std::pair<std::size_t, bool>> told;
    NativeOptions o{.compiler = "", .flags = {"-O2"}, .cache_dir = cache.path(),
                    .on_compile = [&](std::size_t operations, bool done) { told.emplace_back(operations, done); }};
    CompiledExpressions tape = t.compile();
    NativeExpressions f(tape, o);
    ASSERT_TRUE(f.is_native()) << f.message();
    EXPECT_EQ(f.status(), NativeStatus::compiled);
    const std::vector<std::pair<std::size_t, bool>> once{{tape.operation_count(), false}, {tape.operation_count(), true}};
    EXPECT_EQ(told, once);
    EXPECT_EQ(f.input_count(), tape.input_count());
    for (const auto& s : t.states(8)) expect_same(f, tape, s, 1e-12);
    // the same expressions again: loaded from the cache, same values
    NativeExpressions g(t.compile(), o);
    ASSERT_TRUE(g.is_native()) << g.message();
    EXPECT_EQ(g.status(), NativeStatus::cached);
    EXPECT_NE(g.message().find("loaded"), std::string::npos);
    EXPECT_EQ(told, once) << "a cached library is not compiled";
    // copies share the library and outlive the original
    NativeExpressions copy = g;
    { NativeExpressions gone = std::move(g); }
    for (const auto& s : t.states(2)) expect_same(copy, tape, s, 1e-12);
}

TEST(NativeExpressions, ParametersAreHoistedAndCanBeChanged) {
    Tape t;
    ScratchDir cache("native-params");
    const SymbolTable& T = t.c.table();
    std::vector<ex> params{T.symbol("g"), T.symbol("m1"), T.symbol("L2")};
    CompiledExpressions tape = t.compile(params);
    NativeExpressions f(tape, {.compiler = "", .flags = {"-O2"}, .cache_dir = cache.path()});
    ASSERT_TRUE(f.is_native()) << f.message();
    for (const auto& s : t.states(3)) expect_same(f, tape, s, 1e-12);
    const std::vector<double> moon{1.62, 2.5, 0.75};
    f.set_parameters(moon);
    tape.set_parameters(moon);
    for (const auto& s : t.states(3)) expect_same(f, tape, s, 1e-12);
    // and the tape with new parameters differs from the default one (they were used)
    CompiledExpressions earth = t.compile(params);
    std::vector<double> a(tape.output_count()), b(tape.output_count()), at = t.states(1)[0];
    f(at.data(), a.data());
    earth.evaluate(at.data(), b.data());
    EXPECT_NE(a, b);
}

TEST(NativeExpressions, FallsBackToTheTapeWithAReason) {
    Tape t;
    ScratchDir cache("native-fallback");
    CompiledExpressions tape = t.compile();
    NativeExpressions none(tape, {.compiler = "/nonexistent/cc", .flags = {}, .cache_dir = cache.path()});
    EXPECT_FALSE(none.is_native());
    EXPECT_EQ(none.status(), NativeStatus::no_compiler);
    EXPECT_NE(none.message().find("no C compiler '/nonexistent/cc' found"), std::string::npos)
        << none.message();
    for (const auto& s : t.states(2)) expect_same(none, tape, s, 0);
    // no directory to compile in: a cache path under a regular file
    const fs::path file = cache.path() / "a_file";
    std::ofstream(file) << "x";
    NativeExpressions homeless(tape, {.compiler = "", .flags = {}, .cache_dir = file / "cache"});
    EXPECT_FALSE(homeless.is_native());
    EXPECT_EQ(homeless.status(), NativeStatus::no_directory);
    EXPECT_NE(homeless.message().find("no directory to compile in"), std::string::npos)
        << homeless.message();
    for (const auto& s : t.states(2)) expect_same(homeless, tape, s, 0);
    // a "compiler" that fails
    NativeExpressions failed(tape, {.compiler = "false", .flags = {}, .cache_dir = cache.path()});
    EXPECT_FALSE(failed.is_native());
    EXPECT_EQ(failed.status(), NativeStatus::compile_failed);
    EXPECT_NE(failed.message().find("failed (exit status 1)"), std::string::npos)
        << failed.message();
    for (const auto& s : t.states(2)) expect_same(failed, tape, s, 0);
    std::vector<double> in(3), out(tape.output_count());
    EXPECT_THROW_MSG(failed.evaluate(in, out), ArgumentError,
                     "3 inputs and room for 20 outputs given, 13 and 20 expected");
}

TEST(NativeExpressions, SourceIsTheTapesProgramInC) {
    SymbolTable s;
    ex x = s.add_constant("x"), k = s.add_constant("k", 2.0);
    CompiledExpressions tape(s, {x}, {k * k * GiNaC::sin(x) + 1}, {k});
    std::string src = native_source(tape);
    EXPECT_NE(src.find("fx[1] = fx[0]*fx[0];"), std::string::npos) << src;  // k^2 once
    EXPECT_NE(src.find("sin(in[0])"), std::string::npos) << src;
    EXPECT_NE(src.find("void alembert_body(const double* in, const double* fx, double* out)"),
              std::string::npos);
}
