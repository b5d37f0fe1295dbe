// SPDX-License-Identifier: MIT
// Small programs, one per target language, that load generated code, read states from
// standard input and print M, f, forward dynamics, inverse dynamics and outputs per state.
#pragma once

#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "harness.hpp"

namespace alembert::test {

inline std::string replace_all(std::string s, const std::string& a, const std::string& b) {
    for (std::size_t at = s.find(a); at != std::string::npos; at = s.find(a, at + b.size()))
        s.replace(at, a.size(), b);
    return s;
}

/// A C99 program on NAME.h: `read`, `print`, NAME_context c initialised, and `per_state` run
/// once per state, count states on standard input (the count first). NAME is replaced.
inline std::string c_driver_frame(const std::string& name, const std::string& per_state) {
    return replace_all(R"(#include <stdio.h>
#include "NAME.h"
static inline int read(double* x, int n) {
    for (int i = 0; i < n; ++i)
        if (scanf("%lf", &x[i]) != 1) return 0;
    return 1;
}
static inline void print(const double* x, int n) {
    for (int i = 0; i < n; ++i) printf("%.17g\n", x[i]);
}
int main(void) {
    NAME_context c;
    NAME_init(&c, 0);
    int count = 0;
    if (scanf("%d", &count) != 1) return 1;
    for (int k = 0; k < count; ++k) {
)" + per_state + R"(    }
    return 0;
}
)",
                       "NAME", name);
}

/// The same in C++ on NAME.hpp (namespace NAME used): `setup` may change the parameters p
/// before `const Model model(p)` is built.
inline std::string cpp_driver_frame(const std::string& name, const std::string& per_state,
                                    const std::string& setup = "") {
    return replace_all(R"(#include <cstdio>
#include <iostream>
#include "NAME.hpp"
using namespace NAME;
inline bool read(double* x, int n) {
    for (int i = 0; i < n; ++i)
        if (!(std::cin >> x[i])) return false;
    return true;
}
inline void print(const double* x, int n) {
    for (int i = 0; i < n; ++i) std::printf("%.17g\n", x[i]);
}
int main() {
    Parameters p;
    )" + setup + R"(
    const Model model(p);
    int count = 0;
    if (!(std::cin >> count)) return 1;
    for (int k = 0; k < count; ++k) {
)" + per_state + R"(    }
    return 0;
}
)",
                       "NAME", name);
}

/// The same in Python on NAME.py in `dir` (imported as m, with ctx = m.Context()): `per_state`
/// is the loop body, indented four spaces, reading with take(k) (the next k numbers, as an
/// array) and printing each number on its line.
inline std::string python_driver_frame(const std::string& name, const std::string& dir,
                                       const std::string& per_state) {
    return replace_all(replace_all(R"(import sys
sys.path.insert(0, "DIR")
import numpy as np
import NAME as m

ctx = m.Context()
data = sys.stdin.read().split()
count, values, at = int(data[0]), [float(x) for x in data[1:]], 0


def take(k):
    global at
    at += k
    return np.array(values[at - k:at])


for _ in range(count):
)" + per_state,
                                   "NAME", name),
                       "DIR", dir);
}

/// A C99 driver of NAME.h: per state t, q, q', q'', u; prints M, f, q'' of forward dynamics,
/// the loads of inverse dynamics and the outputs.
inline std::string c_driver(const std::string& name) {
    return c_driver_frame(name, R"(        double t, q[NAME_NQ], qp[NAME_NQ], qpp[NAME_NQ], u[NAME_NU + 1];
        double M[NAME_NQ * NAME_NQ], f[NAME_NQ], fd[NAME_NQ], id[NAME_NU + 1], y[NAME_NY + 1];
        if (!read(&t, 1) || !read(q, NAME_NQ) || !read(qp, NAME_NQ) || !read(qpp, NAME_NQ) ||
            !read(u, NAME_NU))
            return 1;
        NAME_mass_forcing(&c, t, q, qp, u, M, f);
        if (NAME_forward_dynamics(&c, t, q, qp, u, fd) != 0) return 2;
        print(M, NAME_NQ * NAME_NQ);
        print(f, NAME_NQ);
        print(fd, NAME_NQ);
        NAME_inverse_dynamics(&c, t, q, qp, qpp, id);
        print(id, NAME_NU);
#if NAME_NY > 0
        NAME_outputs(&c, t, q, qp, qpp, u, y);
#endif
        print(y, NAME_NY);
)");
}

/// The same in C++ on NAME.hpp; `setup` may change the parameters p before the model is built.
inline std::string cpp_driver(const std::string& name, const std::string& setup = "") {
    return cpp_driver_frame(name, R"(        double t, q[nq], qp[nq], qpp[nq], u[nu + 1], M[nq * nq], f[nq], fd[nq], id[nq + 1];
        double y[ny + 1];
        if (!read(&t, 1) || !read(q, nq) || !read(qp, nq) || !read(qpp, nq) || !read(u, nu))
            return 1;
        model.mass_forcing(t, q, qp, u, M, f);
        if (!model.forward_dynamics(t, q, qp, u, fd)) return 2;
        print(M, nq * nq);
        print(f, nq);
        print(fd, nq);
        model.inverse_dynamics(t, q, qp, qpp, id);
        print(id, nq);
        if constexpr (ny > 0) model.outputs(t, q, qp, qpp, u, y);
        print(y, ny);
)",
                            setup);
}

/// The same in Python on NAME.py in `dir`.
inline std::string python_driver(const std::string& name, const std::string& dir) {
    return python_driver_frame(name, dir, R"(    t = take(1)[0]
    q, qp, qpp, u = take(m.NQ), take(m.NQ), take(m.NQ), take(m.NU)
    M, f = m.mass_forcing(t, q, qp, u, ctx)
    out = list(M.ravel()) + list(f) + list(m.forward_dynamics(t, q, qp, u, ctx))
    out += list(m.inverse_dynamics(t, q, qp, qpp, ctx))
    if m.NY:
        out += list(m.outputs(t, q, qp, qpp, u, ctx))
    print("\n".join(repr(float(x)) for x in out))
)");
}

/// An Octave script driving NAME_*.m on the rows of states.txt (t, q, q', q'', u per row).
inline std::string octave_driver(const std::string& name, std::size_t n, std::size_t m,
                                 bool outputs) {
    std::string s = R"(X = load('states.txt');
ctx = NAME_context();
for k = 1:size(X, 1)
    r = X(k, :)';
    t = r(1); q = r(2:N+1); qp = r(N+2:2*N+1); qpp = r(2*N+2:3*N+1); u = r(3*N+2:3*N+1+U);
    [M, f] = NAME_mass_forcing(t, q, qp, u, ctx);
    Mt = M';
    printf('%.17g\n', [Mt(:); f; NAME_forward_dynamics(t, q, qp, u, ctx); NAME_inverse_dynamics(t, q, qp, qpp, ctx)]);
)";
    if (outputs) s += "    printf('%.17g\\n', NAME_outputs(t, q, qp, qpp, u, ctx));\n";
    s += "end\n";
    s = replace_all(s, "NAME", name);
    s = replace_all(s, "N+", std::to_string(n) + "+");
    s = replace_all(s, "*N", "*" + std::to_string(n));
    return replace_all(s, "+U", "+" + std::to_string(m));
}

/// The C compiler generated code is built with: $CC, else cc.
inline std::string c_compiler() {
    const char* cc = std::getenv("CC");
    return cc && *cc ? cc : "cc";
}

/// Whether the C compiler runs (the tests that compile skip without one).
inline bool have_c_compiler() {
    std::string out;
    return run(c_compiler() + " --version", out) == 0;
}

/// A file's whole text.
inline std::string file_text(const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The generated C NAME.c in `dir` compiled with a C driver (`driver`, written to driver.c;
/// c_driver_frame) as strict C99 into `dir`/driver, which is run on `input` (written to
/// states.txt): the numbers it prints. When compiling or running fails, a test failure naming
/// the step with the compiler's or the driver's output is added and nothing is returned.
/// `optimization` is the compiler's -O flag: -O2 as users build, -O0 where a large file's
/// optimization would take most of the test's time and the values do not depend on it.
inline std::optional<std::vector<double>> compile_and_run_c_driver(const fs::path& dir,
                                                                   const std::string& name,
                                                                   const std::string& driver,
                                                                   const std::string& input,
                                                                   const std::string& optimization = "-O2") {
    std::string out;
    write(dir / "driver.c", driver);
    if (run("cd " + dir.string() + " && " + c_compiler() + " -std=c99 -pedantic -Wall -Wextra -Werror " +
                optimization + " " + name + ".c driver.c -lm -o driver",
            out) != 0) {
        ADD_FAILURE() << "compiling the generated C " << name << ".c failed:\n" << out;
        return std::nullopt;
    }
    write(dir / "states.txt", input);
    if (run("cd " + dir.string() + " && ./driver < states.txt", out) != 0) {
        ADD_FAILURE() << "the driver of " << name << ".c failed:\n" << out;
        return std::nullopt;
    }
    return numbers(out);
}

}  // namespace alembert::test
