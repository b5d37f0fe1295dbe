// SPDX-License-Identifier: MIT
// Declared constraints: closed loops (configuration) and rolling (motion).
#include <algorithm>

#include "alembert/error.hpp"
#include "alembert/mech/system.hpp"
#include "alembert/sym/print.hpp"

namespace alembert {

const char* to_string(ConstraintKind kind) {
    return kind == ConstraintKind::configuration ? "configuration" : "motion";
}

namespace {

// the time-varying symbols of e at derivative order `order` (specified inputs included)
std::vector<ex> symbols_at_order(const SymbolTable& st, const ex& e, int order) {
    std::vector<ex> out;
    for (const ex& s : symbols_of(e)) {
        if (!st.owns(s)) continue;
        SymbolKind k = st.kind(s);
        if ((k == SymbolKind::variable || k == SymbolKind::specified) &&
            st.derivative_order(s) == order)
            out.push_back(s);
    }
    return out;
}

std::string names(const std::vector<ex>& xs) {
    std::string s;
    for (const ex& x : xs) s += (s.empty() ? "'" : ", '") + to_string(x) + "'";
    return s;
}

}  // namespace

const Constraint& System::add_constraint(const std::string& name, ConstraintKind kind,
                                         const ex& residual, const char* caller) {
    const std::string what = std::string(caller) + ": " + to_string(kind) + " constraint '" + name + "'";
    if (name.empty())
        throw ArgumentError(std::string(caller) + ": a constraint needs a non-empty name");
    if (std::any_of(constraints_.begin(), constraints_.end(),
                    [&](const Constraint& c) { return c.name == name; }))
        throw ArgumentError(what + " is declared already; give each constraint its own name");
    const SymbolTable& st = *table_;
    ex e = st.expand_intermediates(residual);
    if (e.is_zero())
        throw ArgumentError(what + " is identically zero, so it constrains nothing; check its "
                            "expression");
    std::vector<ex> speeds = symbols_at_order(st, e, 1), accs;
    for (int k = 2; k <= 4; ++k)
        for (const ex& a : symbols_at_order(st, e, k)) accs.push_back(a);
    if (!accs.empty())
        throw ArgumentError(what + " holds " + names(accs) +
                            "; declare constraints at the configuration or velocity level, "
                            "Alembert takes their time derivatives where needed");
    if (kind == ConstraintKind::configuration && !speeds.empty())
        throw ArgumentError(what + " holds the speed(s) " + names(speeds) +
                            "; a constraint on speeds is a motion constraint "
                            "(add_motion_constraint)");
    if (kind == ConstraintKind::motion) {
        if (speeds.empty())
            throw ArgumentError(what + " holds no speed; a constraint on the configuration "
                                "alone is a configuration constraint "
                                "(add_configuration_constraint)");
        for (const ex& u : speeds) {
            ex c = e.diff(GiNaC::ex_to<GiNaC::symbol>(u));
            for (const ex& w : speeds)
                if (c.has(w))
                    throw ArgumentError(what + " is not linear in the speeds (the coefficient "
                                        "of '" + to_string(u) + "' holds '" + to_string(w) +
                                        "'); motion constraints must be linear in the speeds");
        }
    }
    constraints_.push_back(Constraint{name, kind, residual});
    return constraints_.back();
}

const Constraint& System::add_configuration_constraint(const std::string& name,
                                                       const ex& residual) {
    return add_constraint(name, ConstraintKind::configuration, residual,
                          "System::add_configuration_constraint()");
}

const Constraint& System::add_motion_constraint(const std::string& name, const ex& residual) {
    return add_constraint(name, ConstraintKind::motion, residual,
                          "System::add_motion_constraint()");
}

std::vector<Constraint> System::add_vector_constraint(const std::string& name,
                                                     ConstraintKind kind, const Vector& v,
                                                     const Frame& F, const char* caller) {
    Col3 c = v.components_in(F);
    // all measures or none: a later one failing leaves the earlier ones undeclared
    const std::size_t before = constraints_.size();
    std::vector<Constraint> out;
    try {
        for (int i = 0; i < 3; ++i)
            if (!c[i].is_zero())
                out.push_back(add_constraint(name + "_" + static_cast<char>('x' + i), kind, c[i], caller));
    } catch (...) {
        constraints_.resize(before);
        throw;
    }
    if (out.empty())
        throw ArgumentError(std::string(caller) + ": constraint '" + name +
                            "' is the zero vector in " + F.name() +
                            ", so it constrains nothing; check the points or vectors that "
                            "define it");
    return out;
}

std::vector<Constraint> System::add_configuration_constraint(const std::string& name,
                                                             const Vector& v, const Frame& F) {
    return add_vector_constraint(name, ConstraintKind::configuration, v, F,
                                 "System::add_configuration_constraint()");
}

std::vector<Constraint> System::add_motion_constraint(const std::string& name, const Vector& v,
                                                      const Frame& F) {
    return add_vector_constraint(name, ConstraintKind::motion, v, F,
                                 "System::add_motion_constraint()");
}

}  // namespace alembert
