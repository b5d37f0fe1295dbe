// SPDX-License-Identifier: MIT
// The C99 emitter: NAME.h, NAME.c and, for a simulation, NAME_main.c.
#pragma once

#include "alembert/codegen/emitter.hpp"

namespace alembert {

/// Emits C99: a header declaring NAME_parameters (the constants, with defaults from
/// NAME_default_parameters), NAME_context (parameters and the values computed from them once,
/// by NAME_init) and the functions NAME_mass_forcing, NAME_forward_dynamics (Cholesky or LU
/// in the file, returns 0 or -1 for a singular M), NAME_inverse_dynamics, NAME_outputs,
/// NAME_load_laws and NAME_rhs; the source defining them; and with a simulation NAME_main.c,
/// a program integrating x = (q, q') by an adaptive Dormand-Prince RK45 method and writing a
/// CSV. Compiles with `cc -std=c99 -pedantic -Wall -Wextra` and links with -lm.
class CEmitter : public Emitter {
public:
    Language language() const override { return Language::c; }
    const CodePrinter& printer() const override { return printer_; }
    std::vector<GeneratedFile> emit(const CodePlan& plan) const override;

private:
    CPrinter printer_;
};

}  // namespace alembert
