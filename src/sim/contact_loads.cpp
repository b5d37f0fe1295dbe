// SPDX-License-Identifier: MIT
// Contact loads in simulation: which unknown measures the road-map determines, and their rows.
#include "alembert/sim/contact_loads.hpp"

#include <algorithm>
#include <functional>
#include <set>

#include "alembert/eom/kane.hpp"
#include "alembert/eom/planner.hpp"
#include "alembert/eom/statics.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/print.hpp"

namespace alembert {

namespace {

bool in_contact_list(const std::vector<ex>& list, const ex& x) {
    return std::any_of(list.begin(), list.end(), [&](const ex& y) { return y.is_equal(x); });
}

std::string quoted_contact_names(const std::vector<ex>& list) {
    std::string text;
    for (const ex& x : list) text += (text.empty() ? "'" : ", '") + to_string(x) + "'";
    return text;
}

// the arguments of the abs() calls inside `e`, each shared subexpression visited once
void collect_abs_arguments(const ex& e, std::set<ex, GiNaC::ex_is_less>& seen,
                           std::vector<ex>& found) {
    if (GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::numeric>(e)) return;
    if (!seen.insert(e).second) return;
    if (GiNaC::is_a<GiNaC::function>(e) &&
        GiNaC::ex_to<GiNaC::function>(e).get_serial() == GiNaC::abs_SERIAL::serial &&
        !in_contact_list(found, e.op(0)))
        found.push_back(e.op(0));
    for (std::size_t i = 0; i < e.nops(); ++i) collect_abs_arguments(e.op(i), seen, found);
}

// the abs() arguments of the loads of `sys`, in the order of the loads
std::vector<ex> abs_arguments_of_loads(const System& sys) {
    std::set<ex, GiNaC::ex_is_less> seen;
    std::vector<ex> found;
    for (const Load& load : sys.loads())
        for (const Vector::Component& c : load.vector.components())
            for (const ex& e : c.second.v) collect_abs_arguments(e, seen, found);
    return found;
}

std::vector<ex> unknowns_for(const std::vector<TimeVariable>& q, const std::vector<ex>& solved,
                             const std::vector<ex>& more) {
    std::vector<ex> unknowns;
    for (const TimeVariable& qi : q) unknowns.push_back(qi.d(2));
    unknowns.insert(unknowns.end(), solved.begin(), solved.end());
    unknowns.insert(unknowns.end(), more.begin(), more.end());
    return unknowns;
}

bool plans(const System& sys, const std::vector<TimeVariable>& q, const std::vector<ex>& unknowns) {
    try {
        plan_roadmap(sys, q, unknowns, Analysis::dynamics);
        return true;
    } catch (const ModelError&) {
        return false;
    }
}

}  // namespace

ContactLoads find_contact_loads(const System& sys, const std::vector<TimeVariable>& q,
                                const std::vector<ex>& solved, const exmap& inputs,
                                const std::vector<ex>& reads, const std::string& who) {
    const SymbolTable& table = sys.symbols();
    const std::vector<ex> abs_arguments = abs_arguments_of_loads(sys);

    // the candidates: a friction's normal force, or a measure an output or a stop condition reads
    std::vector<ex> candidates, normals;
    for (const ex& m : table.symbols(SymbolKind::unknown)) {
        if (in_contact_list(solved, m) || inputs.count(m)) continue;
        const auto holds = [&](const ex& e) { return table.depends_on(e, m); };
        const bool normal = std::any_of(abs_arguments.begin(), abs_arguments.end(), holds);
        if (normal) normals.push_back(m);
        if (normal || std::any_of(reads.begin(), reads.end(), holds)) candidates.push_back(m);
    }
    ContactLoads found;
    const auto finish = [&](std::vector<ex> measures) {
        found.measures = std::move(measures);
        for (const ex& a : abs_arguments)
            if (std::any_of(found.measures.begin(), found.measures.end(),
                            [&](const ex& m) { return table.depends_on(a, m); }))
                found.abs_arguments.push_back(a);
        return found;
    };
    if (candidates.empty() || plans(sys, q, unknowns_for(q, solved, candidates)))
        return finish(candidates);

    // some have no row: name them, or leave out the applied loads (an idle motor)
    std::vector<ex> determined;
    std::vector<ex> forces;  // the generalized active forces, formed when first needed
    bool formed = false;
    for (const ex& m : candidates) {
        if (plans(sys, q, unknowns_for(q, solved, {m}))) {
            determined.push_back(m);
            continue;
        }
        const std::string name = to_string(m);
        if (in_contact_list(normals, m))
            throw ModelError(who + "the friction's normal force '" + name +
                             "' is not given and no road-map row determines it (no load on a "
                             "body holds it along a direction the coordinates do not move); "
                             "apply it as a force on the body it presses (force normal on P = " +
                             name + "*u>) or give it by an input (input " + name + " = ...)");
        if (!formed) {
            forces = form_generalized_active_forces(sys, q, LoadSelection::all);
            formed = true;
        }
        const bool does_work = std::any_of(forces.begin(), forces.end(), [&](const ex& f) {
            return table.depends_on(f, m);
        });
        if (does_work) continue;  // an applied load, zero unless given
        throw ModelError(who + "'" + name +
                         "' is read by an output or a stop condition, but it does no work in "
                         "the coordinates and no road-map row determines it alone, so its "
                         "value is not known; give it by an input (input " + name +
                         " = ...), or declare what determines it (a joint reaction, or the "
                         "other contact forces on the same body as unknowns)");
    }
    if (!determined.empty()) {
        try {
            plan_roadmap(sys, q, unknowns_for(q, solved, determined), Analysis::dynamics);
        } catch (const ModelError& e) {
            throw ModelError(who + "the contact forces " + quoted_contact_names(determined) +
                             " cannot be solved together with the accelerations: " + e.what());
        }
    }
    return finish(determined);
}

ContactRows plan_contact_rows(const System& sys, const std::vector<TimeVariable>& q,
                              const std::vector<ex>& measures) {
    ContactRows rows;
    rows.unknowns = unknowns_for(q, measures, {});
    rows.residuals = residuals_of(plan_roadmap(sys, q, rows.unknowns, Analysis::dynamics));
    return rows;
}

LinearSystem form_contact_equations(const ContactRows& rows, const std::vector<ex>& abs_arguments,
                                    const std::vector<int>& signs) {
    exmap assumed;
    for (std::size_t i = 0; i < abs_arguments.size(); ++i)
        assumed[GiNaC::abs(abs_arguments[i])] = signs.at(i) * abs_arguments[i];
    std::vector<ex> residuals;
    for (const ex& r : rows.residuals) residuals.push_back(r.subs(assumed));
    return form_linear_system(residuals, rows.unknowns);
}

}  // namespace alembert
