// SPDX-License-Identifier: MIT
// Motions: sampled data filtered and differentiated; formulas of time differentiated exactly.
#include "alembert/sim/motion.hpp"

#include <cmath>
#include <cstdio>

#include "alembert/error.hpp"
#include "alembert/sim/filter.hpp"
#include "alembert/sim/time_grid.hpp"

namespace alembert {

namespace {

// d/dt with the derivatives of step and csgn taken as zero (they are impulses at switches)
ex derivative(const ex& e, const GiNaC::symbol& t) {
    struct DropSwitchImpulses : GiNaC::map_function {
        ex operator()(const ex& x) override {
            if (GiNaC::is_a<GiNaC::fderivative>(x)) {
                const unsigned serial = GiNaC::ex_to<GiNaC::function>(x).get_serial();
                if (serial == GiNaC::step_SERIAL::serial || serial == GiNaC::csgn_SERIAL::serial)
                    return 0;
            }
            return x.map(*this);
        }
    } drop;
    return drop(e.diff(t));
}

std::string where(const Table& table, const std::string& source, std::size_t row) {
    return source + ":" +
           (row < table.lines.size() ? std::to_string(table.lines[row])
                                     : "row " + std::to_string(row + 1)) +
           ": ";
}

// the unit the model declares coordinate i in, or no unit when it does not say (or says in
// a unit this reader does not know)
Unit declared_unit(const MotionFilterOptions& options, std::size_t i) {
    if (i >= options.declared_units.size() || options.declared_units[i].empty()) return {};
    try {
        return parse_unit(options.declared_units[i]);
    } catch (const ArgumentError&) {
        return {};
    }
}

// a number as people write it: 6 significant digits, no trailing zeros
std::string short_number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// "an angle", "a length"
std::string with_article(const std::string& quantity) {
    return (quantity.front() == 'a' ? "an " : "a ") + quantity;
}

// the unit a coordinate column is read in: its own, checked against the coordinate's
// declared quantity; or, without one, the assumed unit or SI where that cannot mislead
Unit checked_column_unit(const Unit& column, const Unit& declared, const std::string& why,
                         const Unit& assumed, const std::string& source, const std::string& name) {
    if (!column.quantity.empty()) {
        const bool fits = declared.quantity.empty()
                              ? column.quantity == "angle" || column.quantity == "length"
                              : column.quantity == declared.quantity;
        if (fits) return column;
        const std::string expected =
            declared.quantity.empty() ? "an angle or a length" : with_article(declared.quantity);
        throw ArgumentError(
            source + ": column '" + name + " [" + column.name + "]' is " +
            with_article(column.quantity) + ", but the coordinate '" + name + "' is " + expected +
            (why.empty() ? "" : " (" + why + ")") +
            "; give the column a unit of " + expected + " (" +
            (declared.quantity == "length" ? "m, mm" : declared.quantity == "angle" ? "deg, rad" : "deg, rad, m, mm") +
            ")");
    }
    if (!assumed.quantity.empty() &&
        (declared.quantity.empty() || assumed.quantity == declared.quantity))
        return assumed;
    if (declared.quantity.empty() || declared.factor == 1.0) return Unit{"", 1.0, ""};
    throw ArgumentError(source + ": column '" + name + "' has no unit, but the coordinate '" +
                        name + "' is declared in " + declared.name + "; it is not read as " +
                        (declared.quantity == "angle" ? "rad" : "m") +
                        " silently: write the unit in the header ('" + name + " [" +
                        declared.name + "]'), or say how to read columns without a unit "
                        "(alembert inverse --unitless " + declared.name + ")");
}

}  // namespace

MotionSamples differentiate_motion(const Table& table, const std::string& source,
                                   const std::vector<std::string>& coordinates,
                                   const MotionFilterOptions& options) {
    const std::size_t rows = table.row_count();
    ALEMBERT_CHECK_ARG(rows >= 4, source + ": the motion has " + std::to_string(rows) +
                                      " samples; differentiating it needs at least 4");
    // the time column, in seconds
    std::size_t tc = table.names.size();
    for (std::size_t c = 0; c < table.names.size(); ++c) {
        if (table.names[c] != "t" && table.names[c] != "time") continue;
        ALEMBERT_CHECK_ARG(tc == table.names.size(),
                           source + ": two time columns, '" + table.names[tc] + "' and '" +
                               table.names[c] + "'; keep one of them");
        tc = c;
    }
    std::string found;
    for (const std::string& n : table.names) found += (found.empty() ? "" : ", ") + n;
    ALEMBERT_CHECK_ARG(
        tc < table.names.size(),
        source + ": no time column; name one 't [s]' (columns found: " + found + ")");
    Unit tu;
    try {
        tu = parse_unit(table.units[tc]);
    } catch (const ArgumentError& e) {
        throw ArgumentError(source + ": column '" + table.names[tc] + "': " + e.what());
    }
    ALEMBERT_CHECK_ARG(tu.quantity.empty() || tu.quantity == "time",
                       source + ": the time column '" + table.names[tc] + " [" + tu.name +
                           "]' is in a unit of " + tu.quantity + "; give it a time unit (s or ms)");
    ALEMBERT_CHECK_ARG(options.declared_units.empty() ||
                           options.declared_units.size() == coordinates.size(),
                       source + ": " + std::to_string(options.declared_units.size()) +
                           " declared units for " + std::to_string(coordinates.size()) +
                           " coordinates; give one per coordinate (\"\" if not stated)");
    Unit assumed;
    if (!options.unitless_unit.empty()) {
        try {
            assumed = parse_unit(options.unitless_unit);
        } catch (const ArgumentError& e) {
            throw ArgumentError(source + ": the unit for columns without one: " + e.what());
        }
    }
    MotionSamples m;
    m.coordinates = coordinates;
    for (double v : table.columns[tc]) m.t.push_back(tu.factor * v);

    // increasing times on a uniform grid (rounding within the time column's printed precision
    // is not jitter: calc_uniform_time_base)
    for (std::size_t r = 1; r < rows; ++r)
        if (!(m.t[r] > m.t[r - 1]))
            throw ArgumentError(where(table, source, r) + "time " + std::to_string(m.t[r]) +
                                " s does not increase (previous row: " +
                                std::to_string(m.t[r - 1]) + " s); sort the rows by time");
    const UniformTimeBase base = calc_uniform_time_base(m.t);
    const double h = base.step;
    if (!base.uniform) {
        // the first sample off the grid, and the step that put it there
        std::size_t r = 1;
        while (r + 1 < rows &&
               std::abs(m.t[r] - (m.t.front() + static_cast<double>(r) * h)) <= base.tolerance)
            ++r;
        const double off = m.t[r] - (m.t.front() + static_cast<double>(r) * h);
        throw ArgumentError(
            where(table, source, r) + "time step " + short_number(m.t[r] - m.t[r - 1]) +
            " s (to t = " + short_number(m.t[r]) + " s) puts this sample " +
            short_number(std::abs(off) * 1000) + " ms off the uniform grid of the time column (step " +
            short_number(h) + " s, " + short_number(1 / h) + " Hz), more than " +
            (base.resolution > 0 ? "the rounding of its printed times can explain (" + short_number(base.tolerance) + " s)"
                                 : "1e-6 of the step (its times are written in full)") +
            "; filtering needs uniformly sampled data: resample the motion at one rate, or "
            "correct the time column");
    }

    // per coordinate: SI, filter, differentiate
    for (std::size_t i = 0; i < coordinates.size(); ++i) {
        const std::string& name = coordinates[i];
        std::size_t c = table.names.size();
        for (std::size_t k = 0; k < table.names.size(); ++k)
            if (table.names[k] == name) c = k;
        ALEMBERT_CHECK_ARG(c < table.names.size(), source + ": no column for the coordinate '" +
                                                       name + "'; name a column '" + name +
                                                       " [deg]' (columns found: " + found + ")");
        Unit u;
        try {
            u = parse_unit(table.units[c]);
        } catch (const ArgumentError& e) {
            throw ArgumentError(source + ": column '" + name + "': " + e.what());
        }
        // the coordinate's quantity: its declared unit's, or its kinematics'
        Unit declared = declared_unit(options, i);
        std::string why = declared.quantity.empty() ? "" : "declared in " + declared.name;
        if (declared.quantity.empty() && i < options.kinematic_quantities.size() &&
            !options.kinematic_quantities[i].empty()) {
            const bool angle = options.kinematic_quantities[i] == "angle";
            declared = parse_unit(angle ? "rad" : "m");
            why = angle ? "it turns a frame of the model" : "it moves points of the model and turns no frame";
        }
        u = checked_column_unit(u, declared, why, assumed, source, name);
        std::vector<double> q;
        for (std::size_t r = 0; r < rows; ++r) {
            // a missing value is not data: never filtered into its neighbours
            if (std::isnan(table.columns[c][r]))
                throw ArgumentError(where(table, source, r) + "column '" + name +
                                    "' has no value (NaN) at t = " + short_number(m.t[r]) +
                                    " s; a missing coordinate is not read as data: fill the gap "
                                    "in the lab's software, or trim the motion to where it is known");
            q.push_back(u.factor * table.columns[c][r]);
        }
        if (options.cutoff_hz > 0) q = filter_lowpass(q, 1.0 / h, options.cutoff_hz);
        m.qd.push_back(differentiate(q, h));
        m.qdd.push_back(differentiate_twice(q, h));
        m.q.push_back(std::move(q));
    }
    return m;
}

MotionSamples read_motion(const std::string& path, const std::vector<std::string>& coordinates,
                          const MotionFilterOptions& options) {
    return differentiate_motion(read_csv(path), path, coordinates, options);
}

PrescribedMotion::PrescribedMotion(const SymbolTable& table, const std::vector<TimeVariable>& q,
                                   const std::vector<ex>& formulas) {
    ALEMBERT_CHECK_ARG(q.size() == formulas.size(),
                       "PrescribedMotion(): " + std::to_string(formulas.size()) + " formulas for " +
                           std::to_string(q.size()) +
                           " coordinates; give one formula of time per coordinate");
    const auto& t = GiNaC::ex_to<GiNaC::symbol>(table.time());
    std::vector<ex> outputs, rates, accelerations;
    for (std::size_t i = 0; i < q.size(); ++i) {
        names_.push_back(q[i].name());
        const ex f = table.expand_intermediates(formulas[i]);
        const ex fd = derivative(f, t);
        outputs.push_back(f);
        rates.push_back(fd);
        accelerations.push_back(derivative(fd, t));
    }
    outputs.insert(outputs.end(), rates.begin(), rates.end());
    outputs.insert(outputs.end(), accelerations.begin(), accelerations.end());
    try {
        tape_ = std::make_shared<const CompiledExpressions>(table, std::vector<ex>{table.time()},
                                                            outputs);
    } catch (const ArgumentError& e) {
        throw ArgumentError(std::string("PrescribedMotion(): ") + e.what() +
                            "; a prescribed motion is a formula of time t and constants with "
                            "values");
    }
}

void PrescribedMotion::calc_state(double t, double* q, double* qd, double* qdd) const {
    const std::size_t n = size();
    std::vector<double> out(3 * n);
    tape_->evaluate(&t, out.data());
    for (std::size_t i = 0; i < n; ++i) q[i] = out[i], qd[i] = out[n + i], qdd[i] = out[2 * n + i];
}

MotionSamples PrescribedMotion::sample(const std::vector<double>& times) const {
    const std::size_t n = size();
    MotionSamples m;
    m.coordinates = names_;
    m.t = times;
    m.q.assign(n, std::vector<double>(times.size()));
    m.qd = m.q;
    m.qdd = m.q;
    std::vector<double> q(n), qd(n), qdd(n);
    for (std::size_t k = 0; k < times.size(); ++k) {
        calc_state(times[k], q.data(), qd.data(), qdd.data());
        for (std::size_t i = 0; i < n; ++i)
            m.q[i][k] = q[i], m.qd[i][k] = qd[i], m.qdd[i][k] = qdd[i];
    }
    return m;
}

ex minimum_jerk(const ex& t, double t0, double t1) {
    ALEMBERT_CHECK_ARG(t1 > t0, "minimum_jerk(): the end time must follow the start time");
    const ex u = (t - t0) / (t1 - t0);
    const ex s = 10 * pow(u, 3) - 15 * pow(u, 4) + 6 * pow(u, 5);
    return GiNaC::step(u) * GiNaC::step(1 - u) * s + GiNaC::step(u - 1);
}

}  // namespace alembert
