// SPDX-License-Identifier: MIT
// A straight-line program in single-assignment form: value kinds and operation counts.
#include "alembert/sym/program.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>

#include "alembert/error.hpp"

namespace alembert {

const char* to_string(ProgramOp op) {
    switch (op) {
        case ProgramOp::combine: return "combine";
        case ProgramOp::sincos: return "sincos";
        case ProgramOp::add: return "add";
        case ProgramOp::sub: return "sub";
        case ProgramOp::mul: return "mul";
        case ProgramOp::div: return "div";
        case ProgramOp::pow: return "pow";
        case ProgramOp::atan2: return "atan2";
        case ProgramOp::neg: return "neg";
        case ProgramOp::sqrt: return "sqrt";
        case ProgramOp::sin: return "sin";
        case ProgramOp::cos: return "cos";
        case ProgramOp::tan: return "tan";
        case ProgramOp::exp: return "exp";
        case ProgramOp::log: return "log";
        case ProgramOp::abs: return "abs";
        case ProgramOp::asin: return "asin";
        case ProgramOp::acos: return "acos";
        case ProgramOp::atan: return "atan";
        case ProgramOp::sinh: return "sinh";
        case ProgramOp::cosh: return "cosh";
        case ProgramOp::tanh: return "tanh";
        case ProgramOp::asinh: return "asinh";
        case ProgramOp::acosh: return "acosh";
        case ProgramOp::atanh: return "atanh";
        case ProgramOp::csgn: return "csgn";
        case ProgramOp::step: return "step";
    }
    return "?";
}

ValueKind StraightLineProgram::kind(std::uint32_t v) const {
    if (v < input_count) return ValueKind::input;
    if (v < first_literal()) return ValueKind::parameter;
    if (v < first_hoisted()) return ValueKind::literal;
    if (v < first_temporary) return ValueKind::hoisted;
    return ValueKind::temporary;
}

std::size_t StraightLineProgram::operation_count(
    const std::vector<ProgramInstruction>& code) const {
    std::size_t n = 0;
    for (const ProgramInstruction& in : code) {
        if (in.op == ProgramOp::sincos) {
            n += 2;
        } else if (in.op == ProgramOp::combine) {
            n += in.b - 1;
            for (std::uint32_t k = in.a; k < in.a + in.b; ++k)
                if (kind(terms[k].value) != ValueKind::literal && std::fabs(terms[k].c) != 1) ++n;
        } else {
            ++n;
        }
    }
    return n;
}

std::size_t StraightLineProgram::call_count(const std::vector<ProgramInstruction>& code) const {
    std::size_t n = 0;
    for (const ProgramInstruction& in : code) {
        if (in.op == ProgramOp::sincos)
            n += 2;
        else if (in.op == ProgramOp::pow || in.op == ProgramOp::atan2 || in.op >= ProgramOp::sqrt)
            ++n;
    }
    return n;
}

}  // namespace alembert

// ---- interpretation ---------------------------------------------------------------------------

namespace alembert {

namespace {

double apply_op(ProgramOp op, double a, double b) {
    switch (op) {
        case ProgramOp::add: return a + b;
        case ProgramOp::sub: return a - b;
        case ProgramOp::mul: return a * b;
        case ProgramOp::div: return a / b;
        case ProgramOp::pow: return std::pow(a, b);
        case ProgramOp::atan2: return std::atan2(a, b);
        case ProgramOp::neg: return -a;
        case ProgramOp::sqrt: return std::sqrt(a);
        case ProgramOp::sin: return std::sin(a);
        case ProgramOp::cos: return std::cos(a);
        case ProgramOp::tan: return std::tan(a);
        case ProgramOp::exp: return std::exp(a);
        case ProgramOp::log: return std::log(a);
        case ProgramOp::abs: return std::fabs(a);
        case ProgramOp::asin: return std::asin(a);
        case ProgramOp::acos: return std::acos(a);
        case ProgramOp::atan: return std::atan(a);
        case ProgramOp::sinh: return std::sinh(a);
        case ProgramOp::cosh: return std::cosh(a);
        case ProgramOp::tanh: return std::tanh(a);
        case ProgramOp::asinh: return std::asinh(a);
        case ProgramOp::acosh: return std::acosh(a);
        case ProgramOp::atanh: return std::atanh(a);
        case ProgramOp::csgn: return a > 0 ? 1.0 : (a < 0 ? -1.0 : 0.0);
        case ProgramOp::step: return a > 0 ? 1.0 : (a < 0 ? 0.0 : 0.5);
        case ProgramOp::combine:
        case ProgramOp::sincos: break;
    }
    return std::nan("");
}

}  // namespace

void evaluate(const StraightLineProgram& p, const double* inputs, const double* parameters,
              double* outputs) {
    std::vector<double> v(p.value_count, 0.0);
    std::copy_n(inputs, p.input_count, v.begin());
    std::copy_n(parameters, p.parameter_count, v.begin() + static_cast<long>(p.input_count));
    std::copy(p.literals.begin(), p.literals.end(), v.begin() + static_cast<long>(p.first_literal()));
    for (const auto* code : {&p.prelude, &p.body})
        for (const ProgramInstruction& in : *code) {
            if (in.op == ProgramOp::combine) {
                double s = 0;
                for (std::uint32_t k = in.a; k < in.a + in.b; ++k)
                    s += p.terms[k].c * v[p.terms[k].value];
                v[in.result] = s;
            } else if (in.op == ProgramOp::sincos) {
                v[in.result] = std::sin(v[in.a]);
                v[in.b] = std::cos(v[in.a]);
            } else {
                v[in.result] = apply_op(in.op, v[in.a], v[in.b]);
            }
        }
    for (std::size_t k = 0; k < p.outputs.size(); ++k) outputs[k] = v[p.outputs[k]];
}

// ---- linear split -------------------------------------------------------------------------------

namespace {

constexpr std::uint32_t kZero = std::numeric_limits<std::uint32_t>::max();

// builds the split program: values numbered as StraightLineProgram requires, binary and unary
// operations shared when repeated
class Builder {
public:
    StraightLineProgram out;

    std::uint32_t next() { return static_cast<std::uint32_t>(out.value_count++); }

    std::uint32_t op(ProgramOp o, std::uint32_t a, std::uint32_t b) {
        if (is_unary(o)) b = a;
        if ((o == ProgramOp::add || o == ProgramOp::mul) && a > b) std::swap(a, b);
        auto key = (std::uint64_t{a} << 32 | b) * 64 + static_cast<std::uint64_t>(o);
        auto [it, fresh] = shared_.try_emplace(key, 0);
        if (!fresh) return it->second;
        it->second = next();
        out.body.push_back({o, it->second, a, b});
        return it->second;
    }

    // sum of c_k v_k over terms, kZero for none
    std::uint32_t combine(const std::vector<ProgramTerm>& t) {
        if (t.empty()) return kZero;
        if (t.size() == 1 && t[0].c == 1) return t[0].value;
        if (t.size() == 1 && t[0].c == -1) return op(ProgramOp::neg, t[0].value, t[0].value);
        auto first = static_cast<std::uint32_t>(out.terms.size());
        out.terms.insert(out.terms.end(), t.begin(), t.end());
        std::uint32_t r = next();
        out.body.push_back({ProgramOp::combine, r, first, static_cast<std::uint32_t>(t.size())});
        return r;
    }

private:
    std::unordered_map<std::uint64_t, std::uint32_t> shared_;
};

struct Nonlinear {
    std::size_t unknown;
};

}  // namespace

StraightLineProgram split_linear(const StraightLineProgram& p,
                                 const std::vector<std::size_t>& unknowns) {
    const std::size_t nx = unknowns.size();
    std::vector<std::ptrdiff_t> which(p.input_count, -1);  // input -> unknown index
    for (std::size_t j = 0; j < nx; ++j) which[unknowns[j]] = static_cast<std::ptrdiff_t>(j);

    // ---- inputs, parameters, numbers (three more: 0, 1, -1) and the prelude, renumbered --------
    Builder b;
    StraightLineProgram& q = b.out;
    q.input_count = p.input_count - nx;
    q.parameter_count = p.parameter_count;
    q.literals = p.literals;
    for (double x : {0.0, 1.0, -1.0}) q.literals.push_back(x);
    q.value_count = q.first_hoisted();
    std::vector<std::uint32_t> map(p.value_count, kZero);
    std::uint32_t next_input = 0;
    for (std::size_t v = 0; v < p.input_count; ++v)
        if (which[v] < 0) map[v] = next_input++;
    for (std::size_t k = 0; k < p.parameter_count + p.literals.size(); ++k)
        map[p.input_count + k] = static_cast<std::uint32_t>(q.input_count + k);
    const auto lit = [&](std::size_t k) {
        return static_cast<std::uint32_t>(q.first_literal() + p.literals.size() + k);
    };
    const std::uint32_t one = lit(1), minus_one = lit(2), zero = lit(0);
    // the prelude reads no input: a copy with its values renumbered
    const auto shift = static_cast<std::int64_t>(q.first_hoisted()) -
                       static_cast<std::int64_t>(p.first_hoisted());
    auto hoisted = [&](std::size_t v) {
        return static_cast<std::uint32_t>(static_cast<std::int64_t>(v) + shift);
    };
    for (std::size_t v = p.first_hoisted(); v < p.first_temporary; ++v) map[v] = hoisted(v);
    for (ProgramInstruction in : p.prelude) {
        if (in.op == ProgramOp::combine) {
            auto first = static_cast<std::uint32_t>(q.terms.size());
            for (std::uint32_t k = in.a; k < in.a + in.b; ++k)
                q.terms.push_back({p.terms[k].c, map[p.terms[k].value]});
            in.a = first;
        } else {
            in.a = map[in.a];
            if (in.op != ProgramOp::sincos) in.b = map[in.b];
            else in.b = hoisted(in.b);
        }
        in.result = hoisted(in.result);
        q.prelude.push_back(in);
    }
    q.value_count = hoisted(p.first_temporary);
    q.first_temporary = q.value_count;

    // ---- the body: each value as rest + sum_j coef_j x_j -------------------------------------
    std::vector<std::vector<std::pair<std::size_t, std::uint32_t>>> coef(p.value_count);
    std::vector<std::uint32_t>& rest = map;  // the part free of x (kZero when nothing)
    for (std::size_t v = 0; v < p.input_count; ++v)
        if (which[v] >= 0) coef[v] = {{static_cast<std::size_t>(which[v]), one}};
    auto depends = [&](std::uint32_t v) { return !coef[v].empty(); };
    auto scale = [&](ProgramOp o, std::uint32_t a, std::uint32_t factor) {
        if (a == kZero) return kZero;
        if (o == ProgramOp::mul && a == one) return factor;
        return b.op(o, a, factor);
    };
    try {
        for (const ProgramInstruction& in : p.body) {
            const ProgramOp o = in.op;
            std::vector<std::uint32_t> reads;
            if (o == ProgramOp::combine)
                for (std::uint32_t k = in.a; k < in.a + in.b; ++k) reads.push_back(p.terms[k].value);
            else
                reads = is_unary(o) || o == ProgramOp::sincos ? std::vector<std::uint32_t>{in.a}
                                                              : std::vector<std::uint32_t>{in.a, in.b};
            bool any = false;
            for (std::uint32_t r : reads) any = any || depends(r);
            if (!any) {
                // free of x: copied
                if (o == ProgramOp::combine) {
                    std::vector<ProgramTerm> t;
                    for (std::uint32_t k = in.a; k < in.a + in.b; ++k)
                        t.push_back({p.terms[k].c, rest[p.terms[k].value]});
                    auto first = static_cast<std::uint32_t>(q.terms.size());
                    q.terms.insert(q.terms.end(), t.begin(), t.end());
                    std::uint32_t r = b.next();
                    q.body.push_back({o, r, first, in.b});
                    rest[in.result] = r;
                } else if (o == ProgramOp::sincos) {
                    std::uint32_t s = b.next(), c = b.next();
                    q.body.push_back({o, s, rest[in.a], c});
                    rest[in.result] = s;
                    rest[in.b] = c;
                } else {
                    rest[in.result] = b.op(o, rest[in.a], rest[in.b]);
                }
                continue;
            }
            // linear in x: sums term by term, products and quotients by a factor free of x
            std::vector<ProgramTerm> terms;
            if (o == ProgramOp::combine)
                for (std::uint32_t k = in.a; k < in.a + in.b; ++k)
                    terms.push_back({p.terms[k].c, p.terms[k].value});
            else if (o == ProgramOp::add)
                terms = {{1, in.a}, {1, in.b}};
            else if (o == ProgramOp::sub)
                terms = {{1, in.a}, {-1, in.b}};
            else if (o == ProgramOp::neg)
                terms = {{-1, in.a}};
            if (!terms.empty()) {
                std::vector<ProgramTerm> r;
                std::map<std::size_t, std::vector<ProgramTerm>> c;
                for (const ProgramTerm& t : terms) {
                    if (rest[t.value] != kZero) r.push_back({t.c, rest[t.value]});
                    for (const auto& [j, cv] : coef[t.value]) c[j].push_back({t.c, cv});
                }
                rest[in.result] = b.combine(r);
                for (auto& [j, t] : c) {
                    std::uint32_t cv = b.combine(t);
                    if (cv != kZero) coef[in.result].push_back({j, cv});
                }
                continue;
            }
            if (o == ProgramOp::mul || o == ProgramOp::div) {
                if (depends(in.b) && (o == ProgramOp::div || depends(in.a)))
                    throw Nonlinear{coef[in.b].front().first};
                const bool left = depends(in.a);
                const std::uint32_t x = left ? in.a : in.b, f = rest[left ? in.b : in.a];
                rest[in.result] = scale(o, rest[x], f);
                for (const auto& [j, cv] : coef[x]) coef[in.result].push_back({j, scale(o, cv, f)});
                continue;
            }
            for (std::uint32_t r : reads)
                if (depends(r)) throw Nonlinear{coef[r].front().first};
        }
        // ---- outputs: A = -coefficients, row by row, then b ------------------------------------
        const std::size_t n = p.outputs.size();
        std::vector<std::uint32_t> A(n * nx, zero);
        for (std::size_t i = 0; i < n; ++i) {
            for (const auto& [j, cv] : coef[p.outputs[i]])
                A[i * nx + j] = cv == one ? minus_one : b.op(ProgramOp::neg, cv, cv);
        }
        q.outputs = A;
        for (std::size_t i = 0; i < n; ++i) {
            std::uint32_t r = rest[p.outputs[i]];
            q.outputs.push_back(r == kZero ? zero : r);
        }
    } catch (const Nonlinear& bad) {
        throw SolveError("split_linear(): an output is not linear in unknown " +
                         std::to_string(bad.unknown) + " (input " +
                         std::to_string(unknowns[bad.unknown]) +
                         "): it is multiplied by another unknown or inside a function");
    }
    return q;
}

}  // namespace alembert
