// SPDX-License-Identifier: MIT
// The Python emitter: one module NAME.py on NumPy (and SciPy for simulate).
#pragma once

#include "alembert/codegen/emitter.hpp"

namespace alembert {

/// Emits a Python 3 module NAME.py: PARAMETERS (a dict of the constants), class Context (the
/// parameters and the values computed from them once), and the functions mass_forcing,
/// forward_dynamics (numpy Cholesky, or numpy.linalg.solve when M is not symmetric),
/// inverse_dynamics, outputs, load_laws, rhs (for scipy.integrate.solve_ivp:
/// `solve_ivp(rhs, (0, T), x0, args=(ctx,))`) and simulate (solve_ivp's RK45, a CSV);
/// `python3 NAME.py [out.csv]` runs the simulation.
class PythonEmitter : public Emitter {
public:
    Language language() const override { return Language::python; }
    const CodePrinter& printer() const override { return printer_; }
    std::vector<GeneratedFile> emit(const CodePlan& plan) const override;

private:
    PythonPrinter printer_;
};

}  // namespace alembert
