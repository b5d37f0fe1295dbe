// SPDX-License-Identifier: MIT
// The MATLAB/Octave emitter: one function file per generated function.
#pragma once

#include "alembert/codegen/emitter.hpp"

namespace alembert {

/// Emits MATLAB/Octave function files: NAME_parameters.m (a struct of the constants),
/// NAME_context.m (the parameters and the values computed from them once),
/// NAME_mass_forcing.m, NAME_forward_dynamics.m (chol, or \ when M is not symmetric),
/// NAME_inverse_dynamics.m, NAME_outputs.m, NAME_load_laws.m, NAME_rhs.m (xdot of
/// x = [q; qp], for ode45: `ode45(@(t, x) NAME_rhs(t, x, ctx), tspan, x0)`), and with a
/// simulation NAME_simulate.m, which integrates with ode45 and writes a CSV.
class MatlabEmitter : public Emitter {
public:
    Language language() const override { return Language::matlab; }
    const CodePrinter& printer() const override { return printer_; }
    std::vector<GeneratedFile> emit(const CodePlan& plan) const override;

private:
    MatlabPrinter printer_;
};

}  // namespace alembert
