// SPDX-License-Identifier: MIT
// The coordinates' kinematics, the power of each load measure, and results per kg of body mass.
#include "alembert/biomech/inverse_results.hpp"

#include <algorithm>
#include <cmath>

#include "alembert/eom/kane.hpp"
#include "alembert/error.hpp"
#include "alembert/sym/derivative.hpp"

namespace alembert {

Table calc_coordinate_table(const MotionSamples& motion,
                            const std::vector<std::string>& quantities) {
    const std::size_t n = motion.coordinates.size();
    ALEMBERT_CHECK_ARG(
        quantities.size() == n,
        "calc_coordinate_table(): " + std::to_string(quantities.size()) + " kinds for " +
            std::to_string(n) +
            " coordinates; give one kind (\"angle\", \"length\" or \"\") per coordinate");
    Table table;
    table.add_column("t", "s");
    table.columns[0] = motion.t;
    for (std::size_t i = 0; i < n; ++i) {
        // the unit of q, q', q'' by the coordinate's kind
        const std::string& kind = quantities[i];
        ALEMBERT_CHECK_ARG(kind.empty() || kind == "angle" || kind == "length",
                           "calc_coordinate_table(): coordinate '" + motion.coordinates[i] +
                               "' is of kind '" + kind + "'; give \"angle\", \"length\" or \"\"");
        const std::string base = kind == "angle" ? "rad" : kind == "length" ? "m" : "";
        const std::string& q = motion.coordinates[i];
        table.columns[table.add_column(q, base)] = motion.q[i];
        table.columns[table.add_column(q + "'", base.empty() ? "" : base + "/s")] = motion.qd[i];
        table.columns[table.add_column(q + "''", base.empty() ? "" : base + "/s^2")] =
            motion.qdd[i];
    }
    return table;
}

LoadRates::LoadRates(const System& sys, const std::vector<TimeVariable>& q,
                     const std::vector<ex>& loads) {
    const SymbolTable& table = sys.symbols();
    // the generalized active forces, every load and gravity, with u_r = q_r'
    std::vector<ex> F = form_generalized_active_forces(sys, q);
    for (ex& f : F) f = table.expand_intermediates(f);
    // rate_j = sum_r dF_r/dT_j q_r'
    for (const ex& T : loads) {
        const std::string name = table.name(T);
        ALEMBERT_CHECK_ARG(GiNaC::is_a<GiNaC::symbol>(T),
                           "LoadRates(): '" + name + "' is not a symbol; list the load measures");
        const auto& s = GiNaC::ex_to<GiNaC::symbol>(T);
        ex rate = 0;
        DerivativeMemo d_ds(s);  // the F_r share most of their terms
        for (std::size_t r = 0; r < q.size(); ++r) rate += d_ds(F[r]) * q[r].d(1);
        ALEMBERT_CHECK_ARG(!rate.has(T),
                           "LoadRates(): the model's loads hold '" + name +
                               "' other than linearly, so it has no one rate it works "
                               "through; apply it as a torque or force times a vector");
        names_.push_back(name);
        rates_.push_back(rate);
    }
    // one tape of [t, q, q']
    std::vector<ex> inputs{table.time()};
    for (const TimeVariable& v : q) inputs.push_back(v.symbol()), coordinates_.push_back(v.name());
    for (const TimeVariable& v : q) inputs.push_back(v.d(1));
    tape_ = std::make_shared<const CompiledExpressions>(table, inputs, rates_);
}

Table LoadRates::calc_power_table(const Table& loads, const MotionSamples& motion) const {
    const std::string who = "LoadRates::calc_power_table(): ";
    const std::size_t k = rates_.size(), n = coordinates_.size();
    ALEMBERT_CHECK_ARG(loads.names.size() == k + 1,
                       who + "the table has " + std::to_string(loads.names.size() - 1) +
                           " load columns for " + std::to_string(k) + " load measures");
    // where each coordinate sits in the motion
    std::vector<std::size_t> from;
    for (const std::string& name : coordinates_) {
        auto it = std::find(motion.coordinates.begin(), motion.coordinates.end(), name);
        ALEMBERT_CHECK_ARG(it != motion.coordinates.end(),
                           who + "the motion has no coordinate '" + name + "'");
        from.push_back(static_cast<std::size_t>(it - motion.coordinates.begin()));
    }
    std::vector<double> factor;
    Table table;
    table.add_column("t", "s");
    for (std::size_t j = 0; j < k; ++j) {
        factor.push_back(parse_unit(loads.units[j + 1]).factor);
        table.add_column("P_" + loads.names[j + 1], "W");
    }
    // each row of the loads at the motion's sample of its time (rows follow samples in order)
    std::vector<double> in(1 + 2 * n), rate(k);
    std::size_t s = 0;
    for (std::size_t row = 0; row < loads.row_count(); ++row) {
        const double t = loads.columns[0][row];
        while (s < motion.t.size() && motion.t[s] < t) ++s;
        ALEMBERT_CHECK_ARG(s < motion.t.size() && motion.t[s] == t,
                           who + "the motion has no sample at t = " + std::to_string(t) +
                               " s of the loads; give the motion the loads were computed from");
        in[0] = t;
        for (std::size_t i = 0; i < n; ++i)
            in[1 + i] = motion.q[from[i]][s], in[1 + n + i] = motion.qd[from[i]][s];
        tape_->evaluate(in.data(), rate.data());
        table.columns[0].push_back(t);
        for (std::size_t j = 0; j < k; ++j)
            table.columns[j + 1].push_back(factor[j] * loads.columns[j + 1][row] * rate[j]);
    }
    return table;
}

Table calc_per_kg(const Table& table, double body_mass_kg) {
    ALEMBERT_CHECK_ARG(body_mass_kg > 0 && std::isfinite(body_mass_kg),
                       "calc_per_kg(): the body mass " + std::to_string(body_mass_kg) +
                           " kg is not positive; give the subject's mass in kg");
    Table out = table;
    for (std::size_t c = 1; c < out.names.size(); ++c) {
        // the column in SI, then per kg
        const Unit u = parse_unit(out.units[c]);
        std::string per;
        if (u.quantity == "torque")
            per = "N m/kg";
        else if (u.quantity == "force")
            per = "N/kg";
        else if (u.quantity == "power")
            per = "W/kg";
        ALEMBERT_CHECK_ARG(!per.empty(), "calc_per_kg(): column '" + out.names[c] + "' is in '" +
                                             out.units[c] +
                                             "', not a torque, force or power; only loads and "
                                             "powers are given per kg");
        for (double& v : out.columns[c]) v = u.factor * v / body_mass_kg;
        out.units[c] = per;
    }
    return out;
}

}  // namespace alembert
