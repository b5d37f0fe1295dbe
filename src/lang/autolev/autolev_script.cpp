// SPDX-License-Identifier: MIT
// The Alembert script assembled from a translated Autolev file: declarations, the model, Kane's
// equations, values and settings.
#include "autolev_translator.hpp"

namespace alembert::lang::autolev {

std::string Translator::kane_statement() {
    std::vector<std::string> coordinates, speeds, residuals;
    for (const KinematicEquation& k : kinematics_) {
        coordinates.push_back(k.coordinate);
        residuals.push_back(k.residual);
    }
    if (!odes_.empty()) {  // a model given by its equations X'' = f
        coordinates.clear();
        residuals.clear();
        for (const std::string& v : variables_)
            for (const auto& [x, where] : odes_)
                if (x == v) coordinates.push_back(v);
    } else if (coordinates.empty()) {
        for (const std::string& v : variables_)
            if (!rate_of_.count(v) && !given_.count(v)) coordinates.push_back(v);
    } else {
        // the speeds are the variables the kinematical (or constraint) equations name; an
        // auxiliary speed that is its own constraint (AUXILIARY[1] = U4) is not among them
        for (const std::string& v : variables_) {
            if (std::find(coordinates.begin(), coordinates.end(), v) != coordinates.end() || given_.count(v)) continue;
            bool named = false, auxiliary = false;
            for (std::size_t i = 0; i < aux_speeds_.size(); ++i)
                auxiliary = auxiliary || (aux_speeds_[i] == v && aux_constraints_[i].first == v);
            if (auxiliary) continue;
            for (const std::string& r : residuals) named = named || mentions(r, v);
            for (const std::string& c : constraints_) named = named || mentions(c, v);
            for (const auto& [c, where] : aux_constraints_) named = named || mentions(c, v);
            if (named) {
                speeds.push_back(v);
                continue;
            }
            // a coordinate used with its own rate among coordinates with speeds: Kane's
            // statement takes one kinematical equation for each coordinate
            const Entry* en = find(v);
            report(Severity::error, en ? en->where : kane_where_,
                   "'" + v + "' has no kinematical equation, while " + kinematics_.front().coordinate + " has one (" +
                       kinematics_.front().coordinate + "' = ...)",
                   "give '" + v + "' a speed and its equation (" + v + "' = U" + v + ") or write the other "
                   "speeds as rates (" + kinematics_.front().coordinate + "' = U with U a speed)");
        }
    }
    std::string name = "K";
    for (int k = 2; find(name) || labels_.count(name); ++k) name = "K" + std::to_string(k);
    kane_name_ = name;
    std::string s = "kane " + name + " for " + join(coordinates);
    if (speeds.empty() && !constraints_.empty() && odes_.empty()) {
        // CONSTRAIN(DEPENDENT[Q1']) in a model without speeds: the kane statement's constraints
        // need speeds, so each coordinate gets one equal to its rate, u = q', and the rates the
        // file names dependent are those speeds
        std::vector<std::string> said;
        for (const std::string& q : coordinates) {
            const std::string u = fresh_name(q + "_u");
            rate_speeds_.emplace_back(q, u);
            speeds.push_back(u);
            residuals.push_back(q + "' - " + u);
            said.push_back(u + " = " + q + "'");
        }
        std::vector<std::string> rates;
        for (std::string& d : dependent_) {
            if (d.empty() || d.back() != '\'') {
                report(Severity::error, dependent_where_.empty() ? kane_where_ : dependent_where_.front(),
                       "DEPENDENT[" + d + "] names a variable that is no speed: the model has no kinematical "
                       "equations (Q1' = U1), so its speeds are the coordinates' rates",
                       "name the dependent rates, CONSTRAIN(DEPENDENT[Q1']), or declare speeds and their kinematical "
                       "equations");
                continue;
            }
            const std::string q = d.substr(0, d.size() - 1);
            for (const auto& [c, u] : rate_speeds_)
                if (c == q) {
                    rates.push_back(u + " (of " + d + ")");
                    d = u;
                }
        }
        report(Severity::note, constraints_where_ ? *constraints_where_ : kane_where_,
               "the model has no speeds: each coordinate is given one equal to its rate (" + join(said) +
                   "), as the kane statement's constraints need; " + join(rates) + " " +
                   (rates.size() == 1 ? "is" : "are") + " dependent");
    }
    // auxiliary speeds: AUXILIARY[i] = U4 with U4 listed makes U4 an auxiliary speed; another
    // constraint E with U2 listed is opened by a new speed UA written into it as its violation
    // (E - UA = 0), U2 dependent: the same motion (UA = 0) and, for UA, U2's partial velocities
    // times d U2 / d UA, which is not zero: the same auxiliary equation times that factor
    std::vector<std::string> constraints = constraints_, dependent = dependent_, auxiliary;
    aux_opened_.clear();
    for (std::size_t i = 0; i < aux_speeds_.size(); ++i) {
        const std::string& u = aux_speeds_[i];
        const std::string& c = aux_constraints_[i].first;
        if (c == u) {
            auxiliary.push_back(u);
            continue;
        }
        std::string ua = "UA_" + u;
        for (int k = 2; find(ua) || extra_names_.count(ua); ++k) ua = "UA_" + u + "_" + std::to_string(k);
        extra_names_.insert({ua, 0});
        aux_opened_.push_back(ua);
        auxiliary.push_back(ua);
        constraints.push_back("(" + c + ") - " + ua);
        dependent.push_back(u);
    }
    if (!speeds.empty()) {
        for (std::size_t i = 0; i < dependent_.size(); ++i)
            if (!dependent_[i].empty() && dependent_[i].back() == '\'')
                report(Severity::error, i < dependent_where_.size() ? dependent_where_[i] : kane_where_,
                       "DEPENDENT[" + dependent_[i] + "] names a rate in a model with speeds",
                       "name the dependent speed: CONSTRAIN(DEPENDENT[U3])");
        s += " speeds " + join(speeds) + " \\\n  kinematics [" + join(residuals) + "]";
        if (!constraints.empty())
            s += " \\\n  constraints [" + join(constraints) + "] dependent " + join(dependent);
        if (!auxiliary.empty()) s += " \\\n  auxiliary " + join(auxiliary);
    } else if (!constraints_.empty()) {
        report(Severity::error, kane_where_, "constraints (DEPENDENT[...]) in a model given by its differential "
                                             "equations are not translated",
               "write the constraint into the equations, or give the model by its bodies and KANE()");
    } else if (!aux_speeds_.empty()) {
        report(Severity::error, aux_constraints_.front().second,
               "auxiliary speeds (AUXILIARY[...]) in a model without speeds are not translated",
               "declare speeds U with MOTIONVARIABLES and kinematical equations Q1' = U1");
    }
    return s;
}

bool Translator::mentions(const std::string& s, const std::string& n) {
    for (std::size_t at = s.find(n); at != std::string::npos; at = s.find(n, at + 1)) {
        auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; };
        bool starts = at == 0 || !word(s[at - 1]);
        bool ends = at + n.size() == s.size() || !word(s[at + n.size()]);
        if (starts && ends) return true;
    }
    return false;
}

void Translator::find_given_variables() {
    if (!kane_at_ || (kinematics_.empty() && rate_of_.empty())) return;
    for (const std::string& v : variables_) {
        if (rate_of_.count(v)) continue;
        bool coordinate = aliased_coordinates_.count(v) > 0, named = false;
        for (const KinematicEquation& k : kinematics_) {
            coordinate = coordinate || k.coordinate == v;
            named = named || mentions(k.residual, v);
        }
        for (const std::string& c : constraints_) named = named || mentions(c, v);
        for (const auto& [c, where] : aux_constraints_) named = named || mentions(c, v);
        // a variable declared and used with derivatives (X'' in V_P_N> = X'*N1>) is a coordinate
        if (coordinate || named || primes_[v] > 0 || used_primes_[v] > 0) continue;
        given_.insert(v);
        const Entry* en = find(v);
        report(Severity::note, en ? en->where : kane_where_,
               "'" + v + "' is neither a coordinate nor a speed (no kinematical equation names it); it is "
               "declared as a specified quantity, a given function of time",
               "give its value with INPUT " + v + " = ..., or a kinematical equation if it is a speed");
    }
}

void Translator::assemble() {
    check_differential_model();
    // KANE(F1, ...): the load measures the auxiliary equations determine are the script's
    // unknowns, whatever the file declared them as
    std::vector<std::string> unknowns;
    for (const auto& force : kane_forces_) {
        const std::string& f = force.first;
        const Location where = force.second;
        if (std::find(unknowns.begin(), unknowns.end(), f) != unknowns.end()) continue;
        unknowns.push_back(f);
        variables_.erase(std::remove(variables_.begin(), variables_.end(), f), variables_.end());
        specified_.erase(std::remove_if(specified_.begin(), specified_.end(),
                                        [&](const std::string& x) { return x.substr(0, x.find('\'')) == f; }),
                         specified_.end());
        report(Severity::note, where,
               "'" + f + "' is declared as an unknown load measure: simulate solves the auxiliary equations for "
               "it at every row (a column of its own), and solving Kane's equations for it gives it",
               "");
    }
    if (!odes_.empty() && !kane_at_) kane_at_ = model_.size(), emit("");
    find_given_variables();
    for (const auto& [p, where] : forced_points_) {
        auto it = point_body_.find(p);
        const Entry* body = it == point_body_.end() ? nullptr : object_spelt(it->second);
        if (!body || body->kind != Kind::body)
            report(Severity::error, where, "the force at point '" + p + "' acts on no body",
                   "Alembert applies forces at points fixed on a body: say which body '" + p +
                       "' is fixed on with V2PTS(N, B, O, " + p + "), or apply the force at a particle");
    }
    // kinematical and constraint equations are part of Kane's equations; without KANE() they
    // have no place in the script, which is said, not left to silence
    if (!kane_at_ && !kinematics_.empty())
        not_translated(kinematics_.front().where, "the kinematical equation " + kinematics_.front().residual + " = 0" +
                           (kinematics_.size() > 1 ? " (and " + std::to_string(kinematics_.size() - 1) + " more)" : ""),
                       "kinematical equations are part of Kane's equations, and the file has no KANE()");
    if (!kane_at_ && constraints_where_)
        not_translated(*constraints_where_, "DEPENDENT[...]",
                       "constraint equations are part of Kane's equations, and the file has no KANE()");
    if (kane_at_) {
        if (!kinematics_.empty() && dependent_.size() != constraints_.size())
            report(Severity::error, kane_where_,
                   std::to_string(constraints_.size()) + " constraints (DEPENDENT[...] = ...) but " +
                       std::to_string(dependent_.size()) + " dependent speeds",
                   "name the dependent speeds with CONSTRAIN(DEPENDENT[U3, ...]) before KANE()");
        model_[*kane_at_] = kane_statement();
        say_model_changes();
        // SOLVE(ZERO, ...) solves Kane's equations, named now
        for (std::string& l : model_)
            for (std::size_t at = l.find('\x02'); at != std::string::npos; at = l.find('\x02', at))
                l.replace(at, 1, kane_name_);
        for (std::string& l : tail_outputs_)
            for (std::size_t at = l.find('\x02'); at != std::string::npos; at = l.find('\x02', at))
                l.replace(at, 1, kane_name_);
    }
    if (!kane_at_) say_model_changes();
    std::string& s = out_.script;
    s = "# " + file_ + ", translated from Autolev by alembert import\n";
    for (const std::string& r : renames_) s += "# renamed: " + r + "\n";
    if (!newtonian_.empty()) s += "newtonian " + newtonian_ + "\n";
    for (const std::string& l : frames_lines_) {
        if (l.empty()) continue;  // a frame line emptied by frame_as_newtonian
        if (l[0] != '\x01') {
            s += l + "\n";
            continue;
        }
        // points: those fixed on a body (V2PTS) are declared on it
        std::vector<std::string> free;
        std::size_t b = 1;
        while (b <= l.size()) {
            std::size_t e = l.find('\x01', b);
            if (e == std::string::npos) e = l.size();
            std::string p = l.substr(b, e - b);
            b = e + 1;
            auto it = point_body_.find(p);
            const Entry* body = it == point_body_.end() ? nullptr : object_spelt(it->second);
            if (body && body->kind == Kind::body) s += "point " + p + " on " + body->name + "\n";
            else free.push_back(p);
        }
        if (!free.empty()) s += "point " + join(free) + "\n";
    }
    for (std::size_t g = 0; g < constants_.size(); ++g) {
        const auto& group = constants_[g];
        if (implicit_group_ && g == *implicit_group_ && !group.empty())
            s += "# declared by MASS and INERTIA, as in Autolev\n";
        // CONSTANTS L+, M: positive L, then constant M
        for (bool positive : {true, false}) {
            std::vector<std::string> parts;
            for (const ConstantDecl& c : group)
                if (c.positive == positive)
                    parts.push_back(c.name + (c.value.empty() ? "" : " = " + c.value + c.unit));
            if (!parts.empty()) s += (positive ? "positive " : "constant ") + join(parts) + "\n";
        }
    }
    if (!time_unit_.empty())
        s += "# Autolev's time T is a number of seconds: t/" + time_unit_ + "\nconstant " + time_unit_ + " = 1 s\n";
    if (!extra_constants_.empty())
        s += "# numbers where Alembert needs a dimension, as constants without a unit\n"
             "constant " + join(extra_constants_) + "\n";
    if (!rate_of_.empty()) {
        std::vector<std::string> said;
        for (const std::string& v : variables_)
            if (auto r = rate_of_.find(v); r != rate_of_.end()) said.push_back(v + " is " + r->second + "'");
        s += "# " + join(said) + " (kinematical equations " + rate_of_.begin()->second + "' = " +
             rate_of_.begin()->first + ", ...): written as the rates, which simulate and codegen take as speeds\n";
    }
    if (!variables_.empty()) {
        std::vector<std::string> parts;
        for (const std::string& v : variables_) {
            if (given_.count(v) || rate_of_.count(v)) continue;
            // Kane's equations, their linearization and generated code take the second
            // derivatives of coordinates and the first of speeds: two primes serve both
            int p = std::max({primes_[v], used_primes_[v], 2});
            parts.push_back(v + std::string(static_cast<std::size_t>(p), '\''));
        }
        for (const std::string& ua : aux_opened_) parts.push_back(ua + "''");
        for (const auto& [q, u] : rate_speeds_) parts.push_back(u + "''");  // the speeds u = q'
        if (!parts.empty()) s += "variable " + join(parts) + "\n";
    }
    for (const std::string& v : variables_)
        if (given_.count(v)) specified_.push_back(v + std::string(static_cast<std::size_t>(std::max(primes_[v], used_primes_[v])), '\''));
    if (!specified_.empty()) s += "specified " + join(specified_) + "\n";
    if (!unknowns.empty()) s += "unknown " + join(unknowns) + "\n";
    for (const std::string& l : model_)
        if (!l.empty()) s += l + "\n";
    for (const std::string& n : initial_order_)
        if (given_.count(n) && std::find(tail_inputs_.begin(), tail_inputs_.end(), n + " = " + initial_[n]) == tail_inputs_.end())
            tail_inputs_.push_back(n + " = " + initial_[n]);
    if (!tail_inputs_.empty()) s += "input " + join(tail_inputs_) + "\n";
    if (!initial_order_.empty()) {
        std::vector<std::string> parts, seen;
        for (const std::string& n : initial_order_) {
            if (std::find(seen.begin(), seen.end(), n) != seen.end()) continue;
            seen.push_back(n);
            if (given_.count(n)) continue;  // given above with `input`
            std::string state = n;
            for (const auto& [q, u] : rate_speeds_)
                if (n == q + "'") state = u;  // INPUT Q' = 1: the speed u = q' starts at 1
            parts.push_back(state + " = " + initial_[n]);
        }
        if (!parts.empty()) s += "initial " + join(parts) + "\n";
    }
    for (const auto& [k, l] : tail_settings_) s += l + "\n";
    if (!abs_tol_.empty() || !rel_tol_.empty())
        s += "tolerance" + (abs_tol_.empty() ? "" : " abs " + abs_tol_) + (rel_tol_.empty() ? "" : " rel " + rel_tol_) + "\n";
    for (const std::string& l : tail_outputs_) s += l + "\n";
    for (const auto& [where, l] : tail_codegen_) {
        if (!kane_at_ && !dynamics_left_out_.empty()) {
            report(Severity::warning, where,
                   "left out: CODE DYNAMICS() needs the equations of motion, which line " +
                       std::to_string(dynamics_left_out_.front()) + " left out",
                   "write the equations of motion by hand in the script, then codegen");
            s += "# left out (" + file_ + ":" + std::to_string(where.line) + "): CODE DYNAMICS() needs the equations "
                 "of motion, which line " + std::to_string(dynamics_left_out_.front()) + " left out\n";
        } else if (!kane_at_) {
            report(Severity::error, where, "CODE DYNAMICS() without KANE()",
                   "form Kane's equations (ZERO = FR() + FRSTAR(), KANE()) before generating code");
        } else if ((!kinematics_.empty() || !rate_speeds_.empty()) && l.rfind("codegen matlab", 0) == 0) {
            // code in generalized speeds is generated in C, C++ and Python
            not_translated(where, "CODE DYNAMICS() to a MATLAB file",
                           "Alembert generates code for Kane's equations in generalized speeds (this model's "
                           "kinematical equations such as " +
                               (kinematics_.empty() ? rate_speeds_.front().first : kinematics_.front().coordinate) +
                               "' = ...) in C, C++ and Python");
        } else {
            s += l + "\n";
        }
    }
}

}  // namespace alembert::lang::autolev
